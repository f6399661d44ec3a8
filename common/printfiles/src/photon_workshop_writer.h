#pragma once
// write_photon_workshop: an Anycubic Photon Workshop file (photon_workshop_format.h;
// docs/formats.md lists every field), of the kind its extension names (kPwsFileKinds: .pwmx,
// .pwma, .pwmb, .pm5, .pm5s, .pm4n), in the newest version that kind holds or the profile's
// file_version when non-zero:
//   tables   the profile's display (resolution, pixel size, display size), the job (layer
//            height, exposures, bottom and transition layers = the profile's faded layers, lift
//            and retract moves, light-off delay, print time: print_estimate.h), the resin volume,
//            the model's extent, the machine name (profile.printer_model, or the kind's printer),
//            the previews, and per layer its LAYERDEF entry (and SUBIMGS entry in version 518)
//   layers   each layer's pw0Img data, as encode_pw0_layer makes it, from layer_record(k)
// layer_record(k) is called on this thread for k = 0, 1, ..., L-1 in that order while the file
// is written, so the caller can encode layers in parallel and keep only a window of them in
// memory; summary() once, after the last layer, for what only all layers tell. The file is
// staged (AtomicFile): on any error, including one thrown by layer_record or summary (rethrown
// as is, e.g. Cancelled), nothing is left under path. Before anything is written, Error in words
// when the extension is not one of the kinds, the file_version is one the kind does not hold or
// slicereuse does not write, the profile is portrait (as .goo: the image is the display's x
// resolution wide, Anycubic's displays are landscape), the resolution does not fit the format's
// 16-bit fields, the tables of L layers do not fit under the 4 GiB its u32 addresses reach, or an
// exposure or the print time does not fit its field.
//
// encode_pw0_layer(job, k, runs, out): layer k's record, out replaced: its LAYERDEF entry
// (kPwsLayerDefSize bytes; the data address left 0, the writer places it) then its pw0Img data,
// from its mask as runs (mask_png.h: rows one after the other are the format's pixel stream;
// a pixel's code is its level >> 4), in time proportional to the runs and the bytes written,
// never the pixels. The entry's lit-pixel count is every non-zero pixel of the mask.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "slicereuse/png/mask_png.h"
#include "slicereuse/printer/printer_profile.h"

namespace slicereuse {

struct PhotonWorkshopJob {
  PrinterProfile profile;
  size_t layers = 0;
  double layer_height_mm = 0;
};

// What the tables say that is known only once every layer is made.
struct PhotonWorkshopSummary {
  double volume_ml = 0;
  std::vector<uint16_t> preview;   // RGB565, kPwsPreviewWidth x kPwsPreviewHeight
  std::vector<uint16_t> preview2;  // RGB565, kPwsPreview2Width x kPwsPreview2Height (version 518)
  // The closed contours' extent on the plate (mm, around the display centre); 0 when none.
  double min_x = 0, max_x = 0, min_y = 0, max_y = 0;
};

using PhotonWorkshopLayerRecord = std::function<const std::vector<uint8_t>&(size_t k)>;

void write_photon_workshop(const std::string& path, const PhotonWorkshopJob& job,
                           const PhotonWorkshopLayerRecord& layer_record,
                           const std::function<PhotonWorkshopSummary()>& summary);

void encode_pw0_layer(const PhotonWorkshopJob& job, size_t k, const MaskRuns& runs, std::vector<uint8_t>& out);

}  // namespace slicereuse
