#pragma once
// vertex_normals: area-weighted unit vertex normals of a triangle mesh given as V (3 per
// vertex) and F (3 per face, counter-clockwise seen from outside). Output: 3 per vertex; (0,0,0)
// for a vertex in no face or only in degenerate faces.
#include <cstdint>
#include <vector>

namespace slicereuse {

std::vector<double> vertex_normals(const std::vector<double>& V, const std::vector<uint32_t>& F);

}  // namespace slicereuse
