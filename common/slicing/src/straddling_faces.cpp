#include "slicereuse/slicing/straddling_faces.h"

#include <algorithm>

#include "slicereuse/slicing/layer_planes.h"

namespace slicereuse {

std::vector<uint64_t> straddling_face_counts(const Mesh& mesh, const std::vector<double>& layer_z) {
  const size_t L = layer_z.size(), nf = mesh.faces();
  std::vector<int64_t> diff(L + 1, 0);
  for (size_t f = 0; f < nf; ++f) {
    const double z0 = mesh.V[3 * size_t(mesh.F[3 * f]) + 2], z1 = mesh.V[3 * size_t(mesh.F[3 * f + 1]) + 2],
                 z2 = mesh.V[3 * size_t(mesh.F[3 * f + 2]) + 2];
    ++diff[first_plane_above(layer_z, std::min({z0, z1, z2}))];
    --diff[first_plane_above(layer_z, std::max({z0, z1, z2}))];
  }
  std::vector<uint64_t> counts(L);
  int64_t running = 0;
  for (size_t k = 0; k < L; ++k) counts[k] = uint64_t(running += diff[k]);
  return counts;
}

}  // namespace slicereuse
