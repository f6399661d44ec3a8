#pragma once
// mesh_topology: the counts that classify a triangle mesh's surface topologically.
//
// Input: a valid mesh (validate_mesh). Output: referenced vertices V, undirected edges E, faces F
// (a face's side from a vertex to itself is no edge), edges used by one face only (boundary) or by
// more than two (non-manifold), boundary loops (connected groups of boundary edges), connected
// components (faces joined through shared vertices), Euler characteristic chi = V - E + F and the
// total genus g = (2 * components - boundary_loops - chi) / 2, which is exact for orientable
// manifold meshes: 0 for a sphere or a disc, 1 for a torus. Unreferenced vertices are ignored (they
// are not part of the surface).
#include <cstdint>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

struct MeshTopology {
  uint64_t vertices = 0, edges = 0, faces = 0;
  uint64_t boundary_edges = 0, nonmanifold_edges = 0;
  uint64_t boundary_loops = 0, components = 0;
  int64_t euler = 0;
  int64_t genus = 0;
};

MeshTopology mesh_topology(const Mesh& mesh);

}  // namespace slicereuse
