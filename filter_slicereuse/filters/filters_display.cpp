// The printer's display, shared by Export Mask Images and Make Print Job: its parameters (bound
// to PrinterProfile, whose defaults are the display defaults), the warning for a part that does
// not fit it, and the figures both filters return about it.
#include "filter_params.h"
#include "filters_common.h"

namespace slicereuse::plugin {

ParamList<PrinterProfile> printer_params() {
  const PrinterProfile d;
  const Range pixels = Range::between(1, kMaxDisplayPixels, "pixels");
  ParamList<PrinterProfile> l;
  l.whole(&PrinterProfile::width_px, "width_px", "Width (pixels)", d.width_px, pixels,
          "Image width in pixels (the printer's display resolution).")
      .whole(&PrinterProfile::height_px, "height_px", "Height (pixels)", d.height_px, pixels,
             "Image height in pixels (the printer's display resolution).")
      .number(&PrinterProfile::pixel_size_x_um, "pixel_size_x_um", "Pixel size x (um)", d.pixel_size_x_um,
              Range::above(0, "um"), "Width of one pixel on the build plane, in micrometres.")
      .number(&PrinterProfile::pixel_size_y_um, "pixel_size_y_um", "Pixel size y (um)", d.pixel_size_y_um,
              Range::above(0, "um"), "Height of one pixel on the build plane, in micrometres.")
      .number(&PrinterProfile::offset_x_mm, "offset_x_mm", "Offset x (mm)", d.offset_x_mm, Range::any(),
              "Shift of the model along x from the image centre, in mm.")
      .number(&PrinterProfile::offset_y_mm, "offset_y_mm", "Offset y (mm)", d.offset_y_mm, Range::any(),
              "Shift of the model along y from the image centre, in mm.")
      .flag(&PrinterProfile::mirror_x, "mirror_x", "Mirror x", d.mirror_x,
            "Flip the images left-right (for printers whose optics mirror the display).")
      .flag(&PrinterProfile::mirror_y, "mirror_y", "Mirror y", d.mirror_y, "Flip the images top-bottom.")
      .flag(&PrinterProfile::antialiasing, "antialiasing", "Anti-aliasing", d.antialiasing,
            "Write 8-bit grey levels from pixel coverage instead of black/white masks.");
  return l;
}

void log_display_warning(Host& host, const char* filter, const MaskExportStats& stats, const PrinterProfile& profile) {
  if (stats.outside_display)
    host.log(format("%s: warning: the part (x %.2f to %.2f mm, y %.2f to %.2f mm, offset %g, %g mm) "
                    "does not fit the %.2f x %.2f mm display; its masks are cut off at the edges",
                    filter, stats.min_x, stats.max_x, stats.min_y, stats.max_y, profile.offset_x_mm,
                    profile.offset_y_mm, 1e-3 * profile.width_px * profile.pixel_size_x_um,
                    1e-3 * profile.height_px * profile.pixel_size_y_um));
}

void add_display_figures(const MaskExportStats& stats, Result& result) {
  result["ignored_open_contours"] = int64_t(stats.ignored_open_contours);
  result["outside_display"] = int64_t(stats.outside_display);
  result["part_min_x_mm"] = stats.min_x;
  result["part_max_x_mm"] = stats.max_x;
  result["part_min_y_mm"] = stats.min_y;
  result["part_max_y_mm"] = stats.max_y;
}

}  // namespace slicereuse::plugin
