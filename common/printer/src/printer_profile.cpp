#include "slicereuse/printer/printer_profile.h"

#include <cmath>
#include <string>
#include <utility>

#include "slicereuse/util/error.h"

namespace slicereuse {

void validate_printer_profile(const PrinterProfile& p) {
  if (p.width_px <= 0 || p.height_px <= 0 || p.width_px > kMaxDisplayPixels || p.height_px > kMaxDisplayPixels)
    throw Error("display size " + std::to_string(p.width_px) + " x " + std::to_string(p.height_px) +
                " px is not within 1.." + std::to_string(kMaxDisplayPixels) + " pixels per side");
  if (!(p.pixel_size_x_um > 0) || !(p.pixel_size_y_um > 0) || !std::isfinite(p.pixel_size_x_um) ||
      !std::isfinite(p.pixel_size_y_um))
    throw Error("pixel size " + std::to_string(p.pixel_size_x_um) + " x " +
                std::to_string(p.pixel_size_y_um) + " um is not positive");
  if (!std::isfinite(p.offset_x_mm) || !std::isfinite(p.offset_y_mm))
    throw Error("display offset is not finite");
  if (!(p.gamma >= 0) || !std::isfinite(p.gamma))
    throw Error("anti-aliasing gamma " + std::to_string(p.gamma) +
                " is not a finite number >= 0 (0: binary threshold, 1: linear coverage)");
  for (const auto& [name, seconds] : {std::pair<const char*, double>{"exposure time", p.exposure_s},
                                      {"bottom exposure time", p.bottom_exposure_s},
                                      {"time between exposures", p.layer_move_s},
                                      {"bottom light-off delay", p.bottom_light_off_s},
                                      {"light-off delay", p.light_off_s}})
    if (!(seconds >= 0) || !std::isfinite(seconds))
      throw Error(std::string(name) + " " + std::to_string(seconds) + " s is not a finite number >= 0");
  for (const auto& [name, mm] : {std::pair<const char*, double>{"elephant foot compensation", p.elephant_foot_mm},
                                 {"elephant foot min width", p.elephant_foot_min_width_mm}})
    if (!(mm >= 0) || !std::isfinite(mm))
      throw Error(std::string(name) + " " + std::to_string(mm) + " mm is not a finite number >= 0");
  for (const auto& [name, mm] : {std::pair<const char*, double>{"bottom lift height", p.bottom_lift_mm},
                                 {"lift height", p.lift_mm}})
    if (!(mm >= 0) || !std::isfinite(mm))
      throw Error(std::string(name) + " " + std::to_string(mm) + " mm is not a finite number >= 0");
  for (const auto& [name, speed] :
       {std::pair<const char*, double>{"bottom lift speed", p.bottom_lift_speed_mm_min},
        {"lift speed", p.lift_speed_mm_min},
        {"bottom retract speed", p.bottom_retract_speed_mm_min},
        {"retract speed", p.retract_speed_mm_min}})
    if (!(speed > 0) || !std::isfinite(speed))
      throw Error(std::string(name) + " " + std::to_string(speed) + " mm/min is not a finite number > 0");
  if (p.grey_levels != 16 && p.grey_levels != 128 && p.grey_levels != 256)
    throw Error("grey levels " + std::to_string(p.grey_levels) +
                " is not 256, 128 (Chitubox .ctb) or 16 (Anycubic Photon Workshop)");
  if (p.file_version < 0)
    throw Error("print file version " + std::to_string(p.file_version) + " is negative (0: the newest written)");
  if (p.bottom_layers < 0 || p.faded_layers < 0)
    throw Error("bottom layers (" + std::to_string(p.bottom_layers) + ") and faded layers (" +
                std::to_string(p.faded_layers) + ") must not be negative");
}

MaskImageLayout mask_image_layout(const PrinterProfile& p) {
  MaskImageLayout m;
  if (!p.portrait) {
    m.width = p.width_px;
    m.height = p.height_px;
    m.column_um = p.pixel_size_x_um;
    m.row_um = p.pixel_size_y_um;
    m.column_offset_mm = p.offset_x_mm;
    m.row_offset_mm = p.offset_y_mm;
    m.columns_descend = p.mirror_x;
  } else {
    // The landscape image turned counter-clockwise: columns along -y, rows along -x.
    m.width = p.height_px;
    m.height = p.width_px;
    m.column_axis = 1;
    m.row_axis = 0;
    m.column_um = p.pixel_size_y_um;
    m.row_um = p.pixel_size_x_um;
    m.column_offset_mm = p.offset_y_mm;
    m.row_offset_mm = p.offset_x_mm;
    m.columns_descend = !p.mirror_x;
  }
  m.rows_ascend = p.mirror_y;
  return m;
}

void plate_point_at_pixel(const MaskImageLayout& m, double u, double v, double xy[2]) {
  // The inverse of the rasterizers' map (pixel_map.h): u = w/2 + su (c + offset), v likewise.
  const double su = (m.columns_descend ? -1000.0 : 1000.0) / m.column_um;
  const double sv = (m.rows_ascend ? 1000.0 : -1000.0) / m.row_um;
  xy[m.column_axis] = (u - 0.5 * m.width) / su - m.column_offset_mm;
  xy[m.row_axis] = (v - 0.5 * m.height) / sv - m.row_offset_mm;
}

}  // namespace slicereuse
