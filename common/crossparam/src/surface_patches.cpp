#include "surface_patches.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "slicereuse/mesh/vec3.h"

namespace slicereuse {

std::vector<uint32_t> surface_patches(const Mesh& mesh, size_t count,
                                      const std::vector<std::array<double, 3>>& first_seeds) {
  const size_t nv = mesh.vertices();
  const double* V = mesh.V.data();
  auto d2 = [&](size_t i, const double* p) { return squared_distance(V + 3 * i, p); };
  count = std::max<size_t>(1, std::min(count, nv));
  std::vector<uint32_t> seeds;
  std::vector<double> nearest(nv, std::numeric_limits<double>::infinity());
  auto add_seed = [&](size_t s) {
    seeds.push_back(uint32_t(s));
    for (size_t i = 0; i < nv; ++i) nearest[i] = std::min(nearest[i], d2(i, V + 3 * s));
  };
  for (const auto& p : first_seeds) {
    if (seeds.size() == count) break;
    size_t best = 0;
    for (size_t i = 1; i < nv; ++i)
      if (d2(i, p.data()) < d2(best, p.data())) best = i;
    if (std::find(seeds.begin(), seeds.end(), uint32_t(best)) == seeds.end()) add_seed(best);
  }
  if (seeds.empty()) add_seed(mesh.F[0]);
  while (seeds.size() < count) {
    const size_t far = size_t(std::max_element(nearest.begin(), nearest.end()) - nearest.begin());
    if (nearest[far] == 0) break;
    add_seed(far);
  }

  // Vertex adjacency (CSR) from the faces' edges.
  std::vector<uint32_t> begin(nv + 1, 0), adj(6 * mesh.faces());
  for (size_t h = 0; h < mesh.F.size(); ++h) begin[mesh.F[h] + 1] += 2;
  for (size_t i = 0; i < nv; ++i) begin[i + 1] += begin[i];
  {
    std::vector<uint32_t> cur(begin.begin(), begin.end() - 1);
    for (size_t h = 0; h < mesh.F.size(); ++h) {
      const uint32_t u = mesh.F[h], v = mesh.F[h - h % 3 + (h % 3 + 1) % 3];
      adj[cur[u]++] = v;
      adj[cur[v]++] = u;
    }
  }
  const uint32_t none = 0xffffffffu;
  std::vector<uint32_t> patch(nv, none);
  std::vector<double> dist(nv, std::numeric_limits<double>::infinity());
  using Item = std::pair<double, uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (size_t k = 0; k < seeds.size(); ++k) {
    dist[seeds[k]] = 0;
    patch[seeds[k]] = uint32_t(k);
    queue.push({0, seeds[k]});
  }
  while (!queue.empty()) {
    const auto [d, u] = queue.top();
    queue.pop();
    if (d > dist[u]) continue;
    for (uint32_t k = begin[u]; k < begin[u + 1]; ++k) {
      const uint32_t v = adj[k];
      const double nd = d + std::sqrt(d2(v, V + 3 * size_t(u)));
      if (nd < dist[v]) {
        dist[v] = nd;
        patch[v] = patch[u];
        queue.push({nd, v});
      }
    }
  }
  for (size_t i = 0; i < nv; ++i)
    if (patch[i] == none) {
      size_t best = 0;
      for (size_t k = 1; k < seeds.size(); ++k)
        if (d2(i, V + 3 * size_t(seeds[k])) < d2(i, V + 3 * size_t(seeds[best]))) best = k;
      patch[i] = uint32_t(best);
    }
  return patch;
}

}  // namespace slicereuse
