// The printer presets (common/printer/presets.json, compiled in): each preset's every field, as
// the table in code gave them before the presets became data, every profile's default print
// file the one its printer takes, and a broken presets text refused naming the preset and key.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "error_of.h"
#include "read_printer_presets.h"
#include "slicereuse/printer/printer_presets.h"

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

}  // namespace

TEST(PrinterPresets, EveryPresetHasItsPrintersFiguresInMenuOrder) {
  const std::vector<PrinterPreset> expected = {
      preset("method", "Method 1024x768, 75 um (Kwok et al.)", "", 1024, 768, 75, 75, false, false, false, "", 6, 35,
             1, 10, 5),
      preset("prusa_sl1", "Prusa SL1", ".sl1", 2560, 1440, 47.25, 47.25, true, true, true, "SL1", 7.5, 35, 3, 10, 5),
      preset("prusa_sl1s_speed", "Prusa SL1S Speed", ".sl1s", 2560, 1620, 50, 50, true, true, true, "SL1S", 2, 25, 3,
             10, 2.5, 0.2),
      preset("anycubic_photon_mono_x", "Anycubic Photon Mono X", "", 3840, 2400, 50, 50, false, false, true, "", 2,
             40, 6, 0, 8),
      preset("elegoo_saturn_3_ultra", "Elegoo Saturn 3 Ultra", ".goo", 11520, 5120, 19, 24, false, false, true, "",
             2.5, 30, 5, 0, 8)};
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
    EXPECT_EQ(a.printer_model, b.printer_model) << e.id;
    EXPECT_EQ(a.exposure_s, b.exposure_s) << e.id;
    EXPECT_EQ(a.bottom_exposure_s, b.bottom_exposure_s) << e.id;
    EXPECT_EQ(a.bottom_layers, b.bottom_layers) << e.id;
    EXPECT_EQ(a.faded_layers, b.faded_layers) << e.id;
    EXPECT_EQ(a.layer_move_s, b.layer_move_s) << e.id;
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
  EXPECT_EQ(printer_preset("anycubic_photon_mono_x").extension, "");
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
