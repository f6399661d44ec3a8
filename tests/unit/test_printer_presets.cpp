// The printer presets (common/printer/presets.json, compiled in): each preset's every field (the
// sources are in presets.json's notes and docs/formats.md), every profile's default print file
// the one its printer takes, every preset's image the right way round for its printer (an L's
// corner and arms), and a broken presets text refused naming the preset and key.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "error_of.h"
#include "mask_layers.h"
#include "read_printer_presets.h"
#include "slicereuse/printer/printer_presets.h"
#include "slicereuse/printer/printer_profile.h"

using namespace slicereuse;

namespace {

PrinterPreset preset(const char* id, const char* name, const char* extension, int width, int height, double px,
                     double py, bool portrait, bool mirror_x, bool antialiasing, const char* model, double exposure,
                     double bottom_exposure, int bottom_layers, int faded_layers, double move,
                     double elephant_foot = 0) {
  PrinterPreset p{id, name, extension, {}};
  p.profile.width_px = width;
  p.profile.height_px = height;
  p.profile.pixel_size_x_um = px;
  p.profile.pixel_size_y_um = py;
  p.profile.portrait = portrait;
  p.profile.mirror_x = mirror_x;
  p.profile.antialiasing = antialiasing;
  p.profile.printer_model = model;
  p.profile.exposure_s = exposure;
  p.profile.bottom_exposure_s = bottom_exposure;
  p.profile.bottom_layers = bottom_layers;
  p.profile.faded_layers = faded_layers;
  p.profile.layer_move_s = move;
  p.profile.elephant_foot_mm = elephant_foot;
  return p;
}

// A lift-and-retract printer's file: its grey levels and version, and its moves (lift heights,
// lift speeds, retract speeds and light-off delays, bottom layers' first).
PrinterPreset lifting(PrinterPreset p, int grey_levels, int file_version, std::array<double, 8> lift) {
  PrinterProfile& q = p.profile;
  q.grey_levels = grey_levels;
  q.file_version = file_version;
  q.bottom_lift_mm = lift[0], q.lift_mm = lift[1];
  q.bottom_lift_speed_mm_min = lift[2], q.lift_speed_mm_min = lift[3];
  q.bottom_retract_speed_mm_min = lift[4], q.retract_speed_mm_min = lift[5];
  q.bottom_light_off_s = lift[6], q.light_off_s = lift[7];
  return p;
}

}  // namespace

