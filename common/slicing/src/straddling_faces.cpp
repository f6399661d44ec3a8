#include "slicereuse/slicing/straddling_faces.h"

#include <omp.h>

#include <algorithm>

#include "slicereuse/slicing/layer_planes.h"
#include "slicereuse/util/buffer.h"

namespace slicereuse {

std::vector<uint64_t> straddling_face_counts(const Mesh& mesh, const std::vector<double>& layer_z) {
  const size_t L = layer_z.size();
  const long long nv = static_cast<long long>(mesh.vertices()), nf = static_cast<long long>(mesh.faces());
  // Each vertex's first plane above it, once (a vertex has about six faces): first_plane_above
  // grows with z, so a face's lowest and highest corners have the least and the greatest of its
  // corners' planes.
  Buffer<uint32_t> above(static_cast<size_t>(nv));
  const int threads = omp_get_max_threads();
  std::vector<std::vector<int64_t>> diff(size_t(threads), std::vector<int64_t>(L + 1, 0));
#pragma omp parallel num_threads(threads)
  {
#pragma omp for schedule(static)
    for (long long v = 0; v < nv; ++v) above[size_t(v)] = uint32_t(first_plane_above(layer_z, mesh.V[3 * size_t(v) + 2]));
    std::vector<int64_t>& d = diff[size_t(omp_get_thread_num())];
#pragma omp for schedule(static)
    for (long long f = 0; f < nf; ++f) {
      const uint32_t* corner = mesh.F.data() + 3 * size_t(f);
      const uint32_t a = above[corner[0]], b = above[corner[1]], c = above[corner[2]];
      ++d[std::min({a, b, c})];
      --d[std::max({a, b, c})];
    }
  }
  std::vector<uint64_t> counts(L);
  int64_t running = 0;
  for (size_t k = 0; k < L; ++k) {
    for (const std::vector<int64_t>& d : diff) running += d[k];
    counts[k] = uint64_t(running);
  }
  return counts;
}

}  // namespace slicereuse
