// The hollowing Make Print Job and Make Plate Job apply to their members, and what they report of
// it.
#include "filters_common.h"
#include "slicereuse/hollowing/cavity.h"

namespace slicereuse::plugin {

ParamList<JobHollowing> job_hollowing_params() {
  ParamList<JobHollowing> l;
  l.number(&JobHollowing::wall_mm, "hollow_wall_mm", "Hollow: wall thickness (mm)", 0, Range::at_least(0, "mm"),
           "Hollow every member, keeping walls at least this thick in mm (PrusaSlicer's hollowing_min_thickness; "
           "its profiles' 3 mm): the cavity is every point farther than this inside the part, in 3-D, computed "
           "on the layers' contours. 0 (the default): solid. The cavity is sealed until drain holes open it, so "
           "the printability check reports it as a resin trap.")
      .number(&JobHollowing::closing_mm, "hollow_closing_mm", "Hollow: closing distance (mm)",
              kPrusaHollowingClosingMm, Range::at_least(0, "mm"),
              "PrusaSlicer's hollowing_closing_distance: the cavity is made this much deeper, then grown back by "
              "it, which drops its parts narrower than twice this and rounds its edges. 0: the cavity follows the "
              "part's shape most closely.");
  return l;
}

void set_job_hollowing(const JobHollowing& h, PlateJobOptions& o) {
  o.hollowing.wall_mm = h.wall_mm;
  o.hollowing.closing_mm = h.closing_mm;
}

void report_hollowing(Host& host, const char* filter, const std::string& plate_label, const PlateJobStats& st,
                      const std::vector<std::string>& names, bool per_member, Result& result) {
  result.emplace("cavity_mm3", 0.0);
  if (st.hollowing_seconds == 0) return;  // solid
  const std::string where = plate_label.empty() ? "" : plate_label + ": ";
  double total = 0;
  for (size_t m = 0; m < st.cavity_mm3.size(); ++m) {
    total += st.cavity_mm3[m];
    if (per_member) result["cavity_mm3_" + names[m]] = st.cavity_mm3[m];
    host.log(st.hollowing_notes[m].empty()
                 ? format("%s: %shollowed %s: a cavity of %.4g mm3", filter, where.c_str(), names[m].c_str(),
                          st.cavity_mm3[m])
                 : format("%s: %s%s", filter, where.c_str(), st.hollowing_notes[m].c_str()));
  }
  host.log(format("%s: %shollowing %.3f s", filter, where.c_str(), st.hollowing_seconds));
  result["cavity_mm3"] = total + std::get<double>(result["cavity_mm3"]);
}

}  // namespace slicereuse::plugin
