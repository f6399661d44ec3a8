// The supports' parameters, declared once for Generate Support Points, Transfer Support Points,
// Build Supports, Make Print Job and Make Plate Job, and each job member's supports.
#include <algorithm>
#include <cmath>
#include <memory>

#include "filters_common.h"
#include "slicereuse/hollowing/hollow_layers.h"
#include "slicereuse/supports/support_points_file.h"
#include "slicereuse/util/error.h"

namespace slicereuse::plugin {

ParamList<SupportPointParams> support_point_params() {
  const SupportPointOptions d;
  ParamList<SupportPointParams> l;
  l.number(&SupportPointParams::critical_angle_deg, "critical_angle", "Critical angle (degrees)",
           d.critical_angle_deg, Range::between(0, 90, "degrees"),
           "A surface flatter than this, from the horizontal, overhangs: flatter than 15 degrees too, it is covered "
           "with support points; between the two, its slopes get points only while the part is held by too few (its "
           "support force, as PrusaSlicer's slopes do). PrusaSlicer's own support_critical_angle is the angle of its "
           "support sticks.")
      .number(&SupportPointParams::density_percent, "density", "Support points density (%)",
              100 * d.density_relative, Range::above(0, "%"),
              "PrusaSlicer's support_points_density_relative: at 100 (the default) one point holds 10 mm2 of "
              "overhanging surface; 200 places twice as many.")
      .number(&SupportPointParams::minimal_distance_mm, "minimal_distance", "Minimal points distance (mm)",
              d.minimal_distance_mm, Range::above(0, "mm"),
              "PrusaSlicer's support_points_minimal_distance, in mm: on a member, a point added this near a dropped "
              "one counts as that point moved.");
  return l;
}

SupportPointOptions support_point_options(const SupportPointParams& p, double elevation_mm) {
  SupportPointOptions o;
  o.critical_angle_deg = p.critical_angle_deg;
  o.density_relative = p.density_percent / 100;
  o.minimal_distance_mm = p.minimal_distance_mm;
  o.raised = elevation_mm > 0;
  return o;
}

ParamList<SupportTreeOptions> support_tree_params() {
  using T = SupportTreeOptions;
  const T d;
  ParamList<T> l;
  l.number(&T::head_front_diameter_mm, "head_front_diameter", "Head front diameter (mm)", d.head_front_diameter_mm,
           Range::above(0, "mm"), "Diameter of the support head's tip where it touches the part, in mm.")
      .number(&T::head_penetration_mm, "head_penetration", "Head penetration (mm)", d.head_penetration_mm,
              Range::at_least(0, "mm"), "How far the head's tip goes into the part, in mm, so that it holds.")
      .number(&T::head_width_mm, "head_width", "Head width (mm)", d.head_width_mm, Range::above(0, "mm"),
              "Length of the head's cone, from the tip to the pillar, in mm.")
      .number(&T::pillar_diameter_mm, "pillar_diameter", "Pillar diameter (mm)", d.pillar_diameter_mm,
              Range::above(0, "mm"), "Diameter of the pillars, in mm.")
      .number(&T::base_diameter_mm, "base_diameter", "Pillar base diameter (mm)", d.base_diameter_mm,
              Range::above(0, "mm"), "Diameter of the cone each pillar stands on, in mm.")
      .number(&T::base_height_mm, "base_height", "Pillar base height (mm)", d.base_height_mm, Range::at_least(0, "mm"),
              "Height of the cone each pillar stands on, in mm.")
      .number(&T::object_elevation_mm, "object_elevation", "Object elevation (mm)", d.object_elevation_mm,
              Range::at_least(0, "mm"),
              "How high the part stands above the plate (or the pad), in mm, rounded to whole layers; the part is "
              "not moved: the supports stand that far below its first layer. 0: the part stands on the plate, "
              "with the pad off (a part sunk into its pad is not modelled: 0 with the pad is refused).")
      .flag(&T::pad_enable, "pad_enable", "Pad", d.pad_enable,
            "A pad under the supports, holding them together on the plate.")
      .number(&T::pad_wall_thickness_mm, "pad_wall_thickness", "Pad wall thickness (mm)", d.pad_wall_thickness_mm,
              Range::above(0, "mm"), "Thickness of the pad, in mm.")
      .number(&T::pad_wall_slope_deg, "pad_wall_slope", "Pad wall slope (degrees)", d.pad_wall_slope_deg,
              Range::between(1, 90, "degrees"), "Slope of the pad's walls from the plate, in degrees; 90: vertical.");
  return l;
}

ParamList<JobSupports> job_support_params() {
  ParamList<JobSupports> l;
  l.choice(&JobSupports::mode, "supports", "Supports", {"none", "generate", "transfer"}, JobSupportsMode::None,
           "none (the default): the part stands on the plate as it is. generate: support points are found on each "
           "member and its supports built. transfer: the points of support_points_file (the family's source's) are "
           "carried to each member, certified there, completed where the member needs more, and its supports "
           "built. Either way, the resin traps the supports close (air between pillars, heads and the part that "
           "nothing drains, up to 20 mm3 each) are printed solid.")
      .file(&JobSupports::support_points_file, ParamType::FileOpen, "support_points_file", "Source support points",
            "*.srp", nullptr,
            "With supports = transfer: the support-points file written by Generate Support Points on the family's "
            "source; every member must have the source's faces.")
      .include(&JobSupports::points, support_point_params())
      .include(&JobSupports::tree, support_tree_params());
  return l;
}

namespace {

// A hollowed, drained member's drain holes (drilled as the job drills them, from the same layers,
// at thickness) as cylinders its support heads keep clear of; none when it is solid or undrained.
// Its cavity, made first, goes to the job (o.made_cavities), which takes it for the same member
// on the same planes (the supports come first).
std::vector<KeepOutCylinder> drain_hole_keep_out(const Mesh& member, const Slices& layers, double z_start,
                                                 double thickness, const std::string& name, PlateJobOptions& o) {
  std::vector<KeepOutCylinder> out;
  if (o.hollowing.wall_mm == 0 || o.drain_hole_mm == 0) return out;
  std::vector<ClipperLib::Paths> cavity = layers_cavity(layers, o.hollowing);
  o.made_cavities.push_back({&member, layers.layer_z, o.hollowing, cavity});
  if (cavity_volume_mm3(cavity, thickness) == 0) return out;
  for (const DrainHole& h : drill_member_drain_holes(member, layers, name, o, cavity)) {
    const auto ends = drain_hole_axis(h, z_start, thickness, drain_hole_depth_mm(o.hollowing));
    out.push_back({ends[0], ends[1], 0.5 * o.drain_hole_mm});
  }
  return out;
}

}  // namespace

std::vector<MemberSupports> job_member_supports(const std::vector<const Mesh*>& members, const JobSupports& s,
                                                PlateJobOptions& o, const Progress& progress) {
  std::vector<MemberSupports> out;
  if (s.mode == JobSupportsMode::None) return out;
  if (s.mode == JobSupportsMode::Transfer && s.support_points_file.empty())
    throw Error("supports is transfer, but support_points_file is empty: choose the source's support-points file");
  std::unique_ptr<SupportPoints> source;
  if (s.mode == JobSupportsMode::Transfer)
    source = std::make_unique<SupportPoints>(read_support_points(s.support_points_file));
  const double thickness = o.encoding ? o.encoding->thickness : o.slicing.thickness;
  double z_start = o.encoding ? o.encoding->z_start : o.slicing.z_start;
  if (std::isnan(z_start)) {
    z_start = HUGE_VAL;
    for (const Mesh* m : members) z_start = std::min(z_start, z_range(*m).min);
    o.slicing.z_start = z_start;
  }
  o.layers_below = support_layers_below(s.tree, thickness);
  MemberSupportOptions mo;
  mo.points = support_point_options(s.points, s.tree.object_elevation_mm);
  mo.tree = s.tree;
  SliceOptions slicing;
  slicing.thickness = thickness;
  slicing.z_start = z_start;
  for (size_t m = 0; m < members.size(); ++m) {
    const Progress part = sub_progress(progress, double(m) / double(members.size()),
                                       double(m + 1) / double(members.size()));
    // A member of the encoding's family is transferred (exact: its own slicing, with its own
    // encoding); any other is sliced on the same planes.
    const bool reuse = o.encoding && o.encoding->fingerprint == mesh_fingerprint(*members[m]);
    Slices member_slicing = reuse ? transfer_contours(*o.encoding, *members[m], TransferOptions(), nullptr,
                                                            sub_progress(part, 0, 0.3))
                                        : slice_layers(*members[m], slicing, sub_progress(part, 0, 0.3));
    const std::string name = m < o.names.size() ? o.names[m] : "member " + std::to_string(m + 1);
    MemberSupportOptions own = mo;
    member_slicing.thickness = thickness;
    own.keep_out = drain_hole_keep_out(*members[m], member_slicing, z_start, thickness, name, o);
    try {
      out.push_back(make_member_supports(*members[m], member_slicing, z_start, thickness, own, source.get(), nullptr,
                                         sub_progress(part, 0.3, 1)));
    } catch (const Error& e) {
      throw Error(name + "'s supports: " + e.what());
    }
  }
  return out;
}

void add_support_figures(const MemberSupports& s, const std::string& suffix, Result& result) {
  result["support_points" + suffix] = int64_t(s.points.size());
  result["kept" + suffix] = int64_t(s.transfer.kept);
  result["moved" + suffix] = int64_t(s.transfer.moved);
  result["added" + suffix] = int64_t(s.transfer.added);
  result["dropped" + suffix] = int64_t(s.transfer.dropped);
}

}  // namespace slicereuse::plugin
