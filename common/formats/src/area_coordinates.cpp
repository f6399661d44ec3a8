#include "area_coordinates.h"

#include <cmath>

namespace slicereuse {

const char* decode_area_coordinates(const double lambda[3], uint8_t& j, double& t) {
  for (int c = 0; c < 3; ++c) {
    if (!std::isfinite(lambda[c])) return "area coordinate is not a finite number";
    if (lambda[c] < 0) return "negative area coordinate";
  }
  int edge = -1;
  for (int c = 0; c < 3; ++c)
    if (lambda[(c + 2) % 3] == 0 && lambda[(c + 1) % 3] > 0) edge = c;
  if (lambda[0] != 0 && lambda[1] != 0 && lambda[2] != 0)
    return "point not on a face edge: no area coordinate is 0";
  if (edge < 0) return "area coordinates are all 0";
  if (lambda[(edge + 1) % 3] > 1) return "area coordinate above 1";
  if (std::abs(lambda[0] + lambda[1] + lambda[2] - 1) > kAreaCoordinateSumTolerance)
    return "area coordinates do not sum to 1";
  j = uint8_t(edge);
  t = lambda[(edge + 1) % 3];
  return nullptr;
}

}  // namespace slicereuse
