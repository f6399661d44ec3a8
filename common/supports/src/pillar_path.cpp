#include "pillar_path.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slicereuse {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// How far under the point the axis ray starts, so that the point's own face is not a hit (and
// under where a rim ray leaves the part, so that face is not one either).
constexpr double kBelowContactMm = 1e-6;
}  // namespace

WayDown find_way_down(const PartColumns& part, double x, double y, double z, double z_head_bottom, double z_floor,
                      double pillar_radius) {
  const double axis_z = part.highest_hit(x, y, z - kBelowContactMm, z_floor);
  WayDown way{axis_z, x, y, axis_z, part.inside(x, y, z_head_bottom)};
  const double rim_radius = pillar_radius + kRimClearanceMm;
  auto ray = [&](double rx, double ry, double from) {
    const double hit = part.highest_hit(rx, ry, from, z_floor);
    if (!std::isnan(hit) && !(hit <= way.blocked_z)) way.blocked_z = hit, way.blocked_x = rx, way.blocked_y = ry;
  };
  for (int i = 0; i < kRimRays; ++i) {
    const double c = std::cos(2 * M_PI * i / kRimRays), s = std::sin(2 * M_PI * i / kRimRays);
    const double half = pillar_radius / 2, margin = pillar_radius + kPillarMarginMm;
    way.pillar_in_part = way.pillar_in_part || part.inside(x + half * c, y + half * s, z_head_bottom);
    const double px = x + margin * c, py = y + margin * s;
    way.pillar_in_part = way.pillar_in_part || part.inside(px, py, z_head_bottom);
    ray(px, py, z_head_bottom);
    const double rx = x + rim_radius * c, ry = y + rim_radius * s;
    double from = z_head_bottom;
    if (part.inside(rx, ry, from)) from = part.highest_hit(rx, ry, from, z_floor) - kBelowContactMm;
    ray(rx, ry, from);
  }
  return way;
}

}  // namespace slicereuse
