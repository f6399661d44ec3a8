// "Make Plate Job": many members on build plates, one print file per plate (issue #17): the
// loaded meshes arranged (or placed as a placements file says), then each plate's masks by
// reuse of a source's encoding or by direct slicing, its layout picture beside it.
#include <map>

#include "filter_params.h"
#include "filters_common.h"
#include "slicereuse/plates/arrange_plates.h"
#include "slicereuse/plates/placements_file.h"
#include "slicereuse/plates/plate_file_names.h"
#include "slicereuse/plates/plate_job.h"
#include "slicereuse/plates/plate_layout.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/memory_budget.h"

namespace slicereuse::plugin {
namespace {

struct PlateJobParams {
  bool visible_only;
  std::string encoding_file;
  double layer_thickness;
  double z_start;
  double spacing_mm;
  double rotation_step_deg;
  std::string placements_file;
  std::string placements_output;
  std::string output_path;
  PrinterSettings printer;
};

ParamList<PlateJobParams> plate_job_params() {
  const ArrangeOptions d;
  ParamList<PlateJobParams> l;
  l.flag(&PlateJobParams::visible_only, "visible_only", "Visible meshes only", true,
         "The members are the loaded meshes with faces that are shown (the eye in the layer dialog); off: every "
         "loaded mesh with faces. pymeshlab and meshlabserver show every mesh they load.")
      .file(&PlateJobParams::encoding_file, ParamType::FileOpen, "encoding_file", "Source encoding file", "*.enc *.srb",
            nullptr,
            "Encoding file written by Slice Mesh with Encoding for a member of the family: every member's layers are "
            "transferred from it (exact). Empty: every member is sliced directly.")
      .number(&PlateJobParams::layer_thickness, "layer_thickness", "Layer thickness (mm)", 0.1, Range::above(0, "mm"),
              "Used when slicing directly (no encoding file): distance between slicing planes, in mm. With an "
              "encoding file, the encoding's layers are used.")
      .number(&PlateJobParams::z_start, "z_start", "Start height (mm)", kLowestVertexZStart, Range::any(),
              "Used when slicing directly: bottom of the first layer, in mm; at or below -1e29 (the default): the "
              "lowest vertex of all members.")
      .number(&PlateJobParams::spacing_mm, "spacing_mm", "Spacing (mm)", d.spacing_mm, Range::at_least(0, "mm"),
              "Distance kept between the members' footprints, and from the display's edges, in mm.")
      .number(&PlateJobParams::rotation_step_deg, "rotation_step_deg", "Rotation step (degrees)", d.rotation_step_deg,
              Range::between(1, 360, "degrees"),
              "Members are tried turned about z by multiples of this angle; 360: never turned.")
      .file(&PlateJobParams::placements_file, ParamType::FileOpen, "placements_file", "Placements file", "*.json",
            nullptr,
            "A placements file (JSON, as this filter writes it) that says which member goes on which plate and "
            "where, by the members' layer names, instead of arranging them. Empty (the default): arrange.")
      .file(&PlateJobParams::placements_output, ParamType::FileSave, "placements_output", "Write placements to",
            "*.json", nullptr,
            "Also write the plates' placements, members and area used here (JSON). Empty (the default): not "
            "written.")
      .file(&PlateJobParams::output_path, ParamType::FileSave, "output_path", "Output .sl1, .sl1s, .goo or folder",
            "*.sl1 *.sl1s *.goo", kMaskOutputWhenEmpty,
            "One print file per plate, numbered: plate.sl1 gives plate_1.sl1, plate_2.sl1, ... (.sl1 or .sl1s: "
            "Prusa archives, .goo: Elegoo print files); a folder name gives folders name_1, name_2, ... of PNG "
            "images. Each plate's layout picture is written beside it (plate_1_layout.png).")
      .include(&PlateJobParams::printer, printer_params());
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

Result run_plate_job(const PlateJobParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const PrinterProfile profile = p.printer.profile();
  log_printer(host, "Make Plate Job", p.printer);
  check_outputs({{"placements_output", p.placements_output}, {"output_path", plate_file_name(p.output_path, 1)}});
  const Progress progress = host.progress();

  const std::vector<Host::NamedMesh> loaded = host.meshes_with_faces(p.visible_only);
  if (loaded.empty())
    throw Error(p.visible_only ? "no shown mesh with faces: show (or load) the members to put on the plates"
                               : "no loaded mesh has faces: load the members to put on the plates");
  const std::vector<std::string> names = unique_names(loaded);
  std::vector<const Mesh*> members;
  for (const Host::NamedMesh& m : loaded) members.push_back(&m.mesh);

  const Platform platform = printer_platform(profile);
  const auto arrange_start = std::chrono::steady_clock::now();
  ArrangeOptions ao;
  ao.spacing_mm = p.spacing_mm;
  ao.rotation_step_deg = p.rotation_step_deg;
  const Arrangement arrangement = p.placements_file.empty()
                                      ? arrange_plates(members, names, platform, ao, sub_progress(progress, 0, 0.1))
                                      : arrangement_of(read_placements_file(p.placements_file), names);
  const double arrange_seconds = seconds_since(arrange_start);

  PlateJobOptions jo;
  jo.slicing = slice_options(p.layer_thickness, p.z_start);
  jo.slicing.encoding = false;
  jo.range_budget_bytes = available_memory() / 4;
  bool cached = false;
  std::shared_ptr<const CachedEncoding> entry;
  if (!p.encoding_file.empty()) {
    entry = encoding_cache().get(p.encoding_file, *members[0], &cached, sub_progress(progress, 0.1, 0.15));
    jo.encoding = &entry->encoding;
    jo.edge_ends = &entry->edge_ends;
  }

  const size_t plates = arrangement.members.size();
  std::vector<std::string> outputs;
  PlateJobStats total;
  size_t layers = 0;
  for (size_t k = 0; k < plates; ++k) {
    const auto plate_start = std::chrono::steady_clock::now();
    std::vector<Mesh> placed;
    std::vector<std::string> plate_names;
    for (size_t m : arrangement.members[k]) {
      placed.push_back(place_mesh(*members[m], arrangement.placement[m]));
      plate_names.push_back(names[m]);
    }
    outputs.push_back(plate_file_name(p.output_path, k + 1));
    const double from = 0.15 + 0.85 * double(k) / double(plates), to = 0.15 + 0.85 * double(k + 1) / double(plates);
    const PlateJobStats st = export_plate(placed, jo, profile, outputs.back(), sub_progress(progress, from, to));
    write_plate_layout(plate_layout_file_name(outputs.back()), placed, plate_names, platform);
    layers = std::max(layers, st.layers);
    total.points += st.points;
    total.transferred_layers += st.transferred_layers;
    total.resliced_layers += st.resliced_layers;
    total.slicing_seconds += st.slicing_seconds;
    total.ranges += st.ranges - 1;
    host.log(format("Make Plate Job: plate %zu: %zu members, %.1f %% of the platform, %zu layers, to %s, %.3f s", k + 1,
                    placed.size(), 100 * arrangement.area_used[k], st.layers, outputs.back().c_str(),
                    seconds_since(plate_start)));
    log_display_warning(host, "Make Plate Job", st.masks, profile);
  }
  if (!p.placements_output.empty())
    write_placements_file(p.placements_output, placements_of(arrangement, names, p.spacing_mm, platform, outputs));

  const double seconds = seconds_since(start);
  host.log(format("Make Plate Job: %zu members on %zu plates (%s %.3f s), %zu points, %zu member layers transferred, "
                  "%zu sliced, %.3f s",
                  members.size(), plates, p.placements_file.empty() ? "arranged in" : "placed by the file in",
                  arrange_seconds, total.points, total.transferred_layers, total.resliced_layers, seconds));
  Result result = {{"plates", int64_t(plates)},
                   {"members", int64_t(members.size())},
                   {"layers", int64_t(layers)},
                   {"points", int64_t(total.points)},
                   {"transferred_layers", int64_t(total.transferred_layers)},
                   {"resliced_layers", int64_t(total.resliced_layers)},
                   {"encoding_cached", int64_t(cached)},
                   {"arrange_seconds", arrange_seconds},
                   {"slicing_seconds", total.slicing_seconds},
                   {"seconds", seconds}};
  for (size_t k = 0; k < plates; ++k) result[format("area_used_%zu", k + 1)] = arrangement.area_used[k];
  return result;
}

}  // namespace

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
      "the plate with each member's outline and name (<i>_layout.png</i>).</p>") +
      kReference;
  return typed_filter({FilterId::MakePlateJob, "Make Plate Job", "make_plate_job", description, Arity::None,
                       kLayerClass, false},
                      plate_job_params(), run_plate_job);
}

}  // namespace slicereuse::plugin