TEST(PrinterPresets, EveryPresetHasItsPrintersFiguresInMenuOrder) {
  // The Anycubic printers' moves: UVtools' profiles (8 mm at 120 mm/min, 2.5 s before each exposure).
  const std::array<double, 8> anycubic = {8, 8, 120, 120, 120, 120, 2.5, 2.5};
  const std::vector<PrinterPreset> expected = {
      preset("method", "Method 1024x768, 75 um (Kwok et al.)", "", 1024, 768, 75, 75, false, false, false, "", 6, 35,
             1, 10, 5),
      preset("prusa_sl1", "Prusa SL1", ".sl1", 2560, 1440, 47.25, 47.25, true, true, true, "SL1", 7.5, 35, 3, 10, 5),
      preset("prusa_sl1s_speed", "Prusa SL1S Speed", ".sl1s", 2560, 1620, 50, 50, true, true, true, "SL1S", 2, 25, 3,
             10, 2.5, 0.2),
      lifting(preset("anycubic_photon_mono_x", "Anycubic Photon Mono X", ".pwmx", 3840, 2400, 50, 50, false, true,
                     true, "Photon Mono X", 2, 28, 8, 0, 10.5, 0.2),
              16, 0, anycubic),
      lifting(preset("elegoo_saturn_3_ultra", "Elegoo Saturn 3 Ultra", ".goo", 11520, 5120, 19, 24, false, true, true,
                     "", 2.5, 30, 5, 0, 8, 0.2),
              256, 0, {7, 7, 70, 70, 210, 210, 0, 0}),
      lifting(preset("elegoo_mars_2_pro", "Elegoo Mars 2 Pro", ".ctb", 1620, 2560, 51, 51, false, true, true,
                     "ELEGOO MARS 2 PRO", 3, 30, 5, 0, 5.18, 0.2),
              128, 4, {5, 5, 60, 80, 210, 210, 0, 0}),
      lifting(preset("phrozen_sonic_mighty_4k", "Phrozen Sonic Mighty 4K", ".ctb", 3840, 2400, 52, 52, false, true,
                     true, "PHROZEN SONIC MIGHTY 4K", 3, 30, 5, 0, 8.4, 0.2),
              128, 3, {8, 6, 60, 60, 150, 150, 0, 0}),
      lifting(preset("anycubic_photon_mono_x_6k", "Anycubic Photon Mono X 6K", ".pwmb", 5760, 3600,
                     198.15 * 1000 / 5760, 34.4, false, true, true, "Photon Mono X 6K", 2.3, 23, 8, 0, 10.5, 0.2),
              16, 0, anycubic),
      lifting(preset("anycubic_photon_mono_4", "Anycubic Photon Mono 4", ".pm4n", 9024, 5120, 17, 17, false, true, true,
                     "Photon Mono 4", 2.5, 40, 8, 0, 10.5, 0.2),
              16, 0, anycubic),
      lifting(preset("anycubic_photon_mono_m5s", "Anycubic Photon Mono M5s", ".pm5s", 11520, 5120, 19, 24, false, true,
                     true, "Photon Mono M5s", 2.5, 40, 8, 0, 10.5, 0.2),
              16, 0, anycubic)};
  const std::vector<PrinterPreset>& presets = printer_presets();
  ASSERT_EQ(presets.size(), expected.size());
  for (size_t i = 0; i < presets.size(); ++i) {
    const PrinterPreset &p = presets[i], &e = expected[i];
    const PrinterProfile &a = p.profile, &b = e.profile;
    EXPECT_EQ(p.id, e.id);
    EXPECT_EQ(p.name, e.name) << e.id;
    EXPECT_EQ(p.extension, e.extension) << e.id;
    EXPECT_EQ(a.width_px, b.width_px) << e.id;
    EXPECT_EQ(a.height_px, b.height_px) << e.id;
    EXPECT_EQ(a.pixel_size_x_um, b.pixel_size_x_um) << e.id;
    EXPECT_EQ(a.pixel_size_y_um, b.pixel_size_y_um) << e.id;
    EXPECT_EQ(a.portrait, b.portrait) << e.id;
    EXPECT_EQ(a.offset_x_mm, 0) << e.id;
    EXPECT_EQ(a.offset_y_mm, 0) << e.id;
    EXPECT_EQ(a.mirror_x, b.mirror_x) << e.id;
    EXPECT_EQ(a.mirror_y, false) << e.id;
    EXPECT_EQ(a.antialiasing, b.antialiasing) << e.id;
    EXPECT_EQ(a.gamma, 1) << e.id;
    EXPECT_EQ(a.grey_levels, b.grey_levels) << e.id;
    EXPECT_EQ(a.printer_model, b.printer_model) << e.id;
    EXPECT_EQ(a.exposure_s, b.exposure_s) << e.id;
    EXPECT_EQ(a.bottom_exposure_s, b.bottom_exposure_s) << e.id;
    EXPECT_EQ(a.bottom_layers, b.bottom_layers) << e.id;
    EXPECT_EQ(a.faded_layers, b.faded_layers) << e.id;
    EXPECT_EQ(a.layer_move_s, b.layer_move_s) << e.id;
    EXPECT_EQ(a.bottom_lift_mm, b.bottom_lift_mm) << e.id;
    EXPECT_EQ(a.lift_mm, b.lift_mm) << e.id;
    EXPECT_EQ(a.bottom_lift_speed_mm_min, b.bottom_lift_speed_mm_min) << e.id;
    EXPECT_EQ(a.lift_speed_mm_min, b.lift_speed_mm_min) << e.id;
    EXPECT_EQ(a.bottom_retract_speed_mm_min, b.bottom_retract_speed_mm_min) << e.id;
    EXPECT_EQ(a.retract_speed_mm_min, b.retract_speed_mm_min) << e.id;
    EXPECT_EQ(a.bottom_light_off_s, b.bottom_light_off_s) << e.id;
    EXPECT_EQ(a.light_off_s, b.light_off_s) << e.id;
    EXPECT_EQ(a.file_version, b.file_version) << e.id;
    EXPECT_EQ(a.elephant_foot_mm, b.elephant_foot_mm) << e.id;
    EXPECT_EQ(a.elephant_foot_min_width_mm, 0.2) << e.id;
    EXPECT_EQ(&printer_preset(e.id), &p);
  }
  // The method's preset is the profile's defaults, which hosts take their parameters from.
  const PrinterProfile defaults;
  EXPECT_EQ(printer_preset("method").profile.width_px, defaults.width_px);
  EXPECT_EQ(printer_preset("method").profile.exposure_s, defaults.exposure_s);
}

