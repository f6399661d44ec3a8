// "Export Mask Images" and "Compare Mask Stacks": file-to-file filters, no mesh involved.
#include <cmath>

#include "filters_common.h"
#include "slicereuse/formats/slice_files.h"
#include "slicereuse/masks/compare_mask_stacks.h"
#include "slicereuse/masks/export_masks.h"
#include "slicereuse/masks/printer_profile.h"
#include "slicereuse/util/error.h"

namespace slicereuse::plugin {
namespace {

int display_pixels(const ParamValues& values, const char* name) {
  const double v = values.number(name);
  if (!(v >= 1 && v <= kMaxDisplayPixels))
    throw Error(format("%s must be between 1 and %d pixels (got %g)", name, kMaxDisplayPixels, v));
  return int(v);
}

double positive(const ParamValues& values, const char* name) {
  const double v = values.number(name);
  if (!(v > 0) || !std::isfinite(v)) throw Error(format("%s must be greater than 0 (got %g)", name, v));
  return v;
}

double finite(const ParamValues& values, const char* name) {
  const double v = values.number(name);
  if (!std::isfinite(v)) throw Error(format("%s must be a finite number", name));
  return v;
}

}  // namespace

// The mask output (a folder, which may be given with a trailing '/', or an .sl1 file).
const std::string& mask_output_path(const ParamValues& values) {
  const std::string& path = values.text("output_path");
  if (path.empty()) throw Error("output_path is empty: choose a folder or a .sl1 file");
  return path;
}

PrinterProfile read_printer_profile(const ParamValues& values) {
  PrinterProfile profile;
  profile.width_px = display_pixels(values, "width_px");
  profile.height_px = display_pixels(values, "height_px");
  profile.pixel_size_x_um = positive(values, "pixel_size_x_um");
  profile.pixel_size_y_um = positive(values, "pixel_size_y_um");
  profile.offset_x_mm = finite(values, "offset_x_mm");
  profile.offset_y_mm = finite(values, "offset_y_mm");
  profile.mirror_x = values.number("mirror_x") != 0;
  profile.mirror_y = values.number("mirror_y") != 0;
  profile.antialiasing = values.number("antialiasing") != 0;
  return profile;
}

void log_display_warning(Host& host, const char* filter, const MaskExportStats& stats, const PrinterProfile& profile) {
  if (stats.outside_display)
    host.log(format("%s: warning: the part (x %.2f to %.2f mm, y %.2f to %.2f mm, offset %g, %g mm) "
                    "does not fit the %.2f x %.2f mm display; its masks are cut off at the edges",
                    filter, stats.min_x, stats.max_x, stats.min_y, stats.max_y, profile.offset_x_mm,
                    profile.offset_y_mm, 1e-3 * profile.width_px * profile.pixel_size_x_um,
                    1e-3 * profile.height_px * profile.pixel_size_y_um));
}

Result run_export_masks(const ParamValues& values, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const PrinterProfile profile = read_printer_profile(values);
  const std::string& contour_file = values.text("contour_file");
  const std::string& output_path = mask_output_path(values);
  check_outputs({{"output_path", output_path}});

  const Progress progress = host.progress();
  // No file: the current layer, opened from a contour file through io_encoding.
  Slices s;
  if (!contour_file.empty()) {
    s = read_contour_file(contour_file, sub_progress(progress, 0, 0.1));
  } else {
    try {
      s = host.current_contour_layer();
    } catch (const Error& e) {
      throw Error(std::string("contour_file is empty and ") + e.what());
    }
  }
  const MaskExportStats stats = export_masks(s, profile, output_path, sub_progress(progress, 0.1, 1));

  const double seconds = seconds_since(start);
  host.log(format("Export Mask Images: %zu layers of %dx%d pixels to %s, %zu open contours ignored, %.3f s",
                  stats.layers, profile.width_px, profile.height_px, output_path.c_str(),
                  stats.ignored_open_contours, seconds));
  log_display_warning(host, "Export Mask Images", stats, profile);
  return {{"layers", int64_t(stats.layers)},
          {"ignored_open_contours", int64_t(stats.ignored_open_contours)},
          {"outside_display", int64_t(stats.outside_display)},
          {"seconds", seconds}};
}

Result run_compare_masks(const ParamValues& values, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const std::string& stack_a = values.text("stack_a");
  const std::string& stack_b = values.text("stack_b");
  if (stack_a.empty() || stack_b.empty()) throw Error("stack_a and stack_b must both be given");
  const std::string& report_file = values.text("report_file");
  check_outputs({{"report_file", report_file}});

  const StackComparison c = compare_mask_stacks(stack_a, stack_b, report_file, host.progress());

  const double seconds = seconds_since(start);
  host.log(format("Compare Mask Stacks: %zu layers, min similarity %.9g at layer %zu, %llu differing pixels, %.3f s",
                  c.layers.size(), c.min_similarity, c.worst_layer,
                  (unsigned long long)c.differing_pixels, seconds));
  return {{"layers", int64_t(c.layers.size())},
          {"min_similarity", c.min_similarity},
          {"worst_layer", int64_t(c.worst_layer)},
          {"differing_pixels", int64_t(c.differing_pixels)},
          {"seconds", seconds}};
}

}  // namespace slicereuse::plugin
