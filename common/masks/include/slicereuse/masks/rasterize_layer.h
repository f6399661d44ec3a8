#pragma once
// rasterize_layer: one layer's mask image from layered contours, for mask-projection printers.
//
// Pixel rule: pixel (col, row) is on when its centre lies inside the layer's region by the
// nonzero winding rule of the oriented closed contours. Open contours are ignored and counted.
// Placement as printer_profile.h says.
#include <cstddef>
#include <cstdint>

#include "slicereuse/masks/mask_png.h"
#include "slicereuse/masks/printer_profile.h"
#include "slicereuse/slicing/slices.h"

namespace slicereuse {

// Rasterizes layer k into out (width*height bytes, row-major, 0 or 255; coverage 0..255 when
// antialiasing). Returns the number of open contours ignored.
size_t rasterize_layer(const Slices& s, size_t k, const PrinterProfile& profile, uint8_t* out);

// The same binary mask (profile.antialiasing must be off) as runs of lit pixels, replacing
// out's content: what .sl1 export encodes without writing out the pixels (mask_png.h).
size_t rasterize_layer_runs(const Slices& s, size_t k, const PrinterProfile& profile, MaskRuns& out);

}  // namespace slicereuse
