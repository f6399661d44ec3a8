// "Make Print Job": the current mesh's layers (transferred from a cached encoding, or sliced
// directly) and its masks in one filter, in memory; a contour file only when asked for.
#include "filter_params.h"
#include "filters_common.h"
#include "slicereuse/slicing/layer_chunks.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/memory_budget.h"

namespace slicereuse::plugin {
namespace {

struct PrintJobParams {
  std::string encoding_file;
  double layer_thickness;
  double z_start;
  std::string contour_file;
  std::string output_path;
  PrinterSettings printer;
};

ParamList<PrintJobParams> print_job_params() {
  ParamList<PrintJobParams> l;
  l.file(&PrintJobParams::encoding_file, ParamType::FileOpen, "encoding_file", "Source encoding file", "*.enc *.srb",
         nullptr,
         "Encoding file written by Slice Mesh with Encoding for a member of the family; the current mesh must have "
         "its faces. Empty: slice the current mesh directly.")
      .number(&PrintJobParams::layer_thickness, "layer_thickness", "Layer thickness (mm)", 0.1, Range::above(0, "mm"),
              "Used when slicing directly (no encoding file): distance between slicing planes, in mm. With an "
              "encoding file, the encoding's layers are used.")
      .number(&PrintJobParams::z_start, "z_start", "Start height (mm)", kLowestVertexZStart, Range::any(),
              "Used when slicing directly: bottom of the first layer, in mm; at or below -1e29 (the default): the "
              "lowest vertex of the mesh.")
      .file(&PrintJobParams::contour_file, ParamType::FileSave, "contour_file", "Contour file", "*.ctr *.srb", nullptr,
            "Also write the layers' contour points here (text .ctr unless the name ends in .srb). Empty (the "
            "default): no contour file.")
      .file(&PrintJobParams::output_path, ParamType::FileSave, "output_path", "Output .sl1, .sl1s, .goo or folder",
            "*.sl1 *.sl1s *.goo",
            kMaskOutputWhenEmpty,
            "A file name ending in .sl1 or .sl1s for a Prusa SL1/SL1S archive, or in .goo for an Elegoo print file "
            "(landscape displays), or a folder for PNG images (created if missing; its parent must exist).")
      .include(&PrintJobParams::printer, printer_params());
  return l;
}

Result run_print_job(const PrintJobParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const PrinterProfile profile = p.printer.profile();
  log_printer(host, "Make Print Job", p.printer);
  const bool direct = p.encoding_file.empty();
  check_outputs({{"contour_file", p.contour_file}, {"output_path", p.output_path}});

  keep_buffers_for_the_next_job();
  const Mesh mesh = host.current_mesh();
  const Progress progress = host.progress();
  TransferStats stats;
  bool cached = false;
  size_t layers = 0, points = 0, ranges = 1;
  MaskExportStats masks;
  double slicing_seconds = 0, masks_seconds = 0;
  SliceOptions options = slice_options(p.layer_thickness, p.z_start);
  options.encoding = false;
  double z_start = 0;
  const std::vector<double> planes = direct ? slicing_planes(mesh, options, &z_start) : std::vector<double>{};
  // A stack of contours that would take more than a quarter of the memory this process may still
  // use is sliced and turned into masks a range of layers at a time, each range freed before the
  // next is sliced (a contour file needs the whole stack: then it is sliced whole, or refused
  // with the figures). Memory kept for reuse (the cached encoding, kept buffers) is given back
  // before settling for ranges.
  const auto ranges_of_layers = [&] { return layer_chunks(mesh, planes, available_memory() / 4, 3 * sizeof(double)); };
  std::vector<size_t> first{0, planes.size()};
  if (direct && p.contour_file.empty()) {
    first = ranges_of_layers();
    if (first.size() > 2 && reclaim_memory() > 0) first = ranges_of_layers();
  }
  if (first.size() > 2) {
    ranges = first.size() - 1;
    SliceChunks chunks{first, options.thickness, [&](size_t i, const Progress& range_progress) {
                         const auto t = std::chrono::steady_clock::now();
                         Slices s = slice_planes(mesh, {planes.begin() + long(first[i]), planes.begin() + long(first[i + 1])},
                                                 range_progress, false);
                         s.thickness = options.thickness;
                         s.z_start = z_start + double(first[i]) * options.thickness;
                         points += s.points();
                         slicing_seconds += seconds_since(t);
                         std::vector<SlicePart> parts;
                         parts.push_back({std::move(s), 0});
                         return parts;
                       }};
    masks = export_masks(chunks, profile, p.output_path, progress);
    masks_seconds = masks.seconds - slicing_seconds;
    layers = stats.resliced_layers = planes.size();
  } else {
    Slices s;
    const auto slicing_start = std::chrono::steady_clock::now();
    if (direct) {
      s = slice_layers(mesh, options, sub_progress(progress, 0, 0.3));
      stats.resliced_layers = s.layers();
    } else {
      const auto entry = encoding_cache().get(p.encoding_file, mesh, &cached, sub_progress(progress, 0, 0.2));
      s = transfer_contours(entry->encoding, entry->edge_ends, mesh, TransferOptions(TransferMode::Exact, false),
                            &stats, sub_progress(progress, 0.2, 0.3));
    }
    slicing_seconds = seconds_since(slicing_start);
    // The contour file appears only with the masks: staged until they are written.
    StagedOutputs outputs;
    if (!p.contour_file.empty())
      write_contour_file(outputs.file(p.contour_file), s, format_for_name(p.contour_file), sub_progress(progress, 0.3, 0.4));
    const auto masks_start = std::chrono::steady_clock::now();
    masks = export_masks(s, profile, p.output_path, sub_progress(progress, 0.4, 1));
    masks_seconds = seconds_since(masks_start);
    outputs.commit();
    layers = s.layers();
    points = s.points();
  }

  const double seconds = seconds_since(start);
  host.log(format("Make Print Job: %zu layers (%zu transferred, %zu sliced%s), %zu points, to %s, %.3f s "
                  "(%s %.3f s%s, masks %.3f s)",
                  layers, stats.transferred_layers, stats.resliced_layers,
                  ranges > 1 ? format(" in %zu ranges of layers, to stay within memory", ranges).c_str() : "", points,
                  p.output_path.c_str(), seconds, direct ? "slicing" : "transfer", slicing_seconds,
                  direct ? "" : (cached ? ", encoding in memory" : ", encoding read"), masks_seconds));
  log_display_warning(host, "Make Print Job", masks, profile);
  Result result = {{"layers", int64_t(layers)},
                   {"points", int64_t(points)},
                   {"transferred_layers", int64_t(stats.transferred_layers)},
                   {"resliced_layers", int64_t(stats.resliced_layers)},
                   {"encoding_cached", int64_t(cached)},
                   {"layer_ranges", int64_t(ranges)},
                   {"slicing_seconds", slicing_seconds},
                   {"masks_seconds", masks_seconds},
                   {"seconds", seconds}};
  add_display_figures(masks, result);
  return result;
}

}  // namespace

FilterSpec print_job_filter() {
  const std::string description = std::string(
      "<p>Makes the current mesh's print job in one step, in memory: its layers, "
      "either transferred from a family member's encoding (as <i>Transfer Slicing "
      "to Mesh</i> in exact mode, so the result equals direct slicing) or sliced "
      "directly when no encoding file is given, then its masks (as <i>Export Mask "
      "Images</i>), with no contour file in between unless one is asked for.</p>"
      "<p>The last encoding file read stays in memory (one entry, checked against "
      "the file's content), so a script or a pymeshlab loop over a family's members "
      "reads it only once; <i>Free Cached Memory</i> releases it, and so does a job "
      "that needs the memory. A member whose layers fail their certificate (e.g. "
      "changed in z) is sliced directly.</p>"
      "<p>When directly sliced contours would take more than a quarter of the memory "
      "still available (a large part at a very fine layer), the mesh is sliced and "
      "its masks made a range of layers at a time, so memory stays bounded; the log "
      "says how many ranges.</p>") +
      kReference;
  return typed_filter({FilterId::MakePrintJob, "Make Print Job", "make_print_job", description,
                       Arity::CurrentMesh, kLayerClass, true},
                      print_job_params(), run_print_job);
}

}  // namespace slicereuse::plugin
