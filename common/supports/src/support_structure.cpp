#include "slicereuse/supports/support_structure.h"

#include <cmath>

namespace slicereuse {

std::vector<HeadZone> head_zones_of(const SupportStructure& s) {
  std::vector<HeadZone> zones;
  for (const SupportHead& h : s.heads) {
    const SupportCone& c = h.cone;
    zones.push_back({c.tip[0], c.tip[1], c.back[2], c.tip[2], c.r_back, c.r_tip});
    if (h.rest != HeadRest::Pillar || s.pillars[h.pillar].end != PillarEnd::Foot) continue;
    const SupportCone& f = s.feet[s.pillars[h.pillar].foot].cone;
    zones.push_back({f.tip[0], f.tip[1], f.tip[2], f.back[2], f.r_tip,
                     f.r_back + std::hypot(f.back[0] - f.tip[0], f.back[1] - f.tip[1])});
  }
  return zones;
}

}  // namespace slicereuse
