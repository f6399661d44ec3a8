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
  WayDown way{kNaN, part.highest_hit(x, y, z - kBelowContactMm, z_floor)};
  way.blocked_z = way.axis_z;
  for (int i = 0; i < kRimRays; ++i) {
    const double a = 2 * M_PI * i / kRimRays;
    const double hit = part.highest_hit(x + rim_radius * std::cos(a), y + rim_radius * std::sin(a), z_head_bottom, z_floor);
    if (!std::isnan(hit) && !(hit <= way.blocked_z)) way.blocked_z = hit;
  }
  return way;
}

}  // namespace slicereuse
