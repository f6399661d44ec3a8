#include "unsampled_edge.h"

#include <algorithm>
#include <set>
#include <vector>

#include "slicereuse/transfer/transfer_contours.h"

namespace slicereuse::test {

bool move_vertex_across_unsampled_edge(const Slices& source, Mesh& member, size_t* layer) {
  const Buffer<uint32_t> ends = encoded_edge_ends(source, member);
  std::vector<std::set<uint32_t>> neighbours(member.vertices());
  for (size_t f = 0; f < member.faces(); ++f)
    for (int c = 0; c < 3; ++c) {
      neighbours[member.F[3 * f + c]].insert(member.F[3 * f + (c + 1) % 3]);
      neighbours[member.F[3 * f + c]].insert(member.F[3 * f + (c + 2) % 3]);
    }
  auto z = [&](uint32_t v) { return member.V[3 * size_t(v) + 2]; };
  for (size_t k = 0; k + 1 < source.layers(); ++k) {
    const double zk = source.layer_z[k], above = source.layer_z[k + 1];
    // The vertices the sample reads (first and middle point of every contour) stay as they are.
    std::set<uint32_t> sampled;
    for (uint64_t c = source.layer_begin[k]; c < source.layer_begin[k + 1]; ++c)
      for (uint64_t p : {source.contour_begin[c], (source.contour_begin[c] + source.contour_begin[c + 1]) / 2}) {
        sampled.insert(ends[2 * p]);
        sampled.insert(ends[2 * p + 1]);
      }
    for (uint64_t p = source.contour_begin[source.layer_begin[k]]; p < source.contour_begin[source.layer_begin[k + 1]];
         ++p) {
      const uint32_t b = ends[2 * p + 1];
      if (sampled.count(b) || !(z(b) >= zk && z(b) < above)) continue;
      size_t up = 0, down = 0;
      for (uint32_t n : neighbours[b]) (z(n) >= zk ? up : down) += 1;
      if (up != down) continue;
      // Just below plane k, still above plane k - 1: only plane k sees b on its other side.
      const double moved = zk - 1e-3 * (above - zk);
      member.V[3 * size_t(b) + 2] = moved;
      *layer = k;
      return true;
    }
  }
  return false;
}

}  // namespace slicereuse::test
