#include "slicereuse/mesh/mesh_topology.h"

#include <algorithm>
#include <numeric>
#include <vector>

#include "slicereuse/util/union_find.h"

namespace slicereuse {

MeshTopology mesh_topology(const Mesh& mesh) {
  const size_t nf = mesh.faces(), nv = mesh.vertices();
  MeshTopology t;
  t.faces = nf;
  // Undirected edges as sorted (min, max) vertex pairs: equal keys are the uses of one edge.
  // A face naming one vertex twice has a "side" from that vertex to itself: no edge of the surface.
  std::vector<uint64_t> keys;
  keys.reserve(3 * nf);
  for (size_t h = 0; h < 3 * nf; ++h) {
    const uint64_t u = mesh.F[h], v = mesh.F[h - h % 3 + (h % 3 + 1) % 3];
    if (u != v) keys.push_back(std::min(u, v) << 32 | std::max(u, v));
  }
  std::sort(keys.begin(), keys.end());
  std::vector<uint8_t> used(nv, 0);
  for (uint32_t v : mesh.F) used[v] = 1;
  t.vertices = uint64_t(std::count(used.begin(), used.end(), 1));

  UnionFind surface(nv), boundary(nv);
  std::vector<uint8_t> on_boundary(nv, 0);
  for (size_t i = 0; i < keys.size();) {
    size_t j = i;
    while (j < keys.size() && keys[j] == keys[i]) ++j;
    ++t.edges;
    const uint32_t u = uint32_t(keys[i] >> 32), v = uint32_t(keys[i]);
    surface.join(u, v);
    if (j - i == 1) {
      ++t.boundary_edges;
      boundary.join(u, v);
      on_boundary[u] = on_boundary[v] = 1;
    } else if (j - i > 2) {
      ++t.nonmanifold_edges;
    }
    i = j;
  }
  for (uint32_t v = 0; v < nv; ++v) {
    if (used[v] && surface.find(v) == v) ++t.components;
    if (on_boundary[v] && boundary.find(v) == v) ++t.boundary_loops;
  }
  t.euler = int64_t(t.vertices) - int64_t(t.edges) + int64_t(t.faces);
  t.genus = (2 * int64_t(t.components) - int64_t(t.boundary_loops) - t.euler) / 2;
  return t;
}

}  // namespace slicereuse
