// "Make Print Job": the current mesh's layers (transferred from a cached encoding, or sliced
// directly) and its masks in one filter, in memory; a contour file only when asked for.
#include "filters_common.h"
#include "slicereuse/slicing/layer_chunks.h"
#include "slicereuse/transfer/encoding_cache.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/memory_budget.h"

namespace slicereuse::plugin {
namespace {

// The plugin's one cached encoding (see encoding_cache.h): lives as long as the plugin.
EncodingCache& encoding_cache() {
  static EncodingCache cache;
  return cache;
}

// From the first print job on, large buffers freed by one member's job are kept for the next
// (ReuseBuffers, at most a quarter of the machine's memory) instead of being returned to the
// kernel, which would zero gigabytes of fresh pages for every member: bench_member_loop
// measured 2x the CPU time for transfer and 1.2-2.6x for direct slicing without this.
void keep_buffers_for_the_next_member() {
  static ReuseBuffers keep;
}

}  // namespace

Result run_print_job(const ParamValues& values, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const PrinterProfile profile = read_printer_profile(values);
  const std::string& encoding_file = values.text("encoding_file");
  const SliceOptions direct = encoding_file.empty() ? read_slice_options(values) : SliceOptions{};
  const std::string& contour_file = values.text("contour_file");
  const std::string output_path = mask_output_path(values);
  check_outputs({{"contour_file", contour_file}, {"output_path", output_path}});

  keep_buffers_for_the_next_member();
  const Mesh mesh = host.current_mesh();
  const Progress progress = host.progress();
  TransferStats stats;
  bool cached = false;
  size_t layers = 0, points = 0, ranges = 1;
  MaskExportStats masks;
  double slicing_seconds = 0, masks_seconds = 0;
  SliceOptions options = direct;
  options.encoding = false;
  double z_start = 0;
  const std::vector<double> planes = encoding_file.empty() ? slicing_planes(mesh, options, &z_start) : std::vector<double>{};
  // A stack of contours that would take more than a quarter of the memory this process may still
  // use is sliced and turned into masks a range of layers at a time, each range freed before the
  // next is sliced (a contour file needs the whole stack: then it is sliced whole, or refused
  // with the figures).
  const std::vector<size_t> first =
      encoding_file.empty() && contour_file.empty()
          ? layer_chunks(mesh, planes, available_memory() / 4, 3 * sizeof(double))
          : std::vector<size_t>{0, planes.size()};
  if (first.size() > 2) {
    ranges = first.size() - 1;
    SliceChunks chunks{first, options.thickness, [&](size_t i, const Progress& p) {
                         const auto t = std::chrono::steady_clock::now();
                         Slices s = slice_planes(mesh, {planes.begin() + long(first[i]), planes.begin() + long(first[i + 1])},
                                                 p, false);
                         s.thickness = options.thickness;
                         s.z_start = z_start + double(first[i]) * options.thickness;
                         points += s.points();
                         slicing_seconds += seconds_since(t);
                         return s;
                       }};
    masks = export_masks(chunks, profile, output_path, progress);
    masks_seconds = masks.seconds - slicing_seconds;
    layers = stats.resliced_layers = planes.size();
  } else {
    Slices s;
    const auto slicing_start = std::chrono::steady_clock::now();
    if (encoding_file.empty()) {
      s = slice_layers(mesh, options, sub_progress(progress, 0, 0.3));
      stats.resliced_layers = s.layers();
    } else {
      const auto entry = encoding_cache().get(encoding_file, mesh, &cached, sub_progress(progress, 0, 0.2));
      s = transfer_contours(entry->encoding, entry->edge_ends, mesh, TransferOptions(TransferMode::Exact, false),
                            &stats, sub_progress(progress, 0.2, 0.3));
    }
    slicing_seconds = seconds_since(slicing_start);
    // The contour file appears only with the masks: staged until they are written.
    StagedOutputs outputs;
    if (!contour_file.empty())
      write_contour_file(outputs.file(contour_file), s, format_for_name(contour_file), sub_progress(progress, 0.3, 0.4));
    const auto masks_start = std::chrono::steady_clock::now();
    masks = export_masks(s, profile, output_path, sub_progress(progress, 0.4, 1));
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
                  output_path.c_str(), seconds, encoding_file.empty() ? "slicing" : "transfer", slicing_seconds,
                  encoding_file.empty() ? "" : (cached ? ", encoding in memory" : ", encoding read"), masks_seconds));
  log_display_warning(host, "Make Print Job", masks, profile);
  return {{"layers", int64_t(layers)},
          {"points", int64_t(points)},
          {"transferred_layers", int64_t(stats.transferred_layers)},
          {"resliced_layers", int64_t(stats.resliced_layers)},
          {"encoding_cached", int64_t(cached)},
          {"layer_ranges", int64_t(ranges)},
          {"ignored_open_contours", int64_t(masks.ignored_open_contours)},
          {"outside_display", int64_t(masks.outside_display)},
          {"slicing_seconds", slicing_seconds},
          {"masks_seconds", masks_seconds},
          {"seconds", seconds}};
}

}  // namespace slicereuse::plugin
