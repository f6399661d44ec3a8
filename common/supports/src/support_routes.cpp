#include "support_routes.h"

#include <algorithm>
#include <cmath>

#include "bridge_path.h"
#include "cell_grid.h"
#include "support_heads.h"

namespace slicereuse {

namespace {

// A foot's cone starts this far above the highest hit under its pillar, so that the pillar's
// cylinder stays clear of the part and only the foot enters it.
constexpr double kFootRiseMm = 1;

double cylinder_mm3(double r, double height) { return M_PI * r * r * height; }
double cone_mm3(double r0, double r1, double height) { return M_PI * height * (r0 * r0 + r0 * r1 + r1 * r1) / 3; }

// How far sideways the longest bridge reaches, at the critical angle.
double max_bridge_run(const SupportTreeOptions& o) {
  return o.max_bridge_length_mm * std::cos(o.critical_angle_deg * M_PI / 180);
}

// A head's bridge to a pillar: its upper end under the head (upper_z below the head's back
// when the head needs a pillar of its own down to it), its lower end on the pillar.
struct Join {
  size_t pillar = kNoPiece;
  double upper_z = 0, lower_z = 0, mm3 = INFINITY;
};

// A junction at `at`, on the pillar or at the back of the head given (kNoPiece for the other).
size_t add_junction(SupportStructure& s, const Point3& at, size_t pillar, size_t head) {
  s.junctions.push_back({at, pillar, head});
  return s.junctions.size() - 1;
}

// A pillar from the head's back down to z_bottom, which the head then rests on.
size_t add_pillar(SupportStructure& s, size_t head, double z_bottom, PillarEnd end, double r) {
  const SupportCone& c = s.heads[head].cone;
  SupportPillar p;
  p.x = c.back[0], p.y = c.back[1], p.z_bottom = z_bottom, p.z_top = c.back[2], p.radius = r, p.end = end;
  p.head = head;
  s.pillars.push_back(p);
  s.heads[head].rest = HeadRest::Pillar;
  s.heads[head].pillar = s.pillars.size() - 1;
  return s.pillars.size() - 1;
}

// The cheapest clear bridge from head h to a pillar on the ground (see route_heads).
Join cheapest_join(const PartColumns& columns, const SupportStructure& s, const CellGrid& on_ground,
                   const std::vector<size_t>& bridges_on, size_t h, const WayDown& way, const SupportTreeOptions& o) {
  const double r = o.pillar_diameter_mm / 2, slope = std::tan(o.critical_angle_deg * M_PI / 180);
  const double max_run = max_bridge_run(o);
  const Point3& back = s.heads[h].cone.back;
  std::vector<Join> joins;
  for (const size_t p : on_ground.near(back[0], back[1])) {
    const SupportPillar& q = s.pillars[p];
    if (bridges_on[p] >= o.max_bridges_on_pillar) continue;
    const double run = std::hypot(q.x - back[0], q.y - back[1]);
    if (run < r || run > max_run) continue;
    Join j{p, back[2], back[2] - run * slope};
    if (j.lower_z > q.z_top) j.lower_z = q.z_top, j.upper_z = q.z_top + run * slope;
    if (j.lower_z < q.base_top) continue;
    // Its own pillar down to the bridge must be clear where the way down is blocked.
    if (!std::isnan(way.blocked_z) && !(way.blocked_z < j.lower_z)) continue;
    j.mm3 = cylinder_mm3(r, back[2] - j.upper_z) + cylinder_mm3(r, std::hypot(run, j.upper_z - j.lower_z));
    joins.push_back(j);
  }
  std::stable_sort(joins.begin(), joins.end(), [](const Join& a, const Join& b) { return a.mm3 < b.mm3; });
  for (const Join& j : joins) {
    const SupportPillar& q = s.pillars[j.pillar];
    if (bridge_is_clear(columns, {back[0], back[1], j.upper_z}, {q.x, q.y, j.lower_z}, r)) return j;
  }
  return {};
}

}  // namespace

void route_heads(const PartColumns& columns, const SupportPoints& points, const std::vector<WayDown>& ways,
                 double floor, const SupportTreeOptions& o, SupportStructure& s) {
  const double r_front = o.head_front_diameter_mm / 2, r_pillar = o.pillar_diameter_mm / 2;
  const double r_base = o.base_diameter_mm / 2;
  const double max_run = max_bridge_run(o);
  const bool joins = max_run > 0 && o.max_bridges_on_pillar > 0;
  CellGrid on_ground(joins ? max_run : 1);
  std::vector<size_t> bridges_on;  // per pillar, the heads' bridges ending on it
  auto new_pillar = [&](size_t h, double z_bottom, PillarEnd end) {
    bridges_on.push_back(0);
    return add_pillar(s, h, z_bottom, end, r_pillar);
  };
  for (size_t h = 0; h < s.heads.size(); ++h) {
    SupportHead& head = s.heads[h];
    const WayDown& way = ways[h];
    const double x = head.cone.back[0], y = head.cone.back[1];
    const double full_back = points.xyz[3 * head.point + 2] - o.head_width_mm;
    if (way.axis_z > full_back) {
      // Into the part below as deep as into the part above: not out of a thin wall's underside.
      const double wall = way.axis_z - columns.highest_hit(x, y, way.axis_z - kWallEpsilonMm, floor);
      const double end = std::max({way.axis_z - depth_in_wall(wall, o), full_back, floor});
      head.cone.back[2] = end;
      head.cone.r_back = head_radius_at(head, end, points, o);
      head.rest = HeadRest::Part;
      continue;
    }
    if (way.pillar_in_part) {
      // No pillar fits: the head's back already lies in the part beside it, which holds it.
      head.rest = HeadRest::Part;
      continue;
    }
    const double back = head.cone.back[2];
    const bool blocked = !std::isnan(way.blocked_z);
    const double base_top = std::min(floor + o.base_height_mm, back);
    if (joins && back > floor) {
      const Join j = cheapest_join(columns, s, on_ground, bridges_on, h, way, o);
      const double own_mm3 = cylinder_mm3(r_pillar, back - base_top) + cone_mm3(r_base, r_pillar, base_top - floor);
      if (j.pillar != kNoPiece && (blocked || j.mm3 < own_mm3)) {
        size_t upper;
        if (j.upper_z < back) {
          const size_t p = new_pillar(h, j.upper_z, PillarEnd::Bridge);
          upper = add_junction(s, {x, y, j.upper_z}, p, kNoPiece);
        } else {
          head.rest = HeadRest::Bridge;
          upper = add_junction(s, {x, y, back}, kNoPiece, h);
        }
        const SupportPillar& q = s.pillars[j.pillar];
        const size_t lower = add_junction(s, {q.x, q.y, j.lower_z}, j.pillar, kNoPiece);
        s.bridges.push_back({upper, lower, r_pillar, false});
        ++bridges_on[j.pillar];
        continue;
      }
    }
    if (blocked) {
      // A foot: a small head upside down, from the pillar into the part where the highest ray
      // met it; under a rim ray's hit, beside the axis, it leans from the pillar to the hit
      // rather than ending in the air on the axis.
      const double foot_top = std::min(full_back, way.blocked_z + kFootRiseMm);
      // As deep as a head goes: not out of a thin wall's underside, where its tip would hang.
      const double wall =
          way.blocked_z - columns.highest_hit(way.blocked_x, way.blocked_y, way.blocked_z - kWallEpsilonMm, floor);
      const double foot_bottom = std::max(way.blocked_z - depth_in_wall(wall, o), floor);
      const size_t p = new_pillar(h, foot_top, PillarEnd::Foot);
      SupportFoot f;
      f.cone = {{way.blocked_x, way.blocked_y, foot_bottom}, {x, y, foot_top}, r_front, r_pillar};
      f.penetration = way.blocked_z - foot_bottom;
      f.pillar = p;
      s.feet.push_back(f);
      s.pillars[p].foot = s.feet.size() - 1;
      continue;
    }
    const size_t p = new_pillar(h, floor, PillarEnd::Ground);
    s.pillars[p].base_radius = r_base;
    s.pillars[p].base_top = base_top;
    if (joins) on_ground.add(p, x, y);
  }
}

}  // namespace slicereuse
