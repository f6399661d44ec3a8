#include "slicereuse/supports/support_tree.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "pillar_path.h"
#include "slicereuse/slicing/layer_planes.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "support_pad.h"
#include "support_shapes.h"

namespace slicereuse {

namespace {

// The rim rays run this far outside the pillar: 0.1 mm between pillar and part, plus a mask
// pixel (0.05 mm) so that the pillar's section never lights a pixel of the part's.
constexpr double kRimClearanceMm = 0.15;
// A foot's cone starts this far above the highest hit under its pillar, so that the pillar's
// cylinder stays clear of the part and only the foot enters it.
constexpr double kFootRiseMm = 1;
// The point's own face lies at its height: the wall above it starts higher than this.
constexpr double kWallEpsilonMm = 1e-6;

void check_option(const char* name, double value, bool zero_allowed) {
  if (!std::isfinite(value) || value < 0 || (value == 0 && !zero_allowed))
    throw Error(format("the support option %s is %g mm; it must be a %s number", name, value,
                       zero_allowed ? "finite, non-negative" : "finite, positive"));
}

void check_options(const SupportTreeOptions& o, double ground_z) {
  if (!std::isfinite(ground_z)) throw Error(format("the supports' ground is at z = %g mm, not a finite height", ground_z));
  check_option("head_front_diameter_mm", o.head_front_diameter_mm, false);
  check_option("head_penetration_mm", o.head_penetration_mm, false);
  check_option("head_width_mm", o.head_width_mm, false);
  check_option("pillar_diameter_mm", o.pillar_diameter_mm, false);
  check_option("base_diameter_mm", o.base_diameter_mm, false);
  check_option("base_height_mm", o.base_height_mm, false);
  check_option("max_height_mm", o.max_height_mm, false);
  if (!o.pad_enable) return;
  check_option("pad_wall_thickness_mm", o.pad_wall_thickness_mm, false);
  check_option("pad_brim_mm", o.pad_brim_mm, true);
  if (!(o.pad_wall_slope_deg > 0 && o.pad_wall_slope_deg <= 90))
    throw Error(format("the pad's wall slope is %g degrees; it must be more than 0 and at most 90",
                       o.pad_wall_slope_deg));
  const double inset = o.pad_wall_thickness_mm / std::tan(o.pad_wall_slope_deg * M_PI / 180);
  if (inset >= o.base_diameter_mm / 2 + o.pad_brim_mm)
    throw Error(format("the pad's walls, %g mm high at %g degrees, slope in by %g mm, more than the base's radius "
                       "and brim (%g mm): the pad would have no bottom",
                       o.pad_wall_thickness_mm, o.pad_wall_slope_deg, inset, o.base_diameter_mm / 2 + o.pad_brim_mm));
}

}  // namespace

SupportTree build_support_tree(const Mesh& part, const SupportPoints& points, double ground_z,
                               const SupportTreeOptions& o) {
  check_options(o, ground_z);
  validate_support_points(points);
  SupportTree tree;
  tree.ground_z = ground_z;
  if (points.size() == 0) return tree;
  const double floor = ground_z + (o.pad_enable ? o.pad_wall_thickness_mm : 0);
  for (size_t i = 0; i < points.size(); ++i) {
    const double z = points.xyz[3 * i + 2];
    if (faces_up(points, i)) continue;
    if (!(z > floor))
      throw Error(format("support point %zu at z = %g mm is below the %s at %g mm", i + 1, z,
                         o.pad_enable ? "pad's top" : "ground", floor));
    const double height = z + o.head_penetration_mm - ground_z;
    if (height > o.max_height_mm)
      throw Error(format("support point %zu needs a pillar of %g mm (from the ground at z = %g mm to its head's top), "
                         "taller than the printer's %g mm",
                         i + 1, height, ground_z, o.max_height_mm));
  }
  validate_mesh(part);
  // The ways down start at the points, and the heads reach at most the penetration above them:
  // faces wholly above that are never met.
  double highest = -INFINITY;
  for (size_t i = 0; i < points.size(); ++i) highest = std::max(highest, points.xyz[3 * i + 2]);
  const PartColumns columns(part, false, highest + o.head_penetration_mm);
  const double r_front = o.head_front_diameter_mm / 2, r_pillar = o.pillar_diameter_mm / 2;
  const double r_base = o.base_diameter_mm / 2, pen = o.head_penetration_mm;
  std::vector<std::array<double, 2>> on_floor;
  Mesh& m = tree.mesh;
  auto add_cone = [&](double x, double y, double z_bottom, double r_bottom, double z_top, double r_top, bool zone) {
    append_frustum(m, x, y, z_bottom, r_bottom, z_top, r_top);
    if (zone) tree.head_zones.push_back({x, y, z_bottom, z_top, r_bottom, r_top});
  };
  for (size_t i = 0; i < points.size(); ++i) {
    if (faces_up(points, i)) {
      ++tree.up_facing;
      continue;
    }
    const double x = points.xyz[3 * i], y = points.xyz[3 * i + 1], z = points.xyz[3 * i + 2];
    // Into a wall thinner than twice the penetration, the head goes halfway: it must not come
    // out of the part's other side.
    const double wall_top = columns.lowest_hit_above(x, y, z + kWallEpsilonMm);
    const double z_top = z + (std::isnan(wall_top) ? pen : std::min(pen, (wall_top - z) / 2));
    const double z_head_bottom = z - o.head_width_mm;
    // The head's radius at height h: r_front at its top, the pillar's at its full width below.
    auto head_r = [&](double h) { return r_pillar + (r_front - r_pillar) * (h - z_head_bottom) / (z_top - z_head_bottom); };
    const WayDown way = find_way_down(columns, x, y, z, z_head_bottom, floor, r_pillar + kRimClearanceMm);
    if (way.axis_z > z_head_bottom) {
      // The head reaches the part below it: it ends in it, penetrating as deep as at its top,
      // and as there halfway into a part thinner than twice that, not out of its underside.
      const double under = columns.highest_hit(x, y, way.axis_z - kWallEpsilonMm, floor);
      const double depth = std::isnan(under) ? pen : std::min(pen, (way.axis_z - under) / 2);
      const double end = std::max({way.axis_z - depth, z_head_bottom, floor});
      add_cone(x, y, end, head_r(end), z_top, r_front, true);
      ++tree.on_part;
      continue;
    }
    const double head_bottom = std::max(z_head_bottom, floor);
    add_cone(x, y, head_bottom, head_r(head_bottom), z_top, r_front, true);
    if (!std::isnan(way.blocked_z)) {
      // A foot: a small head upside down, from the pillar into the part where the highest ray
      // met it; under a rim ray's hit, beside the axis, it leans from the pillar to the hit
      // rather than ending in the air on the axis. Its zone is the vertical cone around the
      // hit that holds it (the lean, rim_radius at the top, added to its radius).
      const double foot_top = std::min(z_head_bottom, way.blocked_z + kFootRiseMm);
      const double foot_bottom = std::max(way.blocked_z - pen, floor);
      const double bx = way.blocked_x, by = way.blocked_y;
      append_loft(m, circle_outline(bx, by, r_front), foot_bottom, circle_outline(x, y, r_pillar), foot_top);
      tree.head_zones.push_back({bx, by, foot_bottom, foot_top, r_front, r_pillar + std::hypot(x - bx, y - by)});
      if (foot_top < z_head_bottom) add_cone(x, y, foot_top, r_pillar, z_head_bottom, r_pillar, false);
      ++tree.on_part;
      continue;
    }
    if (head_bottom > floor) {
      const double base_top = std::min(floor + o.base_height_mm, head_bottom);
      add_cone(x, y, floor, r_base, base_top, r_pillar, false);
      if (base_top < head_bottom) add_cone(x, y, base_top, r_pillar, head_bottom, r_pillar, false);
    }
    on_floor.push_back({x, y});
    ++tree.pillars;
  }
  if (o.pad_enable && !on_floor.empty()) {
    const double r_pad = r_base + o.pad_brim_mm;
    const double inset = o.pad_wall_thickness_mm / std::tan(o.pad_wall_slope_deg * M_PI / 180);
    append_pad(m, on_floor, r_pad - inset, r_pad, ground_z, floor);
  }
  return tree;
}

size_t support_layers_below(const SupportTreeOptions& o, double thickness) {
  const double elevation_mm = o.object_elevation_mm;
  if (!(std::isfinite(thickness) && thickness > 0))
    throw Error(format("the layer thickness is %g mm; it must be a finite, positive number", thickness));
  if (!(std::isfinite(elevation_mm) && elevation_mm >= 0))
    throw Error(format("the object's elevation is %g mm; it must be a finite, non-negative number", elevation_mm));
  if (o.pad_enable && elevation_mm == 0)
    throw Error(format("an object elevation of 0 mm with the pad on needs the part sunk into its pad (PrusaSlicer's "
                       "zero elevation), which the supports do not model: the pad's top (%g mm thick) would lie in "
                       "the part; raise the part (an elevation above 0) or turn the pad off",
                       o.pad_wall_thickness_mm));
  const double below = elevation_mm + (o.pad_enable ? o.pad_wall_thickness_mm : 0);
  // Rounded to whole layers, but never so far down that the pad's top reaches the part's first
  // plane: at least one layer more than the pad's thickness holds.
  const double layers = std::max(std::round(below / thickness),
                                 o.pad_enable ? std::floor(o.pad_wall_thickness_mm / thickness) + 1 : 0.0);
  if (layers > double(kMaxLayers))
    throw Error(format("an elevation of %g mm is %.0f layers of %g mm, more than %zu", below, layers, thickness,
                       kMaxLayers));
  return size_t(layers);
}

}  // namespace slicereuse
