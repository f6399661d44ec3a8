#pragma once
// support_tree: the support structure a part's support points ask for (support_structure.h), and
// its mesh to slice with the part (closed shells that may overlap each other and the part: the
// masks' nonzero rule fills their union). The part is not moved: the structure stands below it,
// on ground_z. After PrusaSlicer's SLA supports (SL1S defaults, its sla_print *SL1S*), in stages
// (build_support_structure):
//   1. heads (support_heads.h): for each point, a vertical cone whose narrow end
//     (head_front_diameter_mm) sits head_penetration_mm inside the part above the point (halfway
//     into a thinner wall), widening to the pillar's diameter head_width_mm below the point; and
//     its way down, by vertical rays through the pillar's axis and rim (pillar_path.h);
//   2. routes (support_routes.h), the heads in order: where the part below is nearer
//     than the head's width, the head ends in it (as deep as its tip goes); where no pillar fits
//     under the head (its back's section meets the part beside it: a groove narrower than the
//     pillar), the head rests on the part there; else the head joins a neighbouring pillar by a
//     bridge descending at least critical_angle_deg (at most max_bridge_length_mm long, at most
//     max_bridges_on_pillar on a pillar, clear of the part) where that takes less resin than a
//     pillar of its own, or where its own way down is blocked; else a pillar of pillar_diameter_mm
//     to the pad's top (or ground_z without a pad) on a base cone (base_diameter_mm,
//     base_height_mm); where the part blocks the way down, the pillar ends on it in a foot: a
//     small head upside down (head_front_diameter_mm, penetrating head_penetration_mm) whose cone
//     starts 1 mm above the highest hit and ends in the part at that hit (leaning from the axis
//     when a rim ray's hit is the highest);
//   3. links (support_links.h): pillars on the pad taller than 15 mm (35 mm) are linked to their
//     nearest one (two) within max_pillar_link_distance_mm by bridges zig-zagging down between
//     them, PrusaSlicer's pillar interconnection;
//   4. pad (support_pad.h, pad_enable): under the pillars on the ground, pad_wall_thickness_mm
//     thick, its top the convex hull of the bases grown by pad_brim_mm, its walls sloping in
//     towards the plate at pad_wall_slope_deg (its bottom smaller by thickness / tan(slope)).
// mesh_support_structure: every cone and cylinder a 16-gon (support_shapes.h), a bridge the loft
// between its horizontal sections at its ends, the pad a loft between its outlines; each shell
// closed, its faces counter-clockwise seen from outside; the same structure, the same bytes.
// A point whose surface faces up (faces_up, support_points.h) gets nothing: counted in
// up_facing, as PrusaSlicer drops it. Nor does a point the part lies right under (a wall facing
// sideways: the axis below it starts inside the part, which holds it), or where no pillar fits
// under its head and the head's back meets no part beside it to rest on: counted in unroutable.
// No points: no structure (an empty mesh, ground_z set); no pillar reaching the ground: no pad.
// Throws Error when a point (not facing up) lies at or below the pad's top (ground_z without a
// pad), the structure would be taller than max_height_mm ("... pillar of H mm, taller than the
// printer's ... mm"), an option or ground_z is not a finite number of the right sign (the critical
// angle not within (0, 90) degrees), the pad's
// walls slope in by more than the base's radius and brim, or the points are inconsistent
// (validate_support_points) or the part has no faces.
#include <cstddef>
#include <vector>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/supports/support_points.h"
#include "slicereuse/supports/support_structure.h"

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
  // Bridges (PrusaSlicer's support_critical_angle, the SL1S profile's support_max_bridge_length,
  // its defaults' support_max_pillar_link_distance and support_max_bridges_on_pillar): 0 mm
  // or 0 bridges turns joining heads, or linking pillars, off.
  double critical_angle_deg = 45;  // from the horizontal
  double max_bridge_length_mm = 10;
  double max_pillar_link_distance_mm = 10;
  size_t max_bridges_on_pillar = 3;
};

struct SupportTree {
  SupportStructure structure;
  Mesh mesh;                          // mesh_support_structure(structure)
  std::vector<HeadZone> head_zones;   // head_zones_of(structure)
  size_t pillars = 0;         // heads on pillars reaching the pad or ground
  size_t on_part = 0;         // heads ending on the part: in it, or on a pillar ending in a foot
  size_t bridged = 0;         // heads joined to a neighbouring pillar by a bridge
  size_t up_facing = 0;       // points dropped: their surface faces up
  size_t unroutable = 0;      // points dropped: the part right under them, or no pillar fits and nothing holds the head
  double ground_z = 0;
};

SupportStructure build_support_structure(const Mesh& part, const SupportPoints& points, double ground_z,
                                         const SupportTreeOptions& options);
Mesh mesh_support_structure(const SupportStructure& structure);
// The structure, its mesh, zones and counts.
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
