#pragma once
// turn_by_15_degrees(k): the cosine and sine of k x 15 degrees (any integer k), from square
// roots, which IEEE arithmetic rounds alike everywhere: a library's cos and sin may differ in the
// last bit from machine to machine, and so would the polygons and masks made from them.
#include <array>
#include <cmath>

namespace slicereuse {

inline std::array<double, 2> turn_by_15_degrees(int k) {
  const double r2 = std::sqrt(2.0), r3 = std::sqrt(3.0), r6 = std::sqrt(6.0);
  const double c15 = (r6 + r2) / 4, s15 = (r6 - r2) / 4;
  // The first quadrant, 0 to 90 degrees.
  const double table[7][2] = {{1, 0}, {c15, s15}, {r3 / 2, 0.5}, {r2 / 2, r2 / 2}, {0.5, r3 / 2}, {s15, c15}, {0, 1}};
  const int m = ((k % 24) + 24) % 24, quadrant = m / 6, i = m % 6;
  const double c = table[i][0], s = table[i][1];
  switch (quadrant) {
    case 0: return {c, s};
    case 1: return {-s, c};
    case 2: return {-c, -s};
    default: return {s, -c};
  }
}

}  // namespace slicereuse