TEST(PrinterPresets, EveryProfilesDefaultFileIsTheOneItsPrinterTakes) {
  EXPECT_EQ(printer_preset("prusa_sl1").extension, ".sl1");
  EXPECT_EQ(printer_preset("prusa_sl1s_speed").extension, ".sl1s");
  EXPECT_EQ(printer_preset("elegoo_saturn_3_ultra").extension, ".goo");
  EXPECT_EQ(printer_preset("method").extension, "");  // a PNG folder
  EXPECT_EQ(printer_preset("anycubic_photon_mono_x").extension, ".pwmx");
  // Chitubox's .ctb, in the version each printer's UVtools profile names.
  EXPECT_EQ(printer_preset("elegoo_mars_2_pro").extension, ".ctb");
  EXPECT_EQ(printer_preset("phrozen_sonic_mighty_4k").extension, ".ctb");
  // Photon Workshop's files, one extension per model.
  EXPECT_EQ(printer_preset("anycubic_photon_mono_x_6k").extension, ".pwmb");
  EXPECT_EQ(printer_preset("anycubic_photon_mono_4").extension, ".pm4n");
  EXPECT_EQ(printer_preset("anycubic_photon_mono_m5s").extension, ".pm5s");
}

namespace {

// Where a layer's lit pixels sit in the mask image and which way the L's arms point, in the
// image as written (row 0 at the top): the quadrant of the image the L's bounding box lies in
// ("top left", ...), then the direction ("right", "left", "up", "down") of its long arm and of
// its short arm from the elbow. "" when the lit pixels are not one L within one quadrant.
struct Orientation {
  std::string quadrant, long_arm, short_arm;
  bool operator==(const Orientation& o) const {
    return quadrant == o.quadrant && long_arm == o.long_arm && short_arm == o.short_arm;
  }
};

std::ostream& operator<<(std::ostream& out, const Orientation& o) {
  return out << "{" << o.quadrant << ", long arm " << o.long_arm << ", short arm " << o.short_arm << "}";
}

Orientation orientation_of(const std::vector<uint8_t>& image, int width, int height) {
  int c0 = width, c1 = -1, r0 = height, r1 = -1;
  for (int r = 0; r < height; ++r)
    for (int c = 0; c < width; ++c)
      if (image[size_t(r) * width + c] == 255) {
        c0 = std::min(c0, c), c1 = std::max(c1, c), r0 = std::min(r0, r), r1 = std::max(r1, r);
      }
  if (c1 < 0) return {};
  const bool left = c1 < width / 2, right = c0 >= width - width / 2;
  const bool top = r1 < height / 2, bottom = r0 >= height - height / 2;
  if (left == right || top == bottom) return {};
  auto lit = [&](int c, int r) { return image[size_t(r) * width + c] == 255; };
  // Of the bounding box's corners, the L leaves exactly the one opposite its elbow dark.
  const std::array<std::array<int, 2>, 4> corners = {{{c0, r0}, {c1, r0}, {c0, r1}, {c1, r1}}};
  int dark = -1;
  for (int k = 0; k < 4; ++k)
    if (!lit(corners[k][0], corners[k][1])) {
      if (dark >= 0) return {};
      dark = k;
    }
  if (dark < 0) return {};
  const auto [ec, er] = corners[3 - dark];  // the elbow
  const std::string along_columns = ec == c0 ? "right" : "left", along_rows = er == r0 ? "down" : "up";
  const bool columns_longer = c1 - c0 > r1 - r0;
  return {std::string(top ? "top" : "bottom") + (left ? " left" : " right"),
          columns_longer ? along_columns : along_rows, columns_longer ? along_rows : along_columns};
}

}  // namespace

