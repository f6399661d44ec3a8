#include "slicereuse/mesh/edge_links.h"

namespace slicereuse {

EdgeLinks edge_links(const Mesh& mesh) {
  const size_t nf = mesh.faces(), nv = mesh.vertices(), nh = 3 * nf;
  const uint32_t* F = mesh.F.data();
  // Half-edges grouped by their first vertex (counting sort), so the reverse of u->v is found
  // among v's few outgoing half-edges: O(faces * valence), no hashing, no sorting.
  std::vector<uint32_t> begin(nv + 1, 0);
  for (size_t h = 0; h < nh; ++h) ++begin[F[h] + 1];
  for (size_t v = 0; v < nv; ++v) begin[v + 1] += begin[v];
  std::vector<uint32_t> out(nh);
  {
    std::vector<uint32_t> cursor(begin.begin(), begin.end() - 1);
    for (size_t h = 0; h < nh; ++h) out[cursor[F[h]]++] = uint32_t(h);
  }
  auto head = [&](uint32_t h) { return F[h - h % 3 + (h % 3 + 1) % 3]; };

  EdgeLinks result;
  result.links.assign(nh, kUnlinked);
  size_t unlinked = 0;
#pragma omp parallel for reduction(+ : unlinked) schedule(static)
  for (long long hh = 0; hh < static_cast<long long>(nh); ++hh) {
    const uint32_t h = uint32_t(hh), u = F[h], v = head(h);
    uint32_t twin = kUnlinked;
    int same = 0, reverse = 0;
    if (u != v) {
      for (uint32_t i = begin[u]; i < begin[u + 1]; ++i) same += head(out[i]) == v;
      for (uint32_t i = begin[v]; i < begin[v + 1]; ++i)
        if (head(out[i]) == u) {
          ++reverse;
          twin = out[i];
        }
    }
    if (same == 1 && reverse == 1) {
      result.links[h] = ((twin / 3) << 2) | (twin % 3);
    } else {
      ++unlinked;
    }
  }
  result.unlinked = unlinked;
  return result;
}

}  // namespace slicereuse
