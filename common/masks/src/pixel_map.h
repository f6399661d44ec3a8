#pragma once
// PixelMap: model x, y (mm) -> continuous pixel coordinates u (columns, to the right) and v
// (rows, downwards) as printer_profile.h places the part; pixel (c, r) is [c, c+1] x [r, r+1].
// pixel_map(p, true) applies the profile's mirrors; pixel_map(p, false) ignores them, for a
// rasterizer that flips its output instead (coverage_runs.h).
#include "slicereuse/masks/printer_profile.h"

namespace slicereuse {

struct PixelMap {
  double cu, cv, su, sv, ox, oy;
  double u(double x) const { return cu + su * (x + ox); }
  double v(double y) const { return cv + sv * (y + oy); }
};

inline PixelMap pixel_map(const PrinterProfile& p, bool mirrored) {
  const double sx = 1000.0 / p.pixel_size_x_um, sy = 1000.0 / p.pixel_size_y_um;
  return {0.5 * p.width_px,
          0.5 * p.height_px,
          mirrored && p.mirror_x ? -sx : sx,
          mirrored && p.mirror_y ? sy : -sy,
          p.offset_x_mm,
          p.offset_y_mm};
}

}  // namespace slicereuse
