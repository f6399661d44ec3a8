#pragma once
// Mesh: an indexed triangle mesh as two flat arrays.
//   V: 3*nv doubles, vertex i is (V[3i], V[3i+1], V[3i+2]).
//   F: 3*nf vertex indices, face f is (F[3f], F[3f+1], F[3f+2]), counter-clockwise seen from
//      outside, so an outward normal is (v1-v0)x(v2-v0).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace slicereuse {

struct Mesh {
  std::vector<double> V;
  std::vector<uint32_t> F;
  size_t vertices() const { return V.size() / 3; }
  size_t faces() const { return F.size() / 3; }
};

// The lowest and highest vertex z; the mesh must have a vertex.
struct ZRange {
  double min, max;
};
ZRange z_range(const Mesh& mesh);

// Throws Error when the mesh has no faces, V or F has a length not divisible by 3, an index is
// out of range, or a coordinate is not finite (naming how many vertices and the first).
void validate_mesh(const Mesh& mesh);

}  // namespace slicereuse