TEST(PrinterPresets, EveryPresetPrintsTheModelTheRightWayRound) {
  // The model's +x/+y quadrant holds an L: the elbow near the origin (the display's centre), the
  // long arm along +x, the short arm, half as long, along +y, sized to the display's smaller side.
  // Where it lands in each preset's image is what its source's orientation and mirrors make of it,
  // which is what the printer's file must hold (UVtools' profiles give each printer the
  // PrusaSlicer orientation and mirrors whose images UVtools copies unchanged into that printer's
  // file). Landscape without mirrors draws the top view: +x right, +y up. A bottom-up printer's
  // part hangs from the plate upside down over the screen, so its file must hold each layer as
  // seen from below, the top view mirrored: every real printer's row below has one mirror.
  const std::map<std::string, Orientation> expected = {
      // The method's display (Kwok et al.): landscape, no mirror: the images are the top view, for
      // the paper's experiments, not for a printer's file.
      {"method", {"top right", "right", "up"}},
      // PrusaSlicer's 'Original Prusa SL1': portrait, display_mirror_x = 1. The landscape image
      // turned counter-clockwise puts +x up and +y left; the mirror flips +y to the right. The
      // SL1 shows it from below, so the part comes out as modelled (UVtools' own SL1 profile,
      // landscape 1440 x 2560 with mirror_x, is the same mirror image turned a quarter).
      {"prusa_sl1", {"top right", "up", "right"}},
      // PrusaSlicer's 'Original Prusa SL1S SPEED': the same portrait with display_mirror_x = 1.
      {"prusa_sl1s_speed", {"top right", "up", "right"}},
      // PrusaSlicer's and UVtools' 'Anycubic Photon Mono X': landscape, display_mirror_x = 1:
      // +x to the left; PrusaSlicer writes its .pwmx images so.
      {"anycubic_photon_mono_x", {"top left", "left", "up"}},
      // UVtools' 'Elegoo Saturn 3 Ultra': landscape, display_mirror_x = 1: +x to the left, the
      // layer seen from below, as the .goo's image is shown.
      {"elegoo_saturn_3_ultra", {"top left", "left", "up"}},
      // UVtools' 'Elegoo Mars 2 Pro': landscape (1620 wide, 2560 tall), display_mirror_x = 1:
      // +x to the left, the layer seen from below, as the .ctb's image is shown.
      {"elegoo_mars_2_pro", {"top left", "left", "up"}},
      // UVtools' 'Phrozen Sonic Mighty 4K': landscape, display_mirror_x = 1 (.ctb, as above).
      {"phrozen_sonic_mighty_4k", {"top left", "left", "up"}},
      // UVtools' 'Anycubic Photon Mono X 6K' (and PrusaSlicer's): landscape, display_mirror_x = 1:
      // +x to the left in the .pwmb, as for the Mono X.
      {"anycubic_photon_mono_x_6k", {"top left", "left", "up"}},
      // UVtools' 'Anycubic Photon Mono 4': landscape, display_mirror_x = 1 (.pm4n, +x to the left).
      {"anycubic_photon_mono_4", {"top left", "left", "up"}},
      // UVtools' 'Anycubic Photon Mono M5s': landscape, display_mirror_x = 1 (.pm5s, +x to the left).
      {"anycubic_photon_mono_m5s", {"top left", "left", "up"}},
  };
  for (const PrinterPreset& preset : printer_presets()) {
    SCOPED_TRACE(preset.id);
    ASSERT_EQ(expected.count(preset.id), 1u) << "a preset without its expected orientation: add a row";
    PrinterProfile p = preset.profile;
    p.antialiasing = false;  // lit pixels are 255, all others 0
    const double side = std::min(p.width_px * p.pixel_size_x_um, p.height_px * p.pixel_size_y_um) / 1000;
    const double at = 0.05 * side, thick = 0.05 * side;
    const Slices s = test::make_slices({{test::rect(at, at, at + 0.4 * side, at + thick),
                                         test::rect(at, at + thick, at + thick, at + 0.2 * side)}});
    const MaskImageLayout m = mask_image_layout(p);
    EXPECT_EQ(orientation_of(test::raster(s, 0, p), m.width, m.height), expected.at(preset.id));
  }
  EXPECT_EQ(expected.size(), printer_presets().size());  // no row for a preset that is gone
}

