// The labels Make Print Job and Make Plate Job engrave into their members' bases, and what they
// report of them.
#include <filesystem>

#include "filters_common.h"
#include "slicereuse/formats/labels_file.h"
#include "slicereuse/plates/side_label.h"
#include "slicereuse/regions/label_region.h"

namespace slicereuse::plugin {

std::vector<std::string> label_side_names() { return {"base", "front", "back", "left", "right"}; }

const char* const kLabelSideTooltip =
    "Where the label goes: the base (mirrored, to read from below), or a side seen from above, upright and "
    "readable from outside: front (-y), back (+y), left (-x) or right (+x), the member's own before the plate "
    "turns it. On a side, the label is centred along it, as near its middle height as a face is flat there (every "
    "point within half the depth of a plane) and solid behind the letters.";

ParamList<JobLabels> job_label_params() {
  const LabelOptions d;
  ParamList<JobLabels> l;
  l.flag(&JobLabels::labels, "labels", "Engrave labels", false,
         "Engrave each member's label into its base (mirrored to read from below) or a side: its name (the file or layer name "
         "without its extension), or its label in the labels file. Letters, digits, '-', '_', '.', '/', '+', '#'.")
      .file(&JobLabels::labels_file, ParamType::FileOpen, "labels_file", "Labels file", "*.csv", nullptr,
            "A CSV of two columns, member (file name or stem) and label, one row per member (an optional header "
            "row 'member,label'). Implies Engrave labels. Empty (the default): the members' names.")
      .number(&JobLabels::height_mm, "label_height_mm", "Label height (mm)", d.height_mm,
              Range::above(0, "mm"),
              "Height of the letters; where they do not fit, a tenth less at a time, down to a third of this, "
              "turned if need be.")
      .number(&JobLabels::depth_mm, "label_depth_mm", "Label depth (mm)", d.depth_mm, Range::above(0, "mm"),
              "How deep the letters are cut into the base or side.")
      .choice(&JobLabels::side, "label_side", "Label side", label_side_names(), d.side, kLabelSideTooltip)
      .flag(&JobLabels::allow_unlabelled, "allow_unlabelled", "Allow unlabelled", false,
            "Print a member whose label fits nowhere on its base (or side) without it; off: the job fails naming it.");
  return l;
}

void set_job_labels(const JobLabels& l, const std::vector<std::string>& names, PlateJobOptions& o) {
  if (!l.labels && l.labels_file.empty()) return;
  o.label.height_mm = l.height_mm;
  o.label.min_height_mm = l.height_mm / 3;
  o.label.depth_mm = l.depth_mm;
  o.label.side = l.side;
  o.allow_unlabelled = l.allow_unlabelled;
  o.labels.clear();
  if (l.labels_file.empty()) {
    for (const std::string& name : names) o.labels.push_back(std::filesystem::path(name).stem().string());
  } else {
    const LabelsFile file = read_labels_file(l.labels_file);
    for (const std::string& name : names) o.labels.push_back(label_of(file, name));
  }
  for (const std::string& text : o.labels) label_box_mm(text, o.label.height_mm);  // the font prints it
}

void report_labels(Host& host, const char* filter, const PlateJobOptions& o, const PlateJobStats& st,
                   const std::vector<std::string>& names, bool per_member, Result& result) {
  if (o.labels.empty()) {
    if (!per_member) result["label_height_mm"] = -1.0;  // not labelled
    return;
  }
  for (size_t m = 0; m < names.size() && m < st.label_heights_mm.size(); ++m) {
    const double h = st.label_heights_mm[m];
    result[per_member ? "label_height_mm_" + names[m] : "label_height_mm"] = h;
    const std::array<double, 3>& at = st.label_places[m];
    if (h > 0 && o.label.side == LabelSide::Base)
      host.log(format("%s: %s labelled '%s', %.3g mm high, at (%.2f, %.2f) mm, turned %.0f degrees", filter,
                      names[m].c_str(), o.labels[m].c_str(), h, at[0] + 0.0, at[1] + 0.0, at[2] + 0.0));
    else if (h > 0)
      host.log(format("%s: %s labelled '%s' on its %s side, %.3g mm high, centred at (%.2f, %.2f, %.2f) mm", filter,
                      names[m].c_str(), o.labels[m].c_str(), side_name(o.label.side), h, at[0] + 0.0, at[1] + 0.0,
                      at[2] + 0.0));
    else
      host.log(format("%s: %s printed without its label '%s': it fits nowhere on its %s", filter, names[m].c_str(),
                      o.labels[m].c_str(),
                      o.label.side == LabelSide::Base ? "base" : format("%s side", side_name(o.label.side)).c_str()));
  }
}

}  // namespace slicereuse::plugin
