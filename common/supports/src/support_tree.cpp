#include "slicereuse/supports/support_tree.h"

#include <algorithm>
#include <cmath>

#include "slicereuse/slicing/layer_planes.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "support_heads.h"
#include "support_links.h"
#include "support_pad.h"
#include "support_routes.h"

namespace slicereuse {

namespace {

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
  check_option("max_bridge_length_mm", o.max_bridge_length_mm, true);
  check_option("max_pillar_link_distance_mm", o.max_pillar_link_distance_mm, true);
  if (!(o.critical_angle_deg > 0 && o.critical_angle_deg < 90))
    throw Error(format("the supports' critical angle is %g degrees; it must be more than 0 and less than 90",
                       o.critical_angle_deg));
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

SupportStructure build_support_structure(const Mesh& part, const SupportPoints& points, double ground_z,
                                         const SupportTreeOptions& o) {
  check_options(o, ground_z);
  validate_support_points(points);
  SupportStructure s;
  if (points.size() == 0) return s;
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
  // Every face: whether a bridge runs inside the part is told by the face above it.
  const PartColumns columns(part);
  std::vector<WayDown> ways;
  s.heads = place_heads(columns, points, floor, o, ways);
  route_heads(columns, points, ways, floor, o, s);
  link_tall_pillars(columns, o, s);
  place_pad(o, ground_z, s);
  return s;
}

SupportTree build_support_tree(const Mesh& part, const SupportPoints& points, double ground_z,
                               const SupportTreeOptions& o) {
  SupportTree tree;
  tree.structure = build_support_structure(part, points, ground_z, o);
  tree.ground_z = ground_z;
  tree.mesh = mesh_support_structure(tree.structure);
  tree.head_zones = head_zones_of(tree.structure);
  for (size_t i = 0; i < points.size(); ++i) tree.up_facing += faces_up(points, i);
  tree.unroutable = points.size() - tree.up_facing - tree.structure.heads.size();
  for (const SupportHead& h : tree.structure.heads) {
    if (h.rest == HeadRest::Part) {
      ++tree.on_part;
      continue;
    }
    const SupportPillar* p = h.rest == HeadRest::Pillar ? &tree.structure.pillars[h.pillar] : nullptr;
    if (p && p->end == PillarEnd::Ground) ++tree.pillars;
    else if (p && p->end == PillarEnd::Foot) ++tree.on_part;
    else ++tree.bridged;
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
