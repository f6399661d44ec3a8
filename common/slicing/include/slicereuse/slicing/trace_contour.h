#pragma once
// trace_contour: the closed contour of a mesh at plane z = zk that passes through one given face,
// followed through the mesh's edge links (edge_links.h) without any search for faces.
//
// Input: the mesh, its edge links, zk, a seed face that straddles zk (a corner below zk and one
// at or above it, the slicer's rule), a per-face stamp array with this plane's stamp value, and
// where to write: ContourSink's arrays from `cursor` up to `end` (face, edge, t may be null when
// the encoding is not wanted).
// Output: the loop written at the cursor, one point per face it crosses, the faces stamped, its
// length appended to sink.lengths. The walk is slice_layers' own (contour_step.h: the same exit
// edges, points and encoding (face, edge, t), the same direction, outer loops counter-clockwise
// seen from +z), so a traced loop is bit for bit one of direct slicing's loops, up to its start
// point.
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

bool trace_contour(const Mesh& mesh, const std::vector<uint32_t>& links, double zk, uint32_t seed,
                   uint32_t stamp_value, uint32_t* stamp, ContourSink& sink);

}  // namespace slicereuse