TEST(PrinterPresets, ABrokenPresetsTextIsRefusedNamingThePresetAndTheKey) {
  const std::string good = R"({"formats": [{"extension": ".sl1", "name": "S", "grey_levels": 256}],
      "presets": [{"id": "a", "name": "A", "extension": ".sl1",
      "display": {"width_px": 100, "height_px": 50, "pixel_x_um": 50, "pixel_y_um": 50,
                  "portrait": false, "mirror_x": true, "mirror_y": false},
      "antialiasing": true,
      "job": {"model": "", "exposure_s": 2, "bottom_exposure_s": 20, "bottom_layers": 3, "faded_layers": 0,
              "layer_move_s": 4, "elephant_foot_mm": 0.1, "elephant_foot_min_width_mm": 0.3}}]})";
  auto error = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    return test::error_of([&] { detail::read_printer_presets(text, "p.json"); });
  };
  const std::vector<PrinterPreset> one = detail::read_printer_presets(good, "p.json");
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].profile.width_px, 100);
  EXPECT_TRUE(one[0].profile.mirror_x);
  EXPECT_EQ(one[0].profile.layer_move_s, 4);
  EXPECT_EQ(one[0].profile.elephant_foot_mm, 0.1);
  EXPECT_EQ(one[0].profile.elephant_foot_min_width_mm, 0.3);
  EXPECT_EQ(error("\"exposure_s\": 2, ", ""), "the job of printer preset 'a' (p.json) has no \"exposure_s\"");
  EXPECT_EQ(error("\"id\": \"a\", ", ""), "printer preset 1 (p.json) has no \"id\"");
  EXPECT_EQ(error("\"portrait\": false", "\"portrait\": \"no\""),
            "\"portrait\" in the display of printer preset 'a' (p.json) is a string, not true or false");
  EXPECT_EQ(error("\"bottom_layers\": 3", "\"bottom_layers\": 2.5"),
            "\"bottom_layers\" in the job of printer preset 'a' (p.json) is 2.5, not a whole number");
  EXPECT_EQ(error("\"elephant_foot_mm\": 0.1", "\"elephant_foot_mm\": -0.1"),
            "printer preset 'a' (p.json): elephant foot compensation -0.100000 mm is not a finite number >= 0");
  EXPECT_EQ(error("\"width_px\": 100", "\"width_px\": 0"),
            "printer preset 'a' (p.json): display size 0 x 50 px is not within 1..65535 pixels per side");
  const std::string preset = good.substr(good.find("{\"id\""), good.rfind("]}") - good.find("{\"id\""));
  EXPECT_EQ(error(preset, preset + ", " + preset), "printer preset 'a' (p.json) is given twice");
  EXPECT_EQ(error(good, R"({"formats": [], "presets": []})"), "p.json has no presets");
  EXPECT_EQ(error("\"name\": \"A\", \"extension\": \".sl1\"", "\"name\": \"A\", \"extension\": \".ctb\""),
            "\"extension\" in printer preset 'a' (p.json) is '.ctb', none of the print formats in p.json");
  EXPECT_EQ(error("\"grey_levels\": 256", "\"grey_levels\": 64"),
            "\"grey_levels\" in print format 1 (p.json) is 64, not 16, 128 or 256");
  EXPECT_EQ(error("\"extension\": \".sl1\", \"name\": \"S\"", "\"extension\": \"CTB\", \"name\": \"S\""),
            "\"extension\" in print format 1 (p.json) is 'CTB', not a dot and lower-case letters and digits");
  EXPECT_EQ(error(good, R"({"presets": [})").rfind("'p.json': parse error at line 1, column 14", 0), 0u);
}
