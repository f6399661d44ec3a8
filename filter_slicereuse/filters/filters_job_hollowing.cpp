// The hollowing Make Print Job and Make Plate Job apply to their members, and what they report of
// it.
#include "filters_common.h"
#include "slicereuse/hollowing/cavity.h"
#include "slicereuse/hollowing/drain_holes.h"
#include "slicereuse/supports/locate_support_points.h"
#include "slicereuse/supports/support_points_file.h"

namespace slicereuse::plugin {

ParamList<HollowingOptions> hollowing_params(double default_wall_mm) {
  const std::string wall_tooltip =
      "Hollow the part, keeping walls at least this thick in mm (PrusaSlicer's hollowing_min_thickness; its "
      "profiles' 3 mm): the cavity is every point farther than this inside the part, in 3-D, computed on the "
      "layers' contours. " +
      (default_wall_mm == 0 ? std::string("0 (the default): solid. ")
                            : format("%g mm by default; 0: solid, nothing to hollow. ", default_wall_mm)) +
      "The cavity is sealed until drain holes open it, so the printability check reports it as a resin trap.";
  ParamList<HollowingOptions> l;
  l.number(&HollowingOptions::wall_mm, "hollow_wall_mm", "Hollow: wall thickness (mm)", default_wall_mm,
           Range::at_least(0, "mm"), wall_tooltip.c_str())
      .number(&HollowingOptions::closing_mm, "hollow_closing_mm", "Hollow: closing distance (mm)",
              kPrusaHollowingClosingMm, Range::at_least(0, "mm"),
              "PrusaSlicer's hollowing_closing_distance: the cavity is made this much deeper, then grown back by "
              "it, which drops its parts narrower than twice this and rounds its edges. 0: the cavity follows the "
              "part's shape most closely.");
  return l;
}

ParamList<DrainHoleParams> drain_hole_params() {
  ParamList<DrainHoleParams> l;
  l.number(&DrainHoleParams::diameter_mm, "drain_hole_mm", "Hollow: drain hole diameter (mm)", kDrainHoleMm,
           Range::at_least(0, "mm"),
           "A drain hole of this diameter under every cavity, through the bottom wall to the base (or at each of "
           "the user's points), so that the resin drains and no cavity stays sealed (PrusaSlicer's holes are 4 mm by default). 0: no holes: the "
           "cavity is sealed, and the check reports it as a resin trap.")
      .whole(&DrainHoleParams::per_cavity, "drain_holes", "Hollow: drain holes per cavity", 1,
             Range::between(1, 100, ""),
             "How many drain holes each cavity gets: the first under its middle, each further one where its lowest "
             "layer lies farthest from the holes placed, so they spread over it (1, the default: one).");
  return l;
}

ParamList<JobHollowing> job_hollowing_params() {
  ParamList<JobHollowing> l;
  l.include(&JobHollowing::cavity, hollowing_params(0))
      .include(&JobHollowing::holes, drain_hole_params())
      .whole(&JobHollowing::points_layer, "drain_points_layer", "Hollow: drain hole points layer", -1,
             Range::at_least(-1, ""),
             "The user's drain holes instead of the automatic ones: a point layer of the (first) member's hole "
             "mouths, as Add Drain Holes adds one (points may be deleted, moved on the surface or added there; a "
             "point farther than 1 mm from the surface is refused), each drilled along its surface's normal "
             "through the wall into the cavity, on every member at the same place on its own surface. The layer's "
             "0-based index as loaded (pymeshlab: its mesh id). -1 (the default): automatic holes.")
      .file(&JobHollowing::holes_file, ParamType::FileOpen, "drain_holes_file", "Hollow: drain holes file", "*.srp",
            nullptr,
            "The user's drain holes from a file instead (a support-points file, .srp, of the hole mouths, as Add "
            "Drain Holes writes). Empty (the default): the point layer, or automatic holes.");
  return l;
}

void set_job_hollowing(const JobHollowing& h, Host& host, const Mesh& first, PlateJobOptions& o) {
  o.hollowing = h.cavity;
  o.drain_hole_mm = h.holes.diameter_mm;
  o.drain_holes_per_cavity = size_t(h.holes.per_cavity);
  const bool layer = h.points_layer >= 0, file = !h.holes_file.empty();
  if (!layer && !file) return;
  if (layer && file)
    throw Error(format("drain_points_layer is %d and drain_holes_file is %s: give the user's holes one way",
                       h.points_layer, h.holes_file.c_str()));
  if (h.cavity.wall_mm == 0 || h.holes.diameter_mm == 0)
    throw Error(format("drain holes were given, but %s: they need hollow_wall_mm and drain_hole_mm above 0",
                       h.cavity.wall_mm == 0 ? "hollow_wall_mm is 0 (solid)" : "drain_hole_mm is 0 (no holes)"));
  if (file) {
    o.drain_points = read_support_points(h.holes_file);
    try {
      validate_support_points(o.drain_points, &first);
    } catch (const Error& e) {
      throw Error(format("drain_holes_file %s: %s", h.holes_file.c_str(), e.what()));
    }
    return;
  }
  const Mesh points = host.mesh_at(h.points_layer);
  if (points.faces() > 0)
    throw Error(format("the drain hole points layer (layer %d) is a mesh of %zu faces, not a point layer",
                       h.points_layer, points.faces()));
  o.drain_points = locate_support_points(first, points.V, {}, kUserPointReachMm, "drain hole point");
}

void report_hollowing(Host& host, const char* filter, const std::string& plate_label, const PlateJobStats& st,
                      const std::vector<std::string>& names, bool per_member, Result& result) {
  result.emplace("cavity_mm3", 0.0);
  result.emplace("drain_holes", int64_t(0));
  if (st.hollowing_seconds == 0) return;  // solid
  const std::string where = plate_label.empty() ? "" : plate_label + ": ";
  double total = 0;
  size_t holes_total = 0;
  for (size_t m = 0; m < st.cavity_mm3.size(); ++m) {
    total += st.cavity_mm3[m];
    const std::vector<DrainHole>& holes = st.drain_holes[m];
    holes_total += holes.size();
    if (per_member) {
      result["cavity_mm3_" + names[m]] = st.cavity_mm3[m];
      result["drain_holes_" + names[m]] = int64_t(holes.size());
    }
    host.log(st.hollowing_notes[m].empty()
                 ? format("%s: %shollowed %s: a cavity of %.4g mm3, %zu drain holes", filter, where.c_str(),
                          names[m].c_str(), st.cavity_mm3[m], holes.size())
                 : format("%s: %s%s", filter, where.c_str(), st.hollowing_notes[m].c_str()));
    for (const DrainHole& h : holes)
      host.log(h.automatic
                   ? format("%s: %s%s: drain hole under its cavity at (%.2f, %.2f) mm, through layers 0-%zu", filter,
                            where.c_str(), names[m].c_str(), h.x_mm + 0.0, h.y_mm + 0.0, h.layer - 1)
                   : format("%s: %s%s: drain hole at (%.2f, %.2f, %.2f) mm along (%.2f, %.2f, %.2f), through layers "
                            "%zu-%zu",
                            filter, where.c_str(), names[m].c_str(), h.x_mm + 0.0, h.y_mm + 0.0, h.z_mm + 0.0,
                            h.axis[0] + 0.0, h.axis[1] + 0.0, h.axis[2] + 0.0, h.first, h.layer - 1));
  }
  host.log(format("%s: %shollowing %.3f s", filter, where.c_str(), st.hollowing_seconds));
  result["cavity_mm3"] = total + std::get<double>(result["cavity_mm3"]);
  result["drain_holes"] = int64_t(holes_total) + std::get<int64_t>(result["drain_holes"]);
}

}  // namespace slicereuse::plugin
