#include "slicereuse/straddling_edges.h"

#include <algorithm>

#include "slicereuse/layer_planes.h"

namespace slicereuse {

std::vector<uint64_t> straddling_edge_counts(const Mesh& mesh, const EdgeLinks& links,
                                             const std::vector<double>& layer_z) {
  const size_t L = layer_z.size(), nh = mesh.F.size();
  std::vector<int64_t> diff(L + 1, 0);
  for (size_t h = 0; h < nh; ++h) {
    const uint32_t link = links.links[h];
    const size_t twin = link == kUnlinked ? h : 3 * size_t(link >> 2) + (link & 3);
    if (twin < h) continue;  // the pair was counted at its first half-edge
    const double za = mesh.V[3 * size_t(mesh.F[h]) + 2];
    const double zb = mesh.V[3 * size_t(mesh.F[h - h % 3 + (h % 3 + 1) % 3]) + 2];
    const size_t k0 = first_plane_above(layer_z, std::min(za, zb));
    const size_t k1 = first_plane_above(layer_z, std::max(za, zb));
    ++diff[k0];
    --diff[k1];
  }
  std::vector<uint64_t> counts(L);
  int64_t running = 0;
  for (size_t k = 0; k < L; ++k) counts[k] = uint64_t(running += diff[k]);
  return counts;
}

}  // namespace slicereuse
