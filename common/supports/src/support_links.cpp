#include "support_links.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "bridge_path.h"
#include "cell_grid.h"

namespace slicereuse {

namespace {

size_t links_needed(const SupportPillar& p) {
  const double height = p.z_top - p.z_bottom;
  return height > kMaxDualPillarMm ? 2 : height > kMaxSoloPillarMm ? 1 : 0;
}

// The zig-zag between pillars a and b (see link_tall_pillars); whether a bridge was built.
bool zig_zag(const PartColumns& columns, size_t a, size_t b, double slope, SupportStructure& s) {
  const SupportPillar pa = s.pillars[a], pb = s.pillars[b];
  const double drop = std::hypot(pb.x - pa.x, pb.y - pa.y) * slope;
  const double z_low = std::max(pa.base_top, pb.base_top);
  size_t from = a, to = b;
  bool built = false;
  size_t upper = kNoPiece;  // the junction the last bridge built ended at, when it is where the next starts
  for (double z = std::min(pa.z_top, pb.z_top); z - drop >= z_low; z -= drop, std::swap(from, to)) {
    const SupportPillar& p = s.pillars[from];
    const SupportPillar& q = s.pillars[to];
    const Point3 u{p.x, p.y, z}, l{q.x, q.y, z - drop};
    if (!bridge_is_clear(columns, u, l, std::min(p.radius, q.radius))) {
      upper = kNoPiece;
      continue;
    }
    if (upper == kNoPiece) {
      s.junctions.push_back({u, from, kNoPiece});
      upper = s.junctions.size() - 1;
    }
    s.junctions.push_back({l, to, kNoPiece});
    s.bridges.push_back({upper, s.junctions.size() - 1, std::min(p.radius, q.radius), true});
    upper = s.junctions.size() - 1;
    built = true;
  }
  return built;
}

}  // namespace

void link_tall_pillars(const PartColumns& columns, const SupportTreeOptions& o, SupportStructure& s) {
  if (!(o.max_pillar_link_distance_mm > 0)) return;
  const double slope = std::tan(o.critical_angle_deg * M_PI / 180);
  CellGrid on_ground(o.max_pillar_link_distance_mm);
  for (size_t p = 0; p < s.pillars.size(); ++p)
    if (s.pillars[p].end == PillarEnd::Ground) on_ground.add(p, s.pillars[p].x, s.pillars[p].y);
  std::vector<size_t> links(s.pillars.size(), 0);
  std::set<std::pair<size_t, size_t>> linked;
  for (size_t a = 0; a < s.pillars.size(); ++a) {
    const SupportPillar& p = s.pillars[a];
    if (p.end != PillarEnd::Ground || links[a] >= links_needed(p)) continue;
    std::vector<std::pair<double, size_t>> near;  // (distance, pillar)
    for (const size_t b : on_ground.near(p.x, p.y)) {
      const SupportPillar& q = s.pillars[b];
      const double d = std::hypot(q.x - p.x, q.y - p.y);
      if (b != a && d >= p.radius + q.radius && d <= o.max_pillar_link_distance_mm &&
          !linked.count({std::min(a, b), std::max(a, b)}))
        near.emplace_back(d, b);
    }
    std::sort(near.begin(), near.end());
    for (const auto& [d, b] : near) {
      if (links[a] >= links_needed(s.pillars[a])) break;
      if (!zig_zag(columns, a, b, slope, s)) continue;
      linked.insert({std::min(a, b), std::max(a, b)});
      ++links[a], ++links[b];
    }
  }
}

}  // namespace slicereuse
