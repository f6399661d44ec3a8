// The plate filters (issue #17). "Arrange on Plates": the loaded meshes arranged on build plates
// (or placed as a placements file says), the placements file and each plate's layout picture
// written, nothing sliced. "Make Plate Job": the same, then each plate's print file (or only one
// plate's: what family.py's per-plate tasks run) by reuse of a source's encoding or by direct
// slicing, its layout picture beside it. Both share load_members and arrange_members.
#include <algorithm>
#include <cmath>
#include <map>

#include "filter_params.h"
#include "filters_common.h"
#include "slicereuse/plates/arrange_plates.h"
#include "slicereuse/plates/placements_file.h"
#include "slicereuse/plates/plate_file_names.h"
#include "slicereuse/plates/plate_job.h"
#include "slicereuse/plates/plate_layout.h"
#include "slicereuse/util/error.h"

namespace slicereuse::plugin {
namespace {

struct PlateJobParams {
  bool visible_only;
  std::vector<std::string> member_files;
  JobLayers layers;
  JobSupports supports;
  JobChecks checks;
  JobLabels labels;
  JobHollowing hollowing;
  double spacing_mm;
  double rotation_step_deg;
  std::string placements_file;
  std::string placements_output;
  std::string output_path;
  int plate;
  PrinterSettings printer;
};

// The parameters both filters have, with the same names, labels and tooltips.
template <class P>
void add_members(ParamList<P>& l) {
  l.flag(&P::visible_only, "visible_only", "Visible meshes only", true,
         "The members are the loaded meshes with faces that are shown (the eye in the layer dialog); off: every "
         "loaded mesh with faces. pymeshlab and meshlabserver show every mesh they load.")
      .file_list(&P::member_files, "member_files", "Member files",
                 "Instead of the loaded meshes: the members' mesh files (STL, PLY or OBJ), separated by ';', read "
                 "straight into the job in parallel, without a layer each (a batch's way), each named by its file "
                 "name. Empty (the default): the loaded meshes.");
}

template <class P>
void add_arrangement(ParamList<P>& l) {
  const ArrangeOptions d;
  l.number(&P::spacing_mm, "spacing_mm", "Spacing (mm)", d.spacing_mm, Range::at_least(0, "mm"),
           "Distance kept between the members' footprints, and from the display's edges, in mm.")
      .number(&P::rotation_step_deg, "rotation_step_deg", "Rotation step (degrees)", d.rotation_step_deg,
              Range::between(1, 360, "degrees"), "Members are tried turned about z by multiples of this angle; 360: "
                                                 "never turned.")
      .file(&P::placements_file, ParamType::FileOpen, "placements_file", "Placements file", "*.json", nullptr,
            "A placements file (JSON, as the plate filters write it) that says which member goes on which plate "
            "and where, by the members' layer names, instead of arranging them. Empty (the default): arrange.");
}

template <class P>
void add_placements_output(ParamList<P>& l, const char* when_empty, const char* tooltip) {
  l.file(&P::placements_output, ParamType::FileSave, "placements_output", "Write placements to", "*.json", when_empty,
         tooltip);
}

// The number of the first plate a plate job makes: plate k alone, or 1.
size_t first_plate(const PlateJobParams& p) { return p.plate > 0 ? size_t(p.plate) : 1; }

ParamList<PlateJobParams> plate_job_params() {
  ParamList<PlateJobParams> l;
  add_members(l);
  l.include(&PlateJobParams::layers,
            job_layer_params("Encoding file written by Slice Mesh with Encoding for a member of the family: every "
                             "member's layers are transferred from it (exact). Empty: every member is sliced "
                             "directly."))
      .include(&PlateJobParams::supports, job_support_params())
      .include(&PlateJobParams::checks, job_check_params())
      .include(&PlateJobParams::labels, job_label_params())
      .include(&PlateJobParams::hollowing, job_hollowing_params());
  add_arrangement(l);
  add_placements_output(l, nullptr,
                        "Also write the plates' placements, members and area used here (JSON). Empty (the default): "
                        "not written.");
  add_print_file_output(l, &PlateJobParams::output_path,
                        "One print file per plate, numbered: plate.sl1 gives plate_1.sl1, plate_2.sl1, ...; a folder "
                        "name gives folders name_1, name_2, ... of PNG images. Each plate's layout picture is written beside it "
                        "(plate_1_layout.png).")
      .first_file([](const PlateJobParams& p) { return plate_file_name(p.output_path, first_plate(p)); });
  l.whole(&PlateJobParams::plate, "plate", "Only plate", 0, Range::at_least(0, ""),
          "0 (the default): every plate. 1, 2, ...: only that plate of the placements file, whose members are the "
          "loaded meshes, into its numbered print file (plate_2.sl1 for 2), as a job split over many machines "
          "makes each plate.");
  l.include(&PlateJobParams::printer, printer_params());
  return l;
}

// Layer names as members' names; a name loaded twice gets "#2", "#3", ... so each is unique.
std::vector<std::string> unique_names(const std::vector<Host::NamedMesh>& meshes) {
  std::map<std::string, int> seen;
  std::vector<std::string> names;
  for (const Host::NamedMesh& m : meshes) {
    const int n = ++seen[m.name];
    names.push_back(n == 1 ? m.name : m.name + "#" + std::to_string(n));
  }
  return names;
}

// The members and where they go: the member files, or the loaded meshes with faces (shown only, with visible_only),
// named by unique_names (load_members), arranged or placed as the placements file says (plate > 0:
// only that plate of it, whose members are the loaded meshes) (arrange_members).
struct PlatePlan {
  std::vector<Host::NamedMesh> loaded;
  std::vector<std::string> names;
  std::vector<const Mesh*> members;
  Platform platform;
  Arrangement arrangement;
  double arrange_seconds = 0;
  double read_seconds = 0;  // reading the member files
};

template <class P>
PlatePlan load_members(const P& p, const PrinterProfile& profile, Host& host) {
  PlatePlan plan;
  const auto start = std::chrono::steady_clock::now();
  plan.loaded = p.member_files.empty() ? host.meshes_with_faces(p.visible_only) : host.read_mesh_files(p.member_files);
  if (!p.member_files.empty()) plan.read_seconds = seconds_since(start);
  if (plan.loaded.empty())
    throw Error(p.visible_only ? "no shown mesh with faces: show (or load) the members to put on the plates"
                               : "no loaded mesh has faces: load the members to put on the plates");
  plan.names = unique_names(plan.loaded);
  for (const Host::NamedMesh& m : plan.loaded) plan.members.push_back(&m.mesh);
  plan.platform = printer_platform(profile);
  return plan;
}

// footprints: what each member takes on the plate (the member, or the member with its supports).
template <class P>
void arrange_members(PlatePlan& plan, const P& p, size_t plate, const std::vector<const Mesh*>& footprints,
                     const Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  ArrangeOptions ao;
  ao.spacing_mm = p.spacing_mm;
  ao.rotation_step_deg = p.rotation_step_deg;
  plan.arrangement = p.placements_file.empty()
                         ? arrange_plates(footprints, plan.names, plan.platform, ao, progress)
                         : arrangement_of(read_placements_file(p.placements_file), plan.names, plate);
  plan.arrange_seconds = seconds_since(start);
}

// A member and its supports as one mesh, whose footprint is their union's.
Mesh with_supports(const Mesh& member, const Mesh& supports) {
  Mesh both = member;
  const uint32_t first = uint32_t(member.vertices());
  both.V.insert(both.V.end(), supports.V.begin(), supports.V.end());
  for (uint32_t v : supports.F) both.F.push_back(first + v);
  return both;
}

// The members' supports (job_member_supports, on o's planes) and what each member takes on the
// plate: itself, or itself with its supports.
struct SupportedMembers {
  std::vector<MemberSupports> supports;
  std::vector<Mesh> with_supports;
  std::vector<const Mesh*> footprints;
};

SupportedMembers support_members(const PlatePlan& plan, const JobSupports& s, PlateJobOptions& o,
                                 const Progress& progress) {
  SupportedMembers out;
  out.supports = job_member_supports(plan.members, s, o, progress);
  for (size_t m = 0; m < out.supports.size(); ++m)
    out.with_supports.push_back(with_supports(*plan.members[m], out.supports[m].tree.mesh));
  out.footprints = plan.members;
  for (size_t m = 0; m < out.with_supports.size(); ++m) out.footprints[m] = &out.with_supports[m];
  return out;
}

// Plate k's members moved to their placements, and their names.
std::vector<Mesh> placed_members(const PlatePlan& plan, size_t k, std::vector<std::string>* names) {
  std::vector<Mesh> placed;
  for (size_t m : plan.arrangement.members[k]) {
    placed.push_back(place_mesh(*plan.members[m], plan.arrangement.placement[m]));
    names->push_back(plan.names[m]);
  }
  return placed;
}

Result run_plate_job(const PlateJobParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const PrinterProfile profile = p.printer.profile();
  log_printer(host, "Make Plate Job", p.printer);
  if (p.plate > 0 && p.placements_file.empty())
    throw Error(format("plate is %d: only a plate of a placements file can be made alone; give placements_file, "
                       "or plate 0 for every plate",
                       p.plate));
  if (p.plate > 0 && !p.placements_output.empty())
    throw Error(format("plate is %d: the placements are the placements file's already; leave placements_output "
                       "empty",
                       p.plate));
  const size_t first = first_plate(p);
  keep_buffers_for_the_next_job();
  const Progress progress = host.progress();
  PlatePlan plan = load_members(p, profile, host);
  const std::vector<std::string>& names = plan.names;
  const std::vector<const Mesh*>& members = plan.members;

  PlateJobOptions jo = plate_job_options(p.layers);
  set_job_checks(p.checks, jo);
  set_job_labels(p.labels, names, jo);  // every member's label checked before any plate is made
  set_job_hollowing(p.hollowing, host, *members[0], jo);
  jo.names = names;
  bool cached = false;
  std::shared_ptr<const CachedEncoding> entry;
  if (!p.layers.encoding_file.empty()) {
    entry = encoding_cache().get(p.layers.encoding_file, members, &cached, sub_progress(progress, 0, 0.05));
    jo.encoding = &entry->encoding;
    jo.edge_ends = &entry->edge_ends;
  }
  // Supports first: a member takes its supports' room on the plate.
  const SupportedMembers supported = support_members(plan, p.supports, jo, sub_progress(progress, 0.05, 0.1));
  const std::vector<MemberSupports>& supports = supported.supports;
  for (size_t m = 0; m < supports.size(); ++m)
    if (supports[m].kept_out > 0)
      host.log(format("Make Plate Job: %s: %zu support points dropped: their heads would reach into a drain hole",
                      names[m].c_str(), supports[m].kept_out));
  // The supports' cavities are of the members as loaded; the plates hold them moved and turned.
  jo.made_cavities.clear();
  arrange_members(plan, p, size_t(p.plate), supported.footprints, sub_progress(progress, 0.1, 0.15));
  const Arrangement& arrangement = plan.arrangement;
  const double arrange_seconds = plan.arrange_seconds;
  const size_t plates = arrangement.members.size();
  VertexOrder order;
  if (entry) {
    // Each member's transfer reads its vertices in this order, made once for all the plates: it
    // pays for itself over several plates, and costs about what it gains on one, so a call that
    // makes one plate (family.py's tasks) goes without it.
    if (plates > 1 && !entry->edge_ends.empty()) {
      order = vertex_order(entry->edge_ends);
      jo.vertex_order = &order;
    }
  }

  std::vector<std::string> outputs;
  PlateJobStats total;
  size_t layers = 0;
  Result result;
  size_t direct_members = 0;
  for (size_t k = 0; k < plates; ++k) {
    const auto plate_start = std::chrono::steady_clock::now();
    std::vector<std::string> plate_names;
    const std::vector<Mesh> placed = placed_members(plan, k, &plate_names);
    outputs.push_back(plate_file_name(p.output_path, first + k));
    const std::string layout = plate_layout_file_name(outputs.back());
    const double from = 0.15 + 0.85 * double(k) / double(plates), to = 0.15 + 0.85 * double(k + 1) / double(plates);
    jo.names = plate_names;
    set_job_labels(p.labels, plate_names, jo);
    jo.label_turns_deg.clear();  // a label on a side goes on the member's own side, however turned
    for (size_t m : arrangement.members[k]) jo.label_turns_deg.push_back(arrangement.placement[m].theta_deg);
    std::vector<Mesh> placed_supports;
    for (size_t m : supports.empty() ? std::vector<size_t>() : arrangement.members[k])
      placed_supports.push_back(place_mesh(supports[m].tree.mesh, arrangement.placement[m]));
    jo.supports.clear();
    for (const Mesh& s : placed_supports) jo.supports.push_back(&s);
    const PlateJobStats st = export_plate(placed, jo, profile, outputs.back(), sub_progress(progress, from, to));
    // The picture names each member by its label when it has one.
    write_plate_layout(layout, placed, jo.labels.empty() ? plate_names : jo.labels, plan.platform);
    result[format("output_%zu", first + k)] = outputs.back();
    result[format("layout_%zu", first + k)] = layout;
    for (size_t m = 0; m < placed.size(); ++m) {
      if (st.direct_reasons[m].empty()) continue;
      ++direct_members;
      result["direct_reason_" + plate_names[m]] = st.direct_reasons[m];
      result["sliced_directly_" + plate_names[m]] = int64_t(1);
      host.log(format("Make Plate Job: plate %zu: %s sliced directly, not by reuse: %s", first + k,
                      plate_names[m].c_str(), st.direct_reasons[m].c_str()));
    }
    layers = std::max(layers, st.layers);
    total.points += st.points;
    total.transferred_layers += st.transferred_layers;
    total.resliced_layers += st.resliced_layers;
    total.slicing_seconds += st.slicing_seconds;
    host.log(format("Make Plate Job: plate %zu: %zu members, %.1f %% of the platform, %zu layers, to %s, %.3f s", first + k,
                    placed.size(), 100 * arrangement.area_used[k], st.layers, outputs.back().c_str(),
                    seconds_since(plate_start)));
    log_display_warning(host, "Make Plate Job", st.masks, profile);
    report_printability(host, "Make Plate Job", format("plate %zu", first + k), st, plate_names, true, result);
    report_labels(host, "Make Plate Job", jo, st, plate_names, true, result);
    report_hollowing(host, "Make Plate Job", format("plate %zu", first + k), st, plate_names, true, result);
  }
  if (!p.placements_output.empty())
    write_placements_file(p.placements_output,
                          placements_of(arrangement, names, p.spacing_mm, plan.platform, outputs));

  const double seconds = seconds_since(start);
  host.log(format("Make Plate Job: %zu members on %zu plates (%s %.3f s), %zu points, %zu member layers transferred, "
                  "%zu sliced, %zu members sliced directly for want of reuse, %.3f s",
                  members.size(), plates, p.placements_file.empty() ? "arranged in" : "placed by the file in",
                  arrange_seconds, total.points, total.transferred_layers, total.resliced_layers, direct_members,
                  seconds));
  result.insert({{"plates", int64_t(plates)},
                 {"members", int64_t(members.size())},
                 {"layers", int64_t(layers)},
                 {"points", int64_t(total.points)},
                 {"transferred_layers", int64_t(total.transferred_layers)},
                 {"resliced_layers", int64_t(total.resliced_layers)},
                 {"direct_members", int64_t(direct_members)},
                 {"encoding_cached", int64_t(cached)},
                 {"arrange_seconds", arrange_seconds},
                 {"read_seconds", plan.read_seconds},
                 {"slicing_seconds", total.slicing_seconds},
                 {"seconds", seconds}});
  for (size_t k = 0; k < plates; ++k) result[format("area_used_%zu", first + k)] = arrangement.area_used[k];
  double seconds_of_supports = 0;
  for (size_t m = 0; m < supports.size(); ++m) {
    add_support_figures(supports[m], "_" + names[m], result);
    seconds_of_supports += support_seconds(supports[m]);
  }
  result["support_seconds"] = seconds_of_supports;
  return result;
}

struct ArrangeParams {
  bool visible_only;
  std::vector<std::string> member_files;
  double layer_thickness;
  double z_start;
  JobSupports supports;
  double spacing_mm;
  double rotation_step_deg;
  std::string placements_file;
  std::string placements_output;
  std::string output_path;
  PrinterSettings printer;
};

ParamList<ArrangeParams> arrange_params() {
  ParamList<ArrangeParams> l;
  add_members(l);
  l.number(&ArrangeParams::layer_thickness, "layer_thickness", "Layer thickness (mm)", 0.1, Range::above(0, "mm"),
           "With supports: the layers the plate job will slice, which the supports are built for, in mm.")
      .number(&ArrangeParams::z_start, "z_start", "Start height (mm)", kLowestVertexZStart, Range::any(),
              "With supports: the plate job's first layer's bottom, in mm (the source's lowest vertex when it "
              "transfers an encoding); at or below -1e29 (the default): the lowest vertex of all members.")
      .include(&ArrangeParams::supports, job_support_params());
  add_arrangement(l);
  add_placements_output(l, "choose the placements file to write (.json)",
                        "The plates' placements, members and area used (JSON), for Make Plate Job's placements_file.");
  add_print_file_output(l, &ArrangeParams::output_path,
                        "The print files the placements name, one per plate (plate.sl1 gives plate_1.sl1, "
                        "plate_2.sl1, ...; a folder name gives name_1, name_2, ...); nothing is written there but "
                        "each plate's layout picture beside it (plate_1_layout.png).")
      .first_file([](const ArrangeParams& p) { return plate_layout_file_name(plate_file_name(p.output_path, 1)); });
  l.include(&ArrangeParams::printer, printer_params());
  return l;
}

Result run_arrange(const ArrangeParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const PrinterProfile profile = p.printer.profile();
  log_printer(host, "Arrange on Plates", p.printer);
  PlatePlan plan = load_members(p, profile, host);
  const Progress progress = host.progress();
  PlateJobOptions o;
  o.slicing = slice_options(p.layer_thickness, p.z_start);
  o.names = plan.names;
  const SupportedMembers supported = support_members(plan, p.supports, o, sub_progress(progress, 0, 0.5));
  arrange_members(plan, p, 0, supported.footprints, sub_progress(progress, 0.5, 1));
  const size_t plates = plan.arrangement.members.size();
  std::vector<std::string> outputs;
  for (size_t k = 0; k < plates; ++k) {
    std::vector<std::string> plate_names;
    const std::vector<Mesh> placed = placed_members(plan, k, &plate_names);
    outputs.push_back(plate_file_name(p.output_path, k + 1));
    write_plate_layout(plate_layout_file_name(outputs.back()), placed, plate_names, plan.platform);
    host.log(format("Arrange on Plates: plate %zu: %zu members, %.1f %% of the platform, layout in %s", k + 1,
                    placed.size(), 100 * plan.arrangement.area_used[k],
                    plate_layout_file_name(outputs.back()).c_str()));
  }
  write_placements_file(p.placements_output,
                        placements_of(plan.arrangement, plan.names, p.spacing_mm, plan.platform, outputs));
  host.log(format("Arrange on Plates: %zu members on %zu plates (%s %.3f s), placements in %s", plan.members.size(),
                  plates, p.placements_file.empty() ? "arranged in" : "placed by the file in", plan.arrange_seconds,
                  p.placements_output.c_str()));
  double z_min = INFINITY;
  for (const Mesh* m : plan.members) z_min = std::min(z_min, z_range(*m).min);
  Result result = {{"plates", int64_t(plates)},
                   {"members", int64_t(plan.members.size())},
                   {"z_min", z_min},
                   {"arrange_seconds", plan.arrange_seconds},
                   {"read_seconds", plan.read_seconds},
                   {"seconds", seconds_since(start)}};
  for (size_t k = 0; k < plates; ++k) result[format("area_used_%zu", k + 1)] = plan.arrangement.area_used[k];
  return result;
}

}  // namespace

FilterSpec arrange_plates_filter() {
  const std::string description = std::string(
      "<p>Arranges many members of a family on build plates, as <i>Make Plate Job</i> does, without slicing: "
      "the members (the shown meshes with faces, or every loaded one) are placed on the printer's display "
      "without overlap, each member's footprint kept <i>spacing</i> from the others and from the display's "
      "edges, turned about z where that packs more; members that do not fit go to the next plate.</p>"
      "<p>Writes the placements file, to look at or edit and to give to <i>Make Plate Job</i> (every plate, "
      "or one plate per run on many machines), and a top-view picture of each plate with each member's "
      "outline and name beside the print file it names (<i>_layout.png</i>).</p>"
      "<p>With <i>supports</i>, each member's footprint includes its supports, made as <i>Make Plate Job</i> "
      "makes them with the same parameters, so that the plate job placing the members by this file keeps "
      "their supports apart too.</p>") +
      kReference;
  return typed_filter({FilterId::ArrangePlates, "Arrange on Plates", "arrange_on_plates", description, Arity::None,
                       kLayerClass, false},
                      arrange_params(), run_arrange,
                      {"plates", "members", "z_min", "arrange_seconds", "read_seconds", "seconds", "area_used_*"});
}

FilterSpec plate_job_filter() {
  const std::string description = std::string(
      "<p>Puts many members of a family on build plates and makes one print file per plate, as a lab "
      "prints them: the members (the shown meshes with faces, or every loaded one) are arranged on the "
      "printer's display without overlap, each member's footprint (the outline of its projection, not a "
      "bounding box) kept <i>spacing</i> from the others and from the display's edges, turned about z where "
      "that packs more; members that do not fit go to the next plate. A placements file can say where "
      "they go instead.</p>"
      "<p>Each plate's layer is the union of its members' layers at that height, each member transferred "
      "from the source's encoding onto its placed vertices (exact, as <i>Make Print Job</i>) or sliced "
      "directly; members of different heights simply end. Next to each print file, a top-view picture of "
      "the plate with each member's outline and name (<i>_layout.png</i>).</p>"
      "<p>With <i>supports</i>, each member gets its supports (points generated on it, or a source's "
      "transferred from a support-points file) before the arrangement, which keeps their footprint "
      "apart too; they are sliced with the members, on the layers below them.</p>"
      "<p>Each plate's masks are checked as they are written, as UVtools checks a print file (see <i>Check "
      "Printability</i>), the findings counted per member; with <i>require printable</i>, a plate holding an "
      "island, a resin trap or a suction cup is refused and not written.</p>"
      "<p>With <i>labels</i>, each member's name (or its row of a labels file: a case ID) is cut into its base, "
      "mirrored to read from below (or upright into the <i>label side</i>, the member's own however the plate "
      "turns it), as large as fits up to the label height; the layout picture names each "
      "member by its label. A label that fits nowhere fails the job, naming the member, unless <i>allow "
      "unlabelled</i>.</p>") +
      kReference;
  return typed_filter({FilterId::MakePlateJob, "Make Plate Job", "make_plate_job", description, Arity::None,
                       kLayerClass, false},
                      plate_job_params(), run_plate_job,
                      with_printability_keys(
                          {"plates", "members", "layers", "points", "transferred_layers", "resliced_layers",
                           "direct_members", "encoding_cached", "arrange_seconds", "read_seconds", "slicing_seconds",
                           "seconds", "support_seconds", "area_used_*", "output_*", "layout_*", "direct_reason_*",
                           "sliced_directly_*", "support_points_*", "kept_*", "moved_*", "added_*", "dropped_*",
                           "label_height_mm_*", "cavity_mm3", "cavity_mm3_*", "drain_holes", "drain_holes_*"},
                          true));
}

}  // namespace slicereuse::plugin
