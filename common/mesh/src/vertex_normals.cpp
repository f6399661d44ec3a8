#include "slicereuse/mesh/vertex_normals.h"

#include <cmath>

namespace slicereuse {

std::vector<double> vertex_normals(const std::vector<double>& V, const std::vector<uint32_t>& F) {
  std::vector<double> N(V.size(), 0.0);
  for (size_t f = 0; f < F.size(); f += 3) {
    const double* a = &V[3 * size_t(F[f])];
    const double* b = &V[3 * size_t(F[f + 1])];
    const double* c = &V[3 * size_t(F[f + 2])];
    const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    // The cross product's length is twice the area: summing it weights by area.
    const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) N[3 * size_t(F[f + j]) + k] += n[k];
  }
  for (size_t i = 0; i < N.size(); i += 3) {
    const double len = std::sqrt(N[i] * N[i] + N[i + 1] * N[i + 1] + N[i + 2] * N[i + 2]);
    if (len > 0)
      for (int k = 0; k < 3; ++k) N[i + k] /= len;
  }
  return N;
}

}  // namespace slicereuse
