// mesh_support_structure (support_tree.h): the structure's pieces as closed shells, each head
// followed by what hangs from it (its foot, its pillar and base), then the bridges, then the pad.
#include "slicereuse/supports/support_tree.h"
#include "support_shapes.h"

namespace slicereuse {

namespace {

void append_cone(Mesh& m, const SupportCone& c) {
  const bool tip_up = c.tip[2] > c.back[2];
  const Point3& bottom = tip_up ? c.back : c.tip;
  const Point3& top = tip_up ? c.tip : c.back;
  append_loft(m, circle_outline(bottom[0], bottom[1], tip_up ? c.r_back : c.r_tip), bottom[2],
              circle_outline(top[0], top[1], tip_up ? c.r_tip : c.r_back), top[2]);
}

}  // namespace

Mesh mesh_support_structure(const SupportStructure& s) {
  Mesh m;
  for (const SupportHead& h : s.heads) {
    append_cone(m, h.cone);
    if (h.rest != HeadRest::Pillar) continue;
    const SupportPillar& p = s.pillars[h.pillar];
    if (p.end == PillarEnd::Foot) append_cone(m, s.feet[p.foot].cone);
    double bottom = p.z_bottom;
    if (p.end == PillarEnd::Ground && p.base_top > p.z_bottom) {
      append_frustum(m, p.x, p.y, p.z_bottom, p.base_radius, p.base_top, p.radius);
      bottom = p.base_top;
    }
    if (bottom < p.z_top) append_frustum(m, p.x, p.y, bottom, p.radius, p.z_top, p.radius);
  }
  for (const SupportBridge& b : s.bridges) {
    const Point3& u = s.junctions[b.upper].at;
    const Point3& l = s.junctions[b.lower].at;
    const double dx = u[0] - l[0], dy = u[1] - l[1], dz = u[2] - l[2];
    append_loft(m, section_outline(l[0], l[1], b.radius, dx, dy, dz), l[2],
                section_outline(u[0], u[1], b.radius, dx, dy, dz), u[2]);
  }
  if (!s.pad.top.empty()) append_loft(m, s.pad.bottom, s.pad.z_bottom, s.pad.top, s.pad.z_top);
  return m;
}

}  // namespace slicereuse
