// "Check Printability": UVtools' checks (islands, overhangs, resin traps, suction cups, parts
// touching the display's bounds) on the masks of a print file or PNG folder, or on those the
// current contour layer or mesh would print with.
// The findings are logged, counted in the result, written to an optional CSV and shown as a
// point layer (a point at each finding's centre on the build plate).
#include "filter_params.h"
#include "filters_common.h"
#include "slicereuse/plates/faded_layers.h"
#include "slicereuse/printability/printability_report.h"
#include "slicereuse/printfiles/check_print_file.h"
#include "slicereuse/printfiles/check_stack.h"
#include "slicereuse/slicing/slice_layers.h"

namespace slicereuse::plugin {
namespace {

constexpr size_t kLoggedFindings = 20;  // the rest are counted, the CSV has them all

struct PrintabilityParams {
  std::string print_file;
  double layer_thickness;
  PrinterSettings printer;
  std::string report_file;
};

ParamList<PrintabilityParams> printability_params() {
  ParamList<PrintabilityParams> l;
  l.file(&PrintabilityParams::print_file, ParamType::FileOpen, "print_file", "Print file", print_file_patterns().c_str(), nullptr,
         print_file_tooltip("The print file (or folder of PNG images) whose masks are checked. Empty: the masks "
                            "the current layer would print with, for the printer below: a contour layer's "
                            "contours, or the current mesh sliced directly from its lowest vertex.")
             .c_str())
      .number(&PrintabilityParams::layer_thickness, "layer_thickness", "Layer thickness (mm)", 0.05,
              Range::above(0, "mm"),
              "The print file's layer height (heights and volumes are counted in it), or the layer height the "
              "current mesh is sliced at. A contour layer has its own.")
      .include(&PrintabilityParams::printer, printer_params())
      .file(&PrintabilityParams::report_file, ParamType::FileSave, "report_file", "Report file (CSV)", "*.csv", nullptr,
            "Where to write one CSV row per finding (kind, layers, box in pixels, centre and size in mm, area or "
            "volume). Empty: no report is written.");
  return l;
}

// The masks of the current contour layer, or of the current mesh sliced directly, as a print job
// makes them (compensated against elephant foot), checked; the report written if asked.
PrintabilityReport check_current_layer(const PrintabilityParams& p, Host& host) {
  const PrinterProfile profile = p.printer.profile();
  const Progress progress = host.progress();
  std::vector<SlicePart> parts(1);
  try {
    parts[0].slices = host.current_contour_layer();
  } catch (const Error&) {  // not a contour layer: the current mesh
    parts[0].slices = slice_layers(host.current_mesh(), slice_options(p.layer_thickness, kLowestVertexZStart),
                                   sub_progress(progress, 0, 0.3));
  }
  const Slices& s = parts[0].slices;
  const size_t layers = s.layers();
  if (layers == 0) throw Error("print_file is empty and the current layer has no layers to check");
  const double thickness = s.thickness;
  compensate_faded_layers(parts, 0, {}, {layers}, profile, true);
  PrintabilityReport r = check_stack(parts, layers, thickness, profile, sub_progress(progress, 0.3, 1));
  if (!p.report_file.empty()) write_printability_csv(r, p.report_file);
  return r;
}

Result run_check_printability(const PrintabilityParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const MaskImageLayout layout = mask_image_layout(p.printer.profile());
  log_printer(host, "Check Printability", p.printer);

  const PrintabilityReport r = p.print_file.empty()
                                    ? check_current_layer(p, host)
                                    : check_print_file(p.print_file, layout.column_um / 1000.0, layout.row_um / 1000.0,
                                                       p.layer_thickness, p.report_file, host.progress());

  std::vector<double> xyz, normals;
  for (size_t i = 0; i < r.findings.size(); ++i) {
    const Finding& f = r.findings[i];
    double xy[2];
    plate_point_at_pixel(layout, 0.5 * (f.x0 + f.x1), 0.5 * (f.y0 + f.y1), xy);
    xyz.insert(xyz.end(), {xy[0], xy[1], f.center_mm[2]});
    normals.insert(normals.end(), {0.0, 0.0, 1.0});
    if (i >= kLoggedFindings) continue;
    const bool solid = f.kind == FindingKind::ResinTrap || f.kind == FindingKind::SuctionCup;
    host.log(format("Check Printability: %s, layers %zu-%zu, centre (%.2f, %.2f) mm in the image, %.2f x %.2f mm, "
                    "%.4g %s",
                    finding_kind_name(f.kind), f.first_layer, f.last_layer, f.center_mm[0], f.center_mm[1],
                    f.size_mm[0], f.size_mm[1], solid ? f.volume_mm3 : f.area_mm2, solid ? "mm3" : "mm2"));
  }
  if (r.findings.size() > kLoggedFindings)
    host.log(format("Check Printability: and %zu more", r.findings.size() - kLoggedFindings));
  if (!r.findings.empty()) host.add_point_layer("printability findings", xyz, normals);

  const double seconds = seconds_since(start);
  host.log(format("Check Printability: %zu layers, %zu islands, %zu overhangs, %zu resin traps (%.4g mm3), "
                  "%zu suction cups, %zu touching bounds, %.3f s",
                  r.layers, r.count(FindingKind::Island), r.count(FindingKind::Overhang),
                  r.count(FindingKind::ResinTrap), r.trapped_mm3(), r.count(FindingKind::SuctionCup),
                  r.count(FindingKind::TouchingBounds), seconds));
  return {{"islands", int64_t(r.count(FindingKind::Island))},
          {"overhangs", int64_t(r.count(FindingKind::Overhang))},
          {"resin_traps", int64_t(r.count(FindingKind::ResinTrap))},
          {"suction_cups", int64_t(r.count(FindingKind::SuctionCup))},
          {"touching_bounds", int64_t(r.count(FindingKind::TouchingBounds))},
          {"layers", int64_t(r.layers)},
          {"trapped_mm3", r.trapped_mm3()},
          {"seconds", seconds}};
}

}  // namespace

FilterSpec check_printability_filter() {
  const std::string description = std::string(
      "<p>Checks the masks of a print file (.sl1, .sl1s, .goo, .ctb, Anycubic files) or a folder of PNG "
      "images, or with no print file those the current layer would print with (a contour layer's contours, or "
      "the current mesh sliced directly at the layer thickness), as UVtools does, with its default settings: <b>islands</b> (a region of a layer resting on "
      "too few lit pixels of the layer below), <b>overhangs</b> (what a layer adds beyond the one below, "
      "eroded 40 pixels), <b>resin traps</b> (air enclosed on all sides), <b>suction cups</b> (air closed "
      "towards the plate and open only upwards, at least 100 pixels and 0.5 mm high) and parts "
      "<b>touching the display's bounds</b> (within 5 pixels of its edges). The printer's display gives "
      "the pixel size; the layer thickness the heights and volumes. Logs each finding (the first 20) with "
      "its layers and place, adds a layer of points at the findings' centres, and optionally writes one "
      "CSV row per finding. Make Print Job and Make Plate Job run the same checks on every file they "
      "write.</p>") +
      kReference;
  return typed_filter({FilterId::CheckPrintability, "Check Printability", "check_printability", description,
                       Arity::None, kLayerClass | kMeasureClass, false},
                      printability_params(), run_check_printability,
                      {"islands", "overhangs", "resin_traps", "suction_cups", "touching_bounds", "layers",
                       "trapped_mm3", "seconds"});
}

}  // namespace slicereuse::plugin
