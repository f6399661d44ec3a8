#pragma once
// PixelMap: model x, y (mm) -> continuous pixel coordinates u (columns, to the right) and v
// (rows, downwards) as printer_profile.h places the part; pixel (c, r) is [c, c+1] x [r, r+1].
// pixel_map(p, true) applies the profile's mirrors; pixel_map(p, false) ignores them, for a
// rasterizer that flips its output instead (coverage_runs.h).
// for_each_closed_contour(s, k, f): what both rasterizers draw, f(xyz, n) for each closed
// contour of layer k with points (its n points, 3 doubles each); returns the number of open
// contours, which are not drawn.
#include <cstddef>
#include <cstdint>

#include "slicereuse/masks/printer_profile.h"
#include "slicereuse/slicing/slices.h"

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

template <class F>
size_t for_each_closed_contour(const Slices& s, size_t k, F&& f) {
  size_t open = 0;
  for (uint64_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c) {
    if (s.contour_open[c]) {
      ++open;
      continue;
    }
    const uint64_t b = s.contour_begin[c], n = s.contour_begin[c + 1] - b;
    if (n > 0) f(s.xyz.data() + 3 * b, n);
  }
  return open;
}

}  // namespace slicereuse
