#pragma once
// surface_patches: a partition of a mesh's vertices into about `count` patches of similar size,
// for colouring corresponding regions of two meshes.
//
// Input: a valid mesh, the patch count wanted, and optional first seeds (points near the
// surface, e.g. landmarks; at most `count` are used). Output: a patch id in [0, patches) per
// vertex. Seeds are the vertices nearest the given points, then farthest-point samples
// (Euclidean) until there are `count`; each vertex joins the seed nearest along the mesh's edges
// (multi-source Dijkstra); a vertex that no seed reaches (another component without a seed, or
// a vertex in no face) joins the Euclidean nearest seed.
#include <array>
#include <cstdint>
#include <vector>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

std::vector<uint32_t> surface_patches(const Mesh& mesh, size_t count,
                                      const std::vector<std::array<double, 3>>& first_seeds = {});

}  // namespace slicereuse
