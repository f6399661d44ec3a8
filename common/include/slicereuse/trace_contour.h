#pragma once
// trace_contour: the closed contour of a mesh at plane z = zk that passes through one given face,
// followed through the mesh's edge links (edge_links.h) without any search for faces.
//
// Input: the mesh, its edge links, zk, a seed face that straddles zk (a corner below zk and one
// at or above it, the slicer's rule), and a per-face stamp array with this plane's stamp value.
// Output: the loop appended to `out`, one point per face it crosses, stamped. Each point is
// computed exactly as slice_layers does it (on the face's exit edge, from the corner below to
// the corner at or above, by edge_point), with the same encoding (face, edge, t) and the same
// direction (outer loops counter-clockwise seen from +z), so a traced loop is bit for bit one of
// direct slicing's loops, up to its start point.
// Returns false (and leaves a partial loop in out) when the walk reaches an unlinked edge (the
// contour is open there) or a face stamped before, or when out would exceed max_points; a caller
// that certifies a layer then re-slices it.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "slicereuse/mesh.h"

namespace slicereuse {

struct TracedContours {
  std::vector<double> xyz;      // 3 per point
  std::vector<uint32_t> face;   // the target's encoding, see slices.h
  std::vector<uint8_t> edge;
  std::vector<double> t;
  std::vector<uint64_t> lengths;  // points per traced loop
  size_t points() const { return face.size(); }
};

bool trace_contour(const Mesh& mesh, const std::vector<uint32_t>& links, double zk, uint32_t seed,
                   uint32_t stamp_value, uint32_t* stamp, size_t max_points, TracedContours& out);

// Whether face f straddles zk (some corner below, some at or above), and, when it does, its exit
// edge: the local edge j whose corner j is below zk and corner (j+1)%3 at or above (exactly one).
constexpr uint32_t kNoEdge = 3;
uint32_t exit_edge(const Mesh& mesh, uint32_t f, double zk);

}  // namespace slicereuse
