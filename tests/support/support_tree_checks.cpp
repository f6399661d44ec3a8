#include "support_tree_checks.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "slicereuse/crossparam/surface_grid.h"
#include "slicereuse/regions/clip_regions.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/slicing/layer_planes.h"
#include "slicereuse/slicing/slice_layers.h"

namespace slicereuse::test {
namespace {

using ClipperLib::Paths;

Paths region_of(const Slices& s, size_t k) { return layer_region(LayerView(s, k)); }


ClipperLib::IntRect bounds(const ClipperLib::Path& path) {
  ClipperLib::IntRect b{path[0].X, path[0].Y, path[0].X, path[0].Y};
  for (const ClipperLib::IntPoint& p : path)
    b.left = std::min(b.left, p.X), b.right = std::max(b.right, p.X), b.top = std::min(b.top, p.Y),
    b.bottom = std::max(b.bottom, p.Y);
  return b;
}

// Whether p lies in path (or on it) within 2 units: the clip's new vertices are rounded to units.
bool near_or_in(const ClipperLib::IntPoint& p, const ClipperLib::Path& path, const ClipperLib::IntRect& b) {
  if (p.X < b.left - 2 || p.X > b.right + 2 || p.Y < b.top - 2 || p.Y > b.bottom + 2) return false;
  for (const auto [dx, dy] : {std::pair{0, 0}, {2, 0}, {-2, 0}, {0, 2}, {0, -2}})
    if (ClipperLib::PointInPolygon({p.X + dx, p.Y + dy}, path) != 0) return true;
  return false;
}

// The head zones' sections at z, as circles around the 16-gons, grown by 1e-3 mm.
Paths zones_at(const std::vector<HeadZone>& zones, double z) {
  Paths out;
  for (const HeadZone& h : zones) {
    if (z < h.z_bottom || z > h.z_top) continue;
    const double r = h.r_bottom + (h.r_top - h.r_bottom) * (z - h.z_bottom) / (h.z_top - h.z_bottom);
    const double R = r / std::cos(M_PI / 64) + 1e-3;
    ClipperLib::Path circle;
    for (int i = 0; i < 64; ++i)
      circle.emplace_back(region_units(h.x + R * std::cos(2 * M_PI * i / 64)),
                          region_units(h.y + R * std::sin(2 * M_PI * i / 64)));
    out.push_back(circle);
  }
  return clip_regions(out, {}, ClipperLib::ctUnion);
}

}  // namespace

TreeSections check_tree_sections(const Mesh& part, const SupportTree& tree, double layer_mm) {
  const std::vector<double> planes = layer_planes(tree.ground_z, layer_mm, z_range(part).max);
  const Slices ps = slice_planes(part, planes, {}, false), ss = slice_planes(tree.mesh, planes, {}, false);
  TreeSections t;
  t.layers = planes.size();
  t.open_contours = ss.open_contours();
  Paths below;
  for (size_t k = 0; k < planes.size(); ++k) {
    // The supports' shells overlap: their union once, for every clip below.
    const Paths p = region_of(ps, k), s = clip_regions(region_of(ss, k), {}, ClipperLib::ctUnion);
    if (k == 0) t.ground_area_mm2 = region_area_mm2(s);
    const Paths both = clip_regions(p, s, ClipperLib::ctIntersection);
    if (!both.empty()) {
      ++t.overlapping_layers;
      const Paths out = clip_regions(both, zones_at(tree.head_zones, planes[k]), ClipperLib::ctDifference);
      const double outside = region_area_mm2(out);
      if (outside > t.outside_zones_mm2) {
        t.outside_zones_mm2 = outside, t.outside_zones_layer = k, t.outside_zones_z = planes[k];
        const auto by_area = [](const ClipperLib::Path& a, const ClipperLib::Path& b) {
          return std::fabs(ClipperLib::Area(a)) < std::fabs(ClipperLib::Area(b));
        };
        const auto largest = std::max_element(out.begin(), out.end(), by_area);
        const ClipperLib::IntRect b = bounds(*largest);
        t.outside_zones_xy[0] = double(b.left + b.right) / 2 / kRegionScale;
        t.outside_zones_xy[1] = double(b.top + b.bottom) / 2 / kRegionScale;
      }
    }
    if (k > 0) {
      // A piece of the union rests when a piece of its overlap with the layer below lies in it
      // (one clip for the layer: a clip per piece costs the pieces times the layer below). A
      // piece of the overlap spans every piece of the union it touches: pieces that touch along
      // an edge stay apart in the union but join in the overlap, so each point of the overlap
      // credits the pieces it lies in or on (one that touches a piece resting is held by it). A
      // piece in another's hole is credited with what rests in it too.
      std::vector<const ClipperLib::Path*> outer;
      std::vector<ClipperLib::IntRect> box;
      for (const ClipperLib::Path& piece : s)
        if (ClipperLib::Orientation(piece)) outer.push_back(&piece), box.push_back(bounds(piece));
      std::vector<bool> rests(outer.size(), false);
      for (const ClipperLib::Path& r : clip_regions(s, below, ClipperLib::ctIntersection))
        for (const ClipperLib::IntPoint& q : r)
          for (size_t i = 0; i < outer.size(); ++i)
            if (!rests[i] && near_or_in(q, *outer[i], box[i])) rests[i] = true;
      for (size_t i = 0; i < outer.size(); ++i)
        if (!rests[i] && t.support_islands++ == 0) {
          t.first_support_island_layer = k;
          t.first_support_island_xy[0] = double(box[i].left + box[i].right) / 2 / kRegionScale;
          t.first_support_island_xy[1] = double(box[i].top + box[i].bottom) / 2 / kRegionScale;
        }
    }
    below = clip_regions(p, s, ClipperLib::ctUnion);
  }
  return t;
}

FeetOnPart check_feet_on_part(const Mesh& part, const SupportTree& tree, const SupportTreeOptions& o) {
  const SurfaceGrid grid(part);
  FeetOnPart f;
  for (const SupportFoot& foot : tree.structure.feet) {
    ++f.feet;
    const Point3& t = foot.cone.tip;
    const double tip[3] = {t[0], t[1], t[2] + foot.penetration};
    const double d = grid.nearest_on_surface(tip, nullptr, 0, INFINITY).distance;
    if (d >= 1e-6 || !(foot.penetration > 0 && foot.penetration <= o.head_penetration_mm)) ++f.in_air;
    if (d > f.farthest_mm) f.farthest_mm = d, f.farthest_xy[0] = t[0], f.farthest_xy[1] = t[1];
  }
  return f;
}

}  // namespace slicereuse::test
