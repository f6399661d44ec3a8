#pragma once
// Mask images: one binary (or 8-bit anti-aliased) image per layer from layered contours, for
// mask-projection printers.
//
// Pixel rule: pixel (col, row) is on when its centre lies inside the layer's region by the
// nonzero winding rule of the oriented closed contours. Open contours are ignored and counted.
// Placement: the model's XY origin sits at the display centre, shifted by offset_x/y_mm;
// row 0 is the top of the image (largest y). mirror_x / mirror_y flip the image.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "slicereuse/mask_png.h"
#include "slicereuse/progress.h"
#include "slicereuse/slices.h"

namespace slicereuse {

struct PrinterProfile {
  int width_px = 1024;
  int height_px = 768;
  double pixel_size_x_um = 75;
  double pixel_size_y_um = 75;
  double offset_x_mm = 0;
  double offset_y_mm = 0;
  bool mirror_x = false;
  bool mirror_y = false;
  bool antialiasing = false;  // 8-bit coverage instead of 1-bit
};

// Rasterizes layer k into out (width*height bytes, row-major, 0 or 255; coverage 0..255 when
// antialiasing). Returns the number of open contours ignored.
size_t rasterize_layer(const Slices& s, size_t k, const PrinterProfile& profile, uint8_t* out);

// The same binary mask (profile.antialiasing must be off) as runs of lit pixels, replacing
// out's content: what .sl1 export encodes without writing out the pixels (mask_png.h).
size_t rasterize_layer_runs(const Slices& s, size_t k, const PrinterProfile& profile, MaskRuns& out);

struct MaskExportStats {
  size_t layers = 0;
  size_t ignored_open_contours = 0;
  // The closed contours' extent in mm, model coordinates, and whether it leaves the display
  // (the masks are then cut off at the display's edges).
  double min_x = 0, max_x = 0, min_y = 0, max_y = 0;
  bool outside_display = false;
  double seconds = 0;
};

// Writes one PNG per layer as <folder>/<prefix>NNNNN.png, or, when output_path ends in .sl1,
// a Prusa SL1 archive of the same PNGs plus config.ini. Multithreaded; only a few layers are
// held in memory at a time. Atomic: nothing is left under the final name on failure. A point of
// a closed contour whose x or y is not finite is refused (Error naming the point and layer).
MaskExportStats export_masks(const Slices& s, const PrinterProfile& profile,
                             const std::string& output_path, const Progress& progress = {});

// A stack too large to hold at once, made a range of layers at a time (layer_chunks.h):
// make(i, progress) returns the slices of layers [first[i], first[i + 1]), counted from 0 within
// the range. Export calls it once per range, in order, on the calling thread, and frees each
// range's slices before it makes the next, so memory holds one range (plus a few images).
struct SliceChunks {
  std::vector<size_t> first;  // range starts, then the layer count
  double thickness = 0;
  std::function<Slices(size_t i, const Progress& progress)> make;
};

// The same export of the stack the ranges make up, equal to exporting it whole.
MaskExportStats export_masks(const SliceChunks& chunks, const PrinterProfile& profile,
                             const std::string& output_path, const Progress& progress = {});

struct LayerSimilarity {
  size_t layer = 0;
  double similarity = 1;  // S(I1, I2): fraction of equal pixels
  uint64_t differing_pixels = 0;
};

struct StackComparison {
  std::vector<LayerSimilarity> layers;
  double min_similarity = 1;
  size_t worst_layer = 0;
  uint64_t differing_pixels = 0;
};

// Compares two mask stacks (folders of PNGs or .sl1 archives) layer by layer and, when
// report_csv is not empty, writes one CSV row per layer. Throws Error when the stacks differ
// in layer count or image size.
StackComparison compare_mask_stacks(const std::string& stack_a, const std::string& stack_b,
                                    const std::string& report_csv, const Progress& progress = {});

}  // namespace slicereuse
