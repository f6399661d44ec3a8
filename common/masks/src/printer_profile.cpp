#include "slicereuse/masks/printer_profile.h"

#include <cmath>
#include <string>

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
}

}  // namespace slicereuse
