#pragma once
// PixelMap: a contour point (x, y in mm) -> continuous pixel coordinates u (columns, to the
// right) and v (rows, downwards) of the image mask_image_layout (printer_profile.h) gives;
// pixel (c, r) is [c, c+1] x [r, r+1]. pixel_map(p, true) applies the image's flips (orientation
// and mirrors); pixel_map(p, false) leaves them out (columns along the column coordinate, row 0
// at the largest row coordinate), for a rasterizer that flips its output instead
// (coverage_runs.h).
// for_each_closed_contour(layer, f): what both rasterizers draw, f(xyz, n) for each closed
// contour of the layer with points (its n points, 3 doubles each), part after part; returns the
// number of open contours, which are not drawn.
#include <cstddef>
#include <cstdint>

#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/slicing/layer_view.h"

namespace slicereuse {

struct PixelMap {
  double cu, cv, su, sv, ou, ov;
  int iu, iv;  // the point's coordinate along the columns and the rows
  double u(const double* xyz) const { return cu + su * (xyz[iu] + ou); }
  double v(const double* xyz) const { return cv + sv * (xyz[iv] + ov); }
};

inline PixelMap pixel_map(const MaskImageLayout& m, bool flipped) {
  const double su = 1000.0 / m.column_um, sv = 1000.0 / m.row_um;
  return {0.5 * m.width,
          0.5 * m.height,
          flipped && m.columns_descend ? -su : su,
          flipped && m.rows_ascend ? sv : -sv,
          m.column_offset_mm,
          m.row_offset_mm,
          m.column_axis,
          m.row_axis};
}

template <class F>
size_t for_each_closed_contour(const LayerView& layer, F&& f) {
  size_t open = 0;
  for (const LayerPart& part : layer) {
    const Slices& s = *part.slices;
    const size_t k = part.layer;
    for (uint64_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c) {
      if (s.contour_open[c]) {
        ++open;
        continue;
      }
      const uint64_t b = s.contour_begin[c], n = s.contour_begin[c + 1] - b;
      if (n > 0) f(s.xyz.data() + 3 * b, n);
    }
  }
  return open;
}

}  // namespace slicereuse
