#pragma once
// write_sl1: writes a Prusa SL1/SL1S archive (zip) as PrusaSlicer 2.5 writes one for an SLA job
// (compared with its --export-sla entry by entry and key by key), which PrusaSlicer's SLA archive
// import, the printers' firmware and UVtools open:
//   prusaslicer.ini  the display and job settings PrusaSlicer's import reads (display_width/height
//                    in mm, display_pixels_x/y, orientation, mirrors, layer heights) and the rest of
//                    the profile it takes over with the model
//   <job>NNNNN.png   one stored (not re-deflated) PNG per layer, job = file name without .sl1/.sl1s
//   config.ini       the printer's job keys (jobDir, expTime, numFade, layerHeight, printerModel, ...)
//   thumbnail/thumbnail400x400.png, thumbnail/thumbnail800x480.png   pictures of the part (RGBA)
// config.ini and the thumbnails come after the layers, so that the resin volume and the top view
// can be gathered while the layers are made (one pass over the contours instead of a second one
// before). docs/formats.md lists every entry and key and where its value comes from.
//
// The PNG of layer k comes from layer_png(k), called on this thread for k = 0, 1, ..., L-1 in
// that order while the archive is written (libzip writes on close), so the caller can encode
// layers in parallel batches and keep only one batch in memory. The archive is staged
// (StagedOutputs, atomic_file.h): on any error, including one thrown by layer_png (rethrown as
// is, e.g. Cancelled), nothing is left under path.
//
// Refused before anything is written (Error naming the problem):
//   - a job name that would mix layers and thumbnails: one containing "thumbnail" (PrusaSlicer's
//     import drops every entry whose name does) or the start of "thumbnail/" (the firmware takes
//     every PNG whose name starts with jobDir as a layer), e.g. thumbnail.sl1 or t.sl1;
//   - for printerModel SL1 or SL1S, what the printer's firmware would not print as written:
//     a layer height under 0.01 mm (it then moves 0.05 mm per layer), numFade outside 2..200,
//     expTime outside 0.1..60 s or expTimeFirst outside 0.1..120 s (it clamps them).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "slicereuse/printer/printer_profile.h"

namespace slicereuse {

struct Sl1Job {
  PrinterProfile profile;
  size_t layers = 0;
  double layer_height_mm = 0;
  // Asked for once, after the last layer's PNG: the resin volume in ml for config.ini.
  std::function<double()> used_material_ml;
  // Asked for once per thumbnail, after config.ini: the RGBA PNG of the part of width x height
  // pixels (thumbnail_png.h), into png (replaced).
  std::function<void(int width, int height, std::vector<uint8_t>& png)> thumbnail_png;
};

using LayerPng = std::function<const std::vector<uint8_t>&(size_t k)>;

void write_sl1(const std::string& path, const Sl1Job& job, const LayerPng& layer_png);

}  // namespace slicereuse
