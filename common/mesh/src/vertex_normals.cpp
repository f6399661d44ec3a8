#include "slicereuse/mesh/vertex_normals.h"

#include "slicereuse/mesh/vec3.h"

namespace slicereuse {

std::vector<double> vertex_normals(const std::vector<double>& V, const std::vector<uint32_t>& F) {
  std::vector<double> N(V.size(), 0.0);
  for (size_t f = 0; f < F.size(); f += 3) {
    const double* a = &V[3 * size_t(F[f])];
    const double* b = &V[3 * size_t(F[f + 1])];
    const double* c = &V[3 * size_t(F[f + 2])];
    // The cross product's length is twice the area: summing it weights by area.
    const Vec3 n = cross(sub(b, a), sub(c, a));
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) N[3 * size_t(F[f + j]) + k] += n[k];
  }
  for (size_t i = 0; i < N.size(); i += 3) {
    const double len = norm(&N[i]);
    if (len > 0)
      for (int k = 0; k < 3; ++k) N[i + k] /= len;
  }
  return N;
}

}  // namespace slicereuse
