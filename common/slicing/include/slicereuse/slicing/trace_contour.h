#pragma once
// trace_contour: the closed contour of a mesh at plane z = zk that passes through one given face,
// followed through the mesh's edge links (edge_links.h) without any search for faces.
//
// Input: the mesh, its edge links, zk, a seed face that straddles zk (a corner below zk and one
// at or above it, the slicer's rule), a per-face stamp array with this plane's stamp value, and
// where to write: ContourSink's arrays from `cursor` up to `end` (face, edge, t may be null when
// the encoding is not wanted).
// Output: the loop written at the cursor, one point per face it crosses, the faces stamped, its
// length appended to sink.lengths. Each point is computed exactly as slice_layers does it (on
// the face's exit edge, from the corner below to the corner at or above, by edge_point), with the
// same encoding (face, edge, t) and the same direction (outer loops counter-clockwise seen from
// +z), so a traced loop is bit for bit one of direct slicing's loops, up to its start point.
// Returns false (the sink then holds a partial loop) when the walk reaches an unlinked edge (the
// contour is open there), a face stamped before, or the sink's end; a caller that certifies a
// layer then re-slices it.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

struct ContourSink {
  double* xyz;      // 3 per point
  uint32_t* face;   // the encoding (slices.h), or null
  uint8_t* edge;
  double* t;
  size_t cursor, end;
  std::vector<uint64_t> lengths;  // points per traced loop
};

// The exit edge of face f at zk: the local edge j whose corner j is below zk and corner (j+1)%3
// at or above it (exactly one when f straddles zk); kNoEdge when f does not straddle zk.
constexpr uint32_t kNoEdge = 3;
uint32_t exit_edge(const Mesh& mesh, uint32_t f, double zk);

bool trace_contour(const Mesh& mesh, const std::vector<uint32_t>& links, double zk, uint32_t seed,
                   uint32_t stamp_value, uint32_t* stamp, ContourSink& sink);

}  // namespace slicereuse
