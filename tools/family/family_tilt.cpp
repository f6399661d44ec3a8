// FamilyTilt (family.h): a family's members turned about the x axis onto the base's lowest height.
#include <cmath>

#include "family.h"

namespace slicereuse::test {

FamilyTilt::FamilyTilt(const Mesh& base, double deg) : c(std::cos(deg * M_PI / 180)), s(std::sin(deg * M_PI / 180)) {
  dz = INFINITY;
  for (size_t v = 0; v < base.vertices(); ++v) dz = std::fmin(dz, s * base.V[3 * v + 1] + c * base.V[3 * v + 2]);
}

void FamilyTilt::apply(Mesh& m) const {
  for (size_t v = 0; v < m.vertices(); ++v) {
    const double y = m.V[3 * v + 1], z = m.V[3 * v + 2];
    m.V[3 * v + 1] = c * y - s * z;
    m.V[3 * v + 2] = s * y + c * z - dz;
  }
}

}  // namespace slicereuse::test
