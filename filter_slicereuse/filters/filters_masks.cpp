// "Export Mask Images": a contour file (or the current contour layer) to a folder of PNG masks,
// an .sl1 archive or an Elegoo .goo file; no mesh involved.
#include "filter_params.h"
#include "filters_common.h"
#include "slicereuse/formats/slice_files.h"
#include "slicereuse/plates/faded_layers.h"
#include "slicereuse/printfiles/export_masks.h"
#include "slicereuse/util/error.h"

namespace slicereuse::plugin {
namespace {

struct ExportParams {
  std::string contour_file;
  std::string output_path;
  PrinterSettings printer;
};

ParamList<ExportParams> export_params() {
  ParamList<ExportParams> l;
  l.file(&ExportParams::contour_file, ParamType::FileOpen, "contour_file", "Contour file", "*.ctr *.srb", nullptr,
         "Contour file written by Slice Mesh with Encoding or Transfer Slicing to Mesh. Empty: the current layer, a "
         "contour file opened with File > Import Mesh (.ctr, .srb, .cli).");
  add_print_file_output(l, &ExportParams::output_path,
                        "A folder for PNG images (created if missing; its parent must exist), or a print file.")
      .include(&ExportParams::printer, printer_params());
  return l;
}

Result run_export_masks(const ExportParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const PrinterProfile profile = p.printer.profile();
  log_printer(host, "Export Mask Images", p.printer);

  const Progress progress = host.progress();
  // No file: the current layer, opened from a contour file through io_encoding.
  Slices s;
  if (!p.contour_file.empty()) {
    s = read_contour_file(p.contour_file, sub_progress(progress, 0, 0.1));
  } else {
    try {
      s = host.current_contour_layer();
    } catch (const Error& e) {
      throw Error(std::string("contour_file is empty and ") + e.what());
    }
  }
  // With elephant-foot compensation, the stack as one range whose faded layers are compensated,
  // the stack being one object (as every print job's members are, plate_job.h).
  const MaskExportStats stats =
      profile.elephant_foot_mm > 0 && s.layers() > 0
          ? export_masks(SliceChunks{{0, s.layers()}, s.thickness,
                                     [&](size_t, const Progress&) {
                                       std::vector<SlicePart> parts(1);
                                       parts[0].slices = std::move(s);
                                       compensate_faded_layers(parts, 0, {}, {parts[0].slices.layers()}, profile,
                                                               true);
                                       return parts;
                                     }},
                         profile, p.output_path, sub_progress(progress, 0.1, 1))
          : export_masks(s, profile, p.output_path, sub_progress(progress, 0.1, 1));

  const double seconds = seconds_since(start);
  host.log(format("Export Mask Images: %zu layers of %dx%d pixels to %s, %zu open contours ignored, %.3f s",
                  stats.layers, profile.width_px, profile.height_px, p.output_path.c_str(),
                  stats.ignored_open_contours, seconds));
  log_display_warning(host, "Export Mask Images", stats, profile);
  Result result = {{"layers", int64_t(stats.layers)}, {"seconds", seconds}};
  add_display_figures(stats, result);
  return result;
}

}  // namespace

FilterSpec export_masks_filter() {
  const std::string description = std::string(
      "<p>Rasterizes the layers of a contour file into one mask image per layer "
      "for mask-projection (DLP/LCD) printers: a folder of PNG images "
      "(NNNNN.png), or the print file the output path's extension names: a Prusa .sl1/.sl1s archive, an "
      "Elegoo .goo, a Chitubox .ctb, an Anycubic Photon Workshop file (.pwmx, .pwma, .pwmb, .pm4n, .pm5, .pm5s).</p>"
      "<p>Choose the printer by name (its display, orientation, mirrors and exposure as its "
      "own slicer writes them), or custom and give them. A binary pixel is lit when its centre lies "
      "inside the layer by the nonzero winding rule of the closed contours; with anti-aliasing a pixel's grey "
      "level is the exact area the part covers of it (PrusaSlicer's gamma). Open contours are ignored and counted. "
      "The model's XY origin sits at the display centre, shifted by the offsets. Pixel sizes are in micrometres, "
      "offsets in mm. With an empty contour file the contours come from the current "
      "layer, a contour file opened in MeshLab (.ctr, .srb or .cli).</p>") +
      kReference;
  return typed_filter({FilterId::ExportMasks, "Export Mask Images", "export_mask_images", description,
                       Arity::None, kLayerClass, false},
                      export_params(), run_export_masks, with_display_keys({"layers", "seconds"}));
}

}  // namespace slicereuse::plugin
