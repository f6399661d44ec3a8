#pragma once
// write_ctb: a Chitubox .ctb print file, version 3 or 4 (ctb_format.h; docs/formats.md lists every
// field), its layers unencrypted unless the job gives a key:
//   header        the image (mask_image_layout: its width and height, the display's size in mm
//                 along them), the job (layer height, exposure, bottom exposure and layers, light-
//                 off delays, print time: print_estimate.h), the encryption key, mirrored or not
//   previews      400 x 300 and 200 x 125, run-length RGB565 as Chitubox encodes them, each in a
//                 place kept for its largest encoding
//   print parameters, slicer info   lift and retract moves (lift_fields.h), resin volume and
//                 weight, the machine name (the profile's printer_model, "custom" when empty),
//                 anti-aliasing, transition layers (the profile's faded layers); v4 also the
//                 disclaimer and its print parameters block
//   layer table   per layer: position, exposure (layer_exposure_s), light-off delay, where its
//                 data lies; v3 and v4 put each layer's extended definition (its moves) before its data
//   layers        layer k's data as encode_ctb_layer makes it, from layer_record(k)
// The profile's file_version says which: 3 or 4; 0 means 4.
// layer_record(k) is called on this thread for k = 0, 1, ..., L-1 in that order while the file
// is written, so the caller can encode layers in parallel and keep only a window of them in
// memory; summary() once, after the last layer, for what only all layers tell. The file is
// staged (AtomicFile): on any error, including one thrown by layer_record or summary (rethrown
// as is, e.g. Cancelled), nothing is left under path. Before anything is written, Error in words
// when the profile asks for another version (5, the encrypted CTB of newer Chitu boards, is not
// written), the image is larger than kGooMaxPixels (what the readers here take back), or the
// stack does not fit the fields: 2^32 - 1 layers, a figure beyond a float's range, a print time
// beyond 2^32 - 1 s.
//
// encode_ctb_layer(job, k, runs, out): layer k's image data from its mask as runs (mask_png.h:
// rows one after the other are the format's pixel stream), each level stored as its 7-bit code
// level >> 1 (decoded 0 or 2c + 1: the rasterizer's 128-level masks exactly), equal codes merged
// across runs and rows, then encrypted with the job's key when it is not 0; in time proportional
// to the runs, never the pixels; out replaced.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "slicereuse/png/mask_png.h"
#include "slicereuse/printer/printer_profile.h"

namespace slicereuse {

struct CtbJob {
  PrinterProfile profile;
  size_t layers = 0;
  double layer_height_mm = 0;
  uint32_t encryption_key = 0;  // 0: the layers as they are (what the export writes)
};

// What the header says that is known only once every layer is made.
struct CtbSummary {
  double volume_ml = 0;
  std::vector<uint16_t> large_preview, small_preview;  // RGB565, 400 x 300 and 200 x 125
};

using CtbLayerRecord = std::function<const std::vector<uint8_t>&(size_t k)>;

void write_ctb(const std::string& path, const CtbJob& job, const CtbLayerRecord& layer_record,
               const std::function<CtbSummary()>& summary);

void encode_ctb_layer(const CtbJob& job, size_t k, const MaskRuns& runs, std::vector<uint8_t>& out);

}  // namespace slicereuse
