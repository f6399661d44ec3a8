#pragma once
// support_tree: the support structure a part's support points ask for, as one mesh to slice with
// the part (closed shells that may overlap each other and the part: the masks' nonzero rule
// fills their union). The part is not moved: the structure stands below it, on ground_z.
// For each point, after PrusaSlicer's SLA supports (SL1S defaults, its sla_print *SL1S*):
//   head: a vertical cone whose narrow end (head_front_diameter_mm) sits head_penetration_mm
//     inside the part above the point, widening to the pillar's diameter head_width_mm below the
//     point;
//   pillar: a vertical cylinder of pillar_diameter_mm from the head down to the pad's top (or
//     ground_z without a pad), standing on a base cone (base_diameter_mm, base_height_mm);
//     where the way down is blocked by the part (a vertical ray through the pillar's axis or its
//     rim, with clearance, hits it), the pillar ends on the part with a small head
//     (head_front_diameter_mm, penetrating head_penetration_mm) instead: a foot, upside down,
//     whose cone starts 1 mm above the highest hit and ends in the part at that hit (leaning
//     from the axis when a rim ray's hit is the highest); where the part below is nearer than
//     the head's width, the head itself ends in it (halfway into a part thinner than twice the
//     penetration, as the head's top into a thin wall).
// Every cone and cylinder is a 16-gon (support_shapes.h), the pad a loft between two outlines;
// each shell closed, its faces counter-clockwise seen from outside.
// pad (pad_enable): under everything that reaches ground_z, pad_wall_thickness_mm thick, its top
//   the convex hull of the bases grown by pad_brim_mm, its walls sloping in towards the plate at
//   pad_wall_slope_deg (its bottom smaller by thickness / tan(slope)), as PrusaSlicer's pad.
// head_zones: where the structure may enter the part (each head, and each foot on the part), as
// vertical cones (a leaning foot's around its tip, wide enough to hold it): the only places the
// part's and the supports' sections may overlap.
// A point whose surface faces up (faces_up, support_points.h) gets nothing: counted in
// up_facing, as PrusaSlicer drops it.
// No points: no structure (an empty mesh, ground_z set); no pillar reaching the ground: no pad.
// Throws Error when a point (not facing up) lies at or below the pad's top (ground_z without a
// pad), the structure would be taller than max_height_mm ("... pillar of H mm, taller than the
// printer's ... mm"), an option or ground_z is not a finite number of the right sign, the pad's
// walls slope in by more than the base's radius and brim, or the points are inconsistent
// (validate_support_points) or the part has no faces.
#include <cstddef>
#include <vector>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/supports/support_points.h"

namespace slicereuse {

struct SupportTreeOptions {  // PrusaSlicer 2.5's SL1S print profile (sla_print:*SL1S*)
  double head_front_diameter_mm = 0.5;
  double head_penetration_mm = 0.5;
  double head_width_mm = 3;
  double pillar_diameter_mm = 1;
  double base_diameter_mm = 3;
  double base_height_mm = 1;
  double object_elevation_mm = 5;
  bool pad_enable = true;
  double pad_wall_thickness_mm = 1;
  double pad_wall_slope_deg = 45;
  // PrusaSlicer's pad_brim_size (1.6) is for a part sunk into its pad (zero elevation); raised,
  // its pad ends at the bases.
  double pad_brim_mm = 0;
  double max_height_mm = 150;
};

// A vertical cone where supports may enter the part: radius r_bottom at z_bottom, r_top at z_top.
struct HeadZone {
  double x = 0, y = 0;
  double z_bottom = 0, z_top = 0;
  double r_bottom = 0, r_top = 0;
};

struct SupportTree {
  Mesh mesh;
  std::vector<HeadZone> head_zones;
  size_t pillars = 0;         // reaching the pad or ground
  size_t on_part = 0;         // ending on the part
  size_t up_facing = 0;       // points dropped: their surface faces up
  double ground_z = 0;
};

SupportTree build_support_tree(const Mesh& part, const SupportPoints& points, double ground_z,
                               const SupportTreeOptions& options);

// Where the structure stands for a part sliced from z_start in layers of thickness: the part
// object_elevation_mm above the pad's top (PrusaSlicer's support_object_elevation), so the pad's
// bottom lies elevation plus pad thickness below z_start, rounded to whole layers (but at least
// one layer more than the pad's thickness, so the pad's top stays below z_start): the part's
// layers keep their planes and the job gains that many layers below it.
// Elevation 0 without a pad: the part on the plate, ground_z = z_start, every point at or under
// it refused; a part on the plate is printed without supports. Elevation 0 with the pad
// (PrusaSlicer's part sunk into its pad, pad_around_object) is not modelled: refused.
// Throws Error for a thickness that is not positive, an elevation that is negative or not
// finite, elevation 0 with the pad ("an object elevation of 0 mm with the pad on needs the part
// sunk into its pad ..."), or more than kMaxLayers layers.
size_t support_layers_below(const SupportTreeOptions& options, double thickness);
inline double support_ground_z(double z_start, double thickness, const SupportTreeOptions& options) {
  return z_start - double(support_layers_below(options, thickness)) * thickness;
}

}  // namespace slicereuse
