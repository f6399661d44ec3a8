#pragma once
// write_sl1: writes a Prusa SL1 archive (zip) that PrusaSlicer's SL1 import and UVtools open:
//   config.ini       the printer's job keys (action, jobDir, expTime, numFast, layerHeight, ...)
//   prusaslicer.ini  the display geometry PrusaSlicer needs to place the images
//                    (display_width/height in mm, display_pixels_x/y, orientation, mirrors)
//   <job>NNNNN.png   one stored (not re-deflated) PNG per layer, job = file name without .sl1.
// config.ini is written after the layers, so that its usedMaterial can be summed up while they
// are made (one pass over the contours instead of a second one before). docs/formats.md lists
// every key. Exposure settings are fixed placeholders (see there).
//
// The PNG of layer k comes from layer_png(k), called on this thread for k = 0, 1, ..., L-1 in
// that order while the archive is written (libzip writes on close), so the caller can encode
// layers in parallel batches and keep only one batch in memory. The archive is staged
// (StagedOutputs, atomic_file.h): on any error, including one thrown by layer_png (rethrown as
// is, e.g. Cancelled), nothing is left under path.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "slicereuse/masks/printer_profile.h"

namespace slicereuse {

struct Sl1Job {
  PrinterProfile profile;
  size_t layers = 0;
  double layer_height_mm = 0;
  // Asked for once, after the last layer's PNG: the resin volume in ml for config.ini.
  std::function<double()> used_material_ml;
};

using LayerPng = std::function<const std::vector<uint8_t>&(size_t k)>;

void write_sl1(const std::string& path, const Sl1Job& job, const LayerPng& layer_png);

}  // namespace slicereuse
