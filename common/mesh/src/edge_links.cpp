#include "slicereuse/mesh/edge_links.h"

namespace slicereuse {

EdgeLinks edge_links(const Mesh& mesh) {
  const size_t nf = mesh.faces(), nv = mesh.vertices(), nh = 3 * nf;
  const uint32_t* F = mesh.F.data();
  // Half-edges grouped by their first vertex (counting sort), so the reverse of u->v is found
  // among v's few outgoing half-edges: O(faces * valence), no hashing, no sorting. Within a
  // vertex's group half-edges stay in increasing order, which ranks those of one edge.
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
    if (u != v) {
      // h's rank among the half-edges u->v (in half-edge order), and the reverse of that rank.
      int same = 0, rank = 0, reverse = 0;
      for (uint32_t i = begin[u]; i < begin[u + 1]; ++i)
        if (head(out[i]) == v) {
          rank += out[i] < h;
          ++same;
        }
      for (uint32_t i = begin[v]; i < begin[v + 1]; ++i)
        if (head(out[i]) == u && reverse++ == rank) twin = out[i];
      if (same != reverse) twin = kUnlinked;
    }
    if (twin != kUnlinked) {
      result.links[h] = ((twin / 3) << 2) | (twin % 3);
    } else {
      ++unlinked;
    }
  }
  result.unlinked = unlinked;
  return result;
}

}  // namespace slicereuse
