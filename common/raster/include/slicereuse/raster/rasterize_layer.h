#pragma once
// rasterize_layer: one layer's mask image from layered contours, for mask-projection printers.
// Placement, orientation and mirrors as printer_profile.h says; the image is
// mask_image_layout(profile).width x height. Open contours are ignored and counted.
//
// Binary masks: pixel (col, row) is on (255) when its centre lies inside the layer's region by
// the nonzero winding rule of the oriented closed contours, off (0) otherwise.
//
// Anti-aliased masks (profile.antialiasing): pixel (col, row) is round(255 * f^profile.gamma),
// f the exact area of the pixel covered by the region, computed analytically from the contours
// (signed areas of the edges' pieces in each pixel, summed along the rows as font rasterizers
// do), not sampled: 256 levels. f is the pixel's integral of the winding number, as an
// absolute value clamped to 1, which is the nonzero rule's covered area wherever loops do not
// overlap (holes running against their outer loop); a pixel that an overlap of loops (winding
// 2) covers in part comes out brighter. gamma 0 gives the binary mask, byte for byte.
// Both kinds depend only on the set of oriented edges (not on contour order or where a loop
// starts; masks of transferred contours equal those of direct slicing), are computed
// deterministically on one thread, and mirror_x / mirror_y flip them exactly.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "slicereuse/png/mask_png.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/slicing/layer_view.h"
#include "slicereuse/slicing/slices.h"

namespace slicereuse {

// Each function below takes one layer, as a view (layer_view.h: a layer made of several
// slicings' layers, such as a build plate's members), or as layer k of s.

// Rasterizes the layer into out (width*height bytes, row-major). Returns the number of open
// contours ignored.
size_t rasterize_layer(const LayerView& layer, const PrinterProfile& profile, uint8_t* out);

// The same binary mask (profile.antialiasing must be off) as runs of lit pixels, replacing
// out's content: what .sl1 export encodes without writing out the pixels (mask_png.h).
size_t rasterize_layer_runs(const LayerView& layer, const PrinterProfile& profile, MaskRuns& out);

// The same anti-aliased mask (profile.antialiasing must be on) as runs of equal non-zero
// levels: runs of full pixels, and the grey pixels along the edges.
size_t rasterize_layer_antialiased_runs(const LayerView& layer, const PrinterProfile& profile, MaskRuns& out);

// That mask straight into an 8-bit PNG (out replaced): the bytes encode_mask_png gives for
// rasterize_layer_antialiased_runs (what .sl1 export encodes), without keeping the runs unless
// runs is not null: then they replace its content too, from the same pass (a job that checks its
// masks makes each once).
size_t rasterize_layer_antialiased_png(const LayerView& layer, const PrinterProfile& profile,
                                       std::vector<uint8_t>& out, MaskRuns* runs = nullptr);

inline size_t rasterize_layer(const Slices& s, size_t k, const PrinterProfile& profile, uint8_t* out) {
  return rasterize_layer(LayerView(s, k), profile, out);
}
inline size_t rasterize_layer_runs(const Slices& s, size_t k, const PrinterProfile& profile, MaskRuns& out) {
  return rasterize_layer_runs(LayerView(s, k), profile, out);
}
inline size_t rasterize_layer_antialiased_runs(const Slices& s, size_t k, const PrinterProfile& profile,
                                               MaskRuns& out) {
  return rasterize_layer_antialiased_runs(LayerView(s, k), profile, out);
}
inline size_t rasterize_layer_antialiased_png(const Slices& s, size_t k, const PrinterProfile& profile,
                                              std::vector<uint8_t>& out, MaskRuns* runs = nullptr) {
  return rasterize_layer_antialiased_png(LayerView(s, k), profile, out, runs);
}

}  // namespace slicereuse
