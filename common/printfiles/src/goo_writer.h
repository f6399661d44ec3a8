#pragma once
// write_goo: an Elegoo .goo print file (goo_format.h; docs/formats.md lists every field):
//   header   the profile's display (resolution, size in mm, mirrors), the job (layer height,
//            exposure, bottom exposure and layers, transition layers = the profile's faded
//            layers, print time: print_estimate.h, lift and retract moves), the resin volume and
//            the two previews
//   layers   record k as encode_goo_layer makes it, from layer_record(k)
//   ending   kGooEnding
// layer_record(k) is called on this thread for k = 0, 1, ..., L-1 in that order while the file
// is written, so the caller can encode layers in parallel and keep only a window of them in
// memory; summary() once, after the last layer, for what only all layers tell. The file is
// staged (AtomicFile): on any error, including one thrown by layer_record or summary (rethrown
// as is, e.g. Cancelled), nothing is left under path. Before anything is written, Error when
// the profile is portrait (a .goo image is its X resolution wide; Elegoo's displays are
// landscape) or the stack does not fit the header's fields (2^32 - 1 layers, 65535 transition
// layers).
//
// encode_goo_layer(job, k, runs, out): layer k's record (definition, data size, image data,
// delimiter) from its mask as runs (mask_png.h: rows one after the other are the format's
// row-major pixel stream), in time proportional to the runs, never the pixels; out replaced.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "slicereuse/png/mask_png.h"
#include "slicereuse/printer/printer_profile.h"

namespace slicereuse {

struct GooJob {
  PrinterProfile profile;
  size_t layers = 0;
  double layer_height_mm = 0;
};

// What the header says that is known only once every layer is made.
struct GooSummary {
  double volume_ml = 0;
  std::vector<uint16_t> small_preview, big_preview;  // RGB565, 116 x 116 and 290 x 290
};

// Each layer's lift and retract are the profile's (the bottom layers' own), one stage; the wait
// after the retract is lift_fields.h's.
using GooLayerRecord = std::function<const std::vector<uint8_t>&(size_t k)>;

void write_goo(const std::string& path, const GooJob& job, const GooLayerRecord& layer_record,
               const std::function<GooSummary()>& summary);

void encode_goo_layer(const GooJob& job, size_t k, const MaskRuns& runs, std::vector<uint8_t>& out);

}  // namespace slicereuse
