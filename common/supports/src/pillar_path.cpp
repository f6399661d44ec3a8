#include "pillar_path.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slicereuse {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// How far under the point the axis ray starts, so that the point's own face is not a hit.
constexpr double kBelowContactMm = 1e-6;
}  // namespace

WayDown find_way_down(const PartColumns& part, double x, double y, double z, double z_head_bottom, double z_floor,
                      double rim_radius) {
  const double axis_z = part.highest_hit(x, y, z - kBelowContactMm, z_floor);
  WayDown way{axis_z, x, y, axis_z};
  for (int i = 0; i < kRimRays; ++i) {
    const double a = 2 * M_PI * i / kRimRays;
    const double rx = x + rim_radius * std::cos(a), ry = y + rim_radius * std::sin(a);
    const double hit = part.highest_hit(rx, ry, z_head_bottom, z_floor);
    if (!std::isnan(hit) && !(hit <= way.blocked_z)) way.blocked_z = hit, way.blocked_x = rx, way.blocked_y = ry;
  }
  return way;
}

}  // namespace slicereuse
