#include "slicereuse/printer/printer_presets.h"

#include "slicereuse/util/error.h"

namespace slicereuse {
namespace {

struct Display {
  int width_px, height_px;
  double pixel_x_um, pixel_y_um;
  bool portrait, mirror_x, mirror_y;
};
struct Job {
  const char* model;
  double exposure_s, bottom_exposure_s;
  int bottom_layers, faded_layers;
  double layer_move_s;
};

PrinterProfile profile(const Display& d, bool antialiasing, const Job& j) {
  PrinterProfile p;
  p.width_px = d.width_px;
  p.height_px = d.height_px;
  p.pixel_size_x_um = d.pixel_x_um;
  p.pixel_size_y_um = d.pixel_y_um;
  p.portrait = d.portrait;
  p.mirror_x = d.mirror_x;
  p.mirror_y = d.mirror_y;
  p.antialiasing = antialiasing;
  p.gamma = 1;
  p.printer_model = j.model;
  p.exposure_s = j.exposure_s;
  p.bottom_exposure_s = j.bottom_exposure_s;
  p.bottom_layers = j.bottom_layers;
  p.faded_layers = j.faded_layers;
  p.layer_move_s = j.layer_move_s;
  return p;
}

std::vector<PrinterPreset> make_presets() {
  const PrinterProfile method;
  return {
      // The method's display (Kwok et al. 2016): binary masks, kept for the paper's experiments.
      {"method", "Method 1024x768, 75 um (Kwok et al.)", "", method},
      // PrusaSlicer 2.5's "Original Prusa SL1": 120.96 x 68.04 mm, portrait, mirror_x left at
      // PrusaSlicer's default (on), gamma_correction default 1; "Prusa Orange Tough @0.05" times
      // (7.5 s, first layers 35 s), 10 faded layers, tilt about 5 s. 3 bottom layers: PrusaSlicer's
      // print time estimate; the SL1's firmware takes them from numFade and its own settings.
      {"prusa_sl1", "Prusa SL1", ".sl1",
       profile({2560, 1440, 47.25, 47.25, true, true, false}, true, {"SL1", 7.5, 35, 3, 10, 5})},
      // "Original Prusa SL1S SPEED": 128 x 81 mm, portrait, display_mirror_x = 1, gamma 1;
      // "Prusa Orange Tough @0.05 SL1S" times (2 s, first layers 25 s), fast tilt 2.5 s.
      {"prusa_sl1s_speed", "Prusa SL1S Speed", ".sl1s",
       profile({2560, 1620, 50, 50, true, true, false}, true, {"SL1S", 2, 25, 3, 10, 2.5})},
      // Anycubic Photon Mono X: 3840 x 2400 pixels of 50 um (192 x 120 mm). Its own format
      // (.pwmx) is not written: PNG folder, .sl1 or .goo for a converter such as UVtools.
      {"anycubic_photon_mono_x", "Anycubic Photon Mono X", "",
       profile({3840, 2400, 50, 50, false, false, false}, true, {"", 2, 40, 6, 0, 8})},
      // Elegoo Saturn 3 Ultra: 11520 x 5120 pixels of 19 x 24 um (218.88 x 122.88 mm), .goo.
      {"elegoo_saturn_3_ultra", "Elegoo Saturn 3 Ultra", ".goo",
       profile({11520, 5120, 19, 24, false, false, false}, true, {"", 2.5, 30, 5, 0, 8})},
  };
}

}  // namespace

const std::vector<PrinterPreset>& printer_presets() {
  static const std::vector<PrinterPreset> presets = make_presets();
  return presets;
}

const PrinterPreset& printer_preset(const std::string& id) {
  std::string ids;
  for (const PrinterPreset& p : printer_presets()) {
    if (p.id == id) return p;
    ids += (ids.empty() ? "" : ", ") + p.id;
  }
  throw Error("no printer profile named '" + id + "' (the profiles are: " + ids + ")");
}

}  // namespace slicereuse
