#include "slicereuse/slicing/layer_chunks.h"

#include <algorithm>

#include "slicereuse/slicing/layer_planes.h"

namespace slicereuse {

std::vector<size_t> layer_chunks(const Mesh& mesh, const std::vector<double>& planes, uint64_t budget_bytes,
                                 size_t bytes_per_point) {
  const size_t L = planes.size();
  if (budget_bytes == 0 || L == 0) return {0, L};
  // A face is crossed by the planes strictly above its lowest vertex and at or below its highest
  // (a vertex at a plane's height counts as above it): a difference array over the layers.
  std::vector<int64_t> change(L + 1, 0);
  for (size_t f = 0; f < mesh.faces(); ++f) {
    double lo = mesh.V[3 * size_t(mesh.F[3 * f]) + 2], hi = lo;
    for (int i = 1; i < 3; ++i) {
      const double z = mesh.V[3 * size_t(mesh.F[3 * f + i]) + 2];
      lo = std::min(lo, z);
      hi = std::max(hi, z);
    }
    const size_t k0 = first_plane_above(planes, lo), k1 = first_plane_above(planes, hi);
    if (k0 < k1) {
      ++change[k0];
      --change[k1];
    }
  }
  std::vector<size_t> starts{0};
  int64_t crossed = 0;
  uint64_t bytes = 0;
  for (size_t k = 0; k < L; ++k) {
    crossed += change[k];
    const uint64_t layer = uint64_t(crossed) * bytes_per_point;
    if (bytes > 0 && bytes + layer > budget_bytes) {
      starts.push_back(k);
      bytes = 0;
    }
    bytes += layer;
  }
  starts.push_back(L);
  return starts;
}

}  // namespace slicereuse
