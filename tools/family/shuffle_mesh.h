#pragma once
// shuffle_mesh: the same surface with other connectivity in indices: vertices renumbered, faces
// reordered, and each face's corners rotated (orientation kept), all by a seeded permutation.
// Output: the shuffled mesh and where each input vertex went (new_index[i]) and, for each input
// face f, its new face new_face[f] and the corner its corner 0 moved to (corner_shift[f]: input
// corner j is output corner (j + corner_shift[f]) % 3). Deterministic in (mesh, seed) on every
// platform (mt19937_64, Fisher-Yates).
// map_onto_shuffled: the exact SurfaceMap from `source` (a mesh with the faces of the shuffled
// input, e.g. the family's base) onto the shuffled mesh: source vertex i lands on its new self,
// as the corner with barycentric coordinate 1 of a face that uses it.
#include <cstdint>
#include <vector>

#include "slicereuse/crossparam/surface_map.h"
#include "slicereuse/mesh/mesh.h"

namespace slicereuse::test {

struct ShuffledMesh {
  Mesh mesh;
  std::vector<uint32_t> new_index;    // per input vertex
  std::vector<uint32_t> new_face;     // per input face
  std::vector<uint8_t> corner_shift;  // per input face
};

ShuffledMesh shuffle_mesh(const Mesh& mesh, uint64_t seed);

SurfaceMap map_onto_shuffled(const Mesh& source, const ShuffledMesh& shuffled);

}  // namespace slicereuse::test
