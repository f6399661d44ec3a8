#include "support_heads.h"

#include <algorithm>
#include <cmath>

namespace slicereuse {

double depth_in_wall(double wall_mm, const SupportTreeOptions& o) {
  return std::isnan(wall_mm) ? o.head_penetration_mm : std::min(o.head_penetration_mm, wall_mm / 2);
}

double head_radius_at(const SupportHead& head, double z, const SupportPoints& points, const SupportTreeOptions& o) {
  const double r_pillar = o.pillar_diameter_mm / 2;
  const double full_back = points.xyz[3 * head.point + 2] - o.head_width_mm;
  return r_pillar + (head.cone.r_tip - r_pillar) * (z - full_back) / (head.cone.tip[2] - full_back);
}

namespace {

// Whether the disc of radius r around (x, y) at height z meets the part: its centre or a point of
// the circles of half and all of r, in kRimRays directions, inside it.
bool disc_meets_part(const PartColumns& columns, double x, double y, double z, double r) {
  if (columns.inside(x, y, z)) return true;
  for (int i = 0; i < kRimRays; ++i) {
    const double a = 2 * M_PI * i / kRimRays;
    for (const double d : {r / 2, r})
      if (columns.inside(x + d * std::cos(a), y + d * std::sin(a), z)) return true;
  }
  return false;
}

}  // namespace

std::vector<SupportHead> place_heads(const PartColumns& columns, const SupportPoints& points, double floor,
                                     const SupportTreeOptions& o, std::vector<WayDown>& ways) {
  std::vector<SupportHead> heads;
  ways.clear();
  for (size_t i = 0; i < points.size(); ++i) {
    if (faces_up(points, i)) continue;
    const double x = points.xyz[3 * i], y = points.xyz[3 * i + 1], z = points.xyz[3 * i + 2];
    SupportHead h;
    h.point = i;
    const double wall_top = columns.lowest_hit_above(x, y, z + kWallEpsilonMm);
    h.penetration = depth_in_wall(wall_top - z, o);
    h.cone.r_tip = o.head_front_diameter_mm / 2;
    h.cone.tip = {x, y, z + h.penetration};
    const double full_back = z - o.head_width_mm;
    h.cone.back = {x, y, std::max(full_back, floor)};
    h.cone.r_back = head_radius_at(h, h.cone.back[2], points, o);
    // A point on a wall facing sideways with the part right under it (the axis starts inside
    // it): a vertical head would end below the part's underside, and the part holds the point.
    if (columns.inside(x, y, z - kBelowPointMm)) continue;
    const WayDown way = find_way_down(columns, x, y, z, full_back, floor, o.pillar_diameter_mm / 2);
    // No pillar fits, the head does not reach the part below, and its back hangs beside the
    // part: nothing would hold it.
    if (way.pillar_in_part && !(way.axis_z > full_back) &&
        !disc_meets_part(columns, x, y, h.cone.back[2], h.cone.r_back))
      continue;
    heads.push_back(h);
    ways.push_back(way);
  }
  return heads;
}

}  // namespace slicereuse
