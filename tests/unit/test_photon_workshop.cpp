// Anycubic Photon Workshop export (.pwmx, .pwma, .pwmb, .pm5, .pm5s, .pm4n; versions 516, 517,
// 518): every layer, read back through MaskStack, equals rasterize_layer's pixels; the tables
// carry the profile (read here field by field at the offsets docs/formats.md gives); hand-encoded
// pw0Img runs at the run-length limits; lit-pixel counts; previews; atomic writes and refusals;
// MaskStack's errors on damaged files.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <tuple>
#include <vector>

#include "error_of.h"
#include "mask_layers.h"
#include "print_file_tests.h"
#include "mask_stack.h"
#include "photon_workshop_writer.h"
#include "thumbnail_png.h"
#include "slicereuse/printer/print_estimate.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/printfiles/compare_mask_stacks.h"
#include "slicereuse/printfiles/export_masks.h"
#include "slicereuse/raster/top_view.h"
#include "slicereuse/util/error.h"
#include "temp_folder.h"

namespace fs = std::filesystem;
using namespace slicereuse;

namespace {

using test::Layer;
using test::make_slices;
using test::mirrored_display;
using test::raster;
using test::le16;
using test::le32;
using test::f32;
using test::part_layers;
using test::read_bytes;
using test::read_stack;
using test::rect;
using test::write_bytes;
using test::small_display;
using test::star;

std::string text(const std::string& b, size_t at, size_t n) { return std::string(b.c_str() + at, strnlen(b.c_str() + at, n)); }

// File mark offsets (docs/formats.md).
constexpr size_t kHeaderAt = 20, kSoftwareAt = 24, kPreviewAt = 28, kColoursAt = 32, kLayerDefAt = 36, kExtraAt = 40,
                 kMachineAt = 44, kLayerDataAt = 48, kModelAt = 52, kSubLayerDefAt = 56, kPreview2At = 60;

// Layer k's LAYERDEF entry.
size_t entry(const std::string& b, size_t k) { return le32(b, kLayerDefAt) + 20 + 32 * k; }

// Every extension and the versions it takes: {name, file_version (0: default), version written}.
struct Kind {
  const char* name;
  int file_version;
  unsigned version;
};
const Kind kKinds[] = {{"a.pwmx", 0, 516}, {"a.pwma", 0, 516}, {"a.pwmb", 0, 517}, {"b.pwmb", 516, 516},
                       {"a.pm5", 0, 517},  {"a.pm5s", 0, 518}, {"a.pm4n", 0, 518}, {"b.pm4n", 517, 517},
                       {"c.pm4n", 516, 516}, {"D.PWMX", 0, 516}};

using PhotonWorkshopFiles = test::TempFolderTest;

}  // namespace

TEST_F(PhotonWorkshopFiles, EveryLayerReadsBackAsTheMaskInEveryKindAndVersion) {
  const Slices s = make_slices(part_layers());
  for (PrinterProfile p : {small_display(), mirrored_display()})
    for (bool aa : {false, true})
      for (const Kind& kind : kKinds) {
        p.antialiasing = aa;
        p.grey_levels = aa ? 16 : 256;
        p.file_version = kind.file_version;
        export_masks(s, p, path(kind.name));
        const std::string b = read_bytes(path(kind.name));
        ASSERT_EQ(b.substr(0, 12), std::string("ANYCUBIC\0\0\0\0", 12));
        EXPECT_EQ(le32(b, 12), kind.version) << kind.name;
        const std::vector<MaskImage> images = read_stack(path(kind.name));
        ASSERT_EQ(images.size(), s.layers());
        for (size_t k = 0; k < s.layers(); ++k) {
          const std::vector<uint8_t> mask = raster(s, k, p);
          EXPECT_TRUE(images[k].pixels == mask) << kind.name << " layer " << k;
          EXPECT_EQ(images[k].width, mask_image_layout(p).width);
          // Anti-aliased layers hold grey levels (the thin wall is half a pixel wide).
          if (k == 1)
            EXPECT_EQ(std::any_of(mask.begin(), mask.end(), [](uint8_t v) { return v != 0 && v != 255; }), aa);
        }
        fs::remove(path(kind.name));
      }
}

TEST_F(PhotonWorkshopFiles, A256LevelProfileIsExportedAsTheNearestLevelsTheFileHolds) {
  // Export draws a 256-level profile's masks with the 16 levels an Anycubic file holds
  // (grey_levels.h), each stored as its code level >> 4 and read back as 17c.
  const Slices s = make_slices(part_layers());
  PrinterProfile p = small_display();
  p.antialiasing = true;
  p.grey_levels = 256;
  export_masks(s, p, path("g.pwmx"));
  const std::vector<MaskImage> images = read_stack(path("g.pwmx"));
  PrinterProfile held = p;
  held.grey_levels = 16;
  size_t moved = 0;
  for (size_t k = 0; k < s.layers(); ++k) {
    const std::vector<uint8_t> full = raster(s, k, p), expected = raster(s, k, held);
    for (size_t i = 0; i < full.size(); ++i) moved += full[i] != expected[i];
    EXPECT_TRUE(images[k].pixels == expected) << k;
  }
  EXPECT_GT(moved, 0u);
}

TEST_F(PhotonWorkshopFiles, RunsAreEncodedAtTheFormatsLimits) {
  // 10000 x 2 pixels as runs; row 0: 15 x 255, 15 x 136 (code 8), 16 x 119 (code 7),
  // 4096 x 255, 3 x 5 (code 0: black), then black to 2333 in row 1 (8191 in all), 4095 x 255, black.
  MaskRuns runs;
  runs.width = 10000;
  runs.height = 2;
  const std::vector<std::array<int, 4>> all = {{0, 0, 15, 255},     {0, 15, 30, 136}, {0, 30, 46, 119},
                                               {0, 46, 4142, 255},  {0, 4142, 4145, 5}, {1, 2333, 6428, 255}};
  runs.row_begin = {0};
  for (int r = 0; r < 2; ++r) {
    for (const auto& [row, c0, c1, v] : all)
      if (row == r) {
        runs.columns.push_back(uint16_t(c0));
        runs.columns.push_back(uint16_t(c1));
        runs.levels.push_back(uint8_t(v));
      }
    runs.row_begin.push_back(uint32_t(runs.levels.size()));
  }
  PrinterProfile p;
  p.width_px = 10000;
  p.height_px = 2;
  const PhotonWorkshopJob job{p, 1, 0.05};
  std::vector<uint8_t> record;
  encode_pw0_layer(job, 0, runs, record);
  const std::vector<uint8_t> data = {0xF0, 0x0F,                          // 15 x 0xF
                                     0x8F,                                // 15 x code 8
                                     0x7F, 0x71,                          // 16 x code 7: 15 + 1
                                     0xFF, 0xFF, 0xF0, 0x01,              // 4096 x 0xF: 4095 + 1
                                     0x0F, 0xFF, 0x0F, 0xFF, 0x00, 0x01,  // 8191 x 0: 4095 + 4095 + 1
                                     0xFF, 0xFF,                          // 4095 x 0xF
                                     0x0D, 0xF4};                         // 3572 x 0
  ASSERT_EQ(record.size(), 32 + data.size());
  EXPECT_EQ(std::vector<uint8_t>(record.begin() + 32, record.end()), data);
  const std::string entry_bytes(record.begin(), record.begin() + 32);
  EXPECT_EQ(le32(entry_bytes, 4), data.size());
  // Lit pixels: those a reader finds lit; the 5s are stored as code 0, black.
  EXPECT_EQ(le32(entry_bytes, 24), 15u + 15 + 16 + 4096 + 4095);

  write_photon_workshop(path("runs.pwmx"), job, [&](size_t) -> const std::vector<uint8_t>& { return record; }, [] {
    return PhotonWorkshopSummary{0, std::vector<uint16_t>(224 * 168), std::vector<uint16_t>(320 * 190)};
  });
  std::vector<uint8_t> pixels(20000, 0);
  for (const auto& [row, c0, c1, v] : all) std::fill(pixels.begin() + row * 10000 + c0, pixels.begin() + row * 10000 + c1, uint8_t(17 * (v >> 4)));
  const std::vector<MaskImage> images = read_stack(path("runs.pwmx"));
  ASSERT_EQ(images.size(), 1u);
  EXPECT_EQ(images[0].width, 10000);
  EXPECT_EQ(images[0].height, 2);
  EXPECT_TRUE(images[0].pixels == pixels);
  const std::string b = read_bytes(path("runs.pwmx"));
  EXPECT_EQ(le32(b, entry(b, 0)), le32(b, kLayerDataAt));
  EXPECT_EQ(b.substr(le32(b, kLayerDataAt)), std::string(data.begin(), data.end()));
}

TEST_F(PhotonWorkshopFiles, TheTablesCarryTheProfileAndTheJobInEachVersion) {
  // 1 mm layers: a 10 x 10 mm square, then the same square with a 4 x 4 mm hole: 184 mm^3; then
  // three empty layers.
  const Slices s = make_slices({{rect(-5, -5, 5, 5)}, {rect(-5, -5, 5, 5), rect(-2, -2, 2, 2, true)}, {}, {}, {}}, 1.0);
  PrinterProfile p = mirrored_display();
  p.exposure_s = 2;
  p.bottom_exposure_s = 20;
  p.bottom_layers = 1;
  p.faded_layers = 3;
  p.layer_move_s = 8;
  p.bottom_lift_mm = 6;
  p.lift_mm = 4;
  p.bottom_lift_speed_mm_min = 60;
  p.lift_speed_mm_min = 120;
  p.bottom_retract_speed_mm_min = 90;
  p.retract_speed_mm_min = 180;
  p.light_off_s = 0.5;
  for (const char* name : {"t.pwmx", "t.pm5", "t.pm5s"}) {
    for (bool named : {false, true}) {
      p.printer_model = named ? "My Mono" : "";
      export_masks(s, p, path(name));
      const std::string b = read_bytes(path(name));
      const unsigned v = le32(b, 12);
      SCOPED_TRACE(std::string(name) + " version " + std::to_string(v));
      EXPECT_EQ(v, std::string(name) == "t.pwmx" ? 516u : std::string(name) == "t.pm5" ? 517u : 518u);
      EXPECT_EQ(le32(b, 16), v == 516 ? 8u : v == 517 ? 9u : 11u);  // tables
      const size_t mark = v == 516 ? 52 : v == 517 ? 56 : 64;
      // HEADER.
      const size_t h = le32(b, kHeaderAt);
      EXPECT_EQ(h, mark);
      EXPECT_EQ(text(b, h, 12), "HEADER");
      EXPECT_EQ(le32(b, h + 12), v == 516 ? 84u : v == 517 ? 92u : 96u);
      EXPECT_FLOAT_EQ(f32(b, h + 16), 120);  // the larger side of an 80 x 120 um pixel
      EXPECT_FLOAT_EQ(f32(b, h + 20), 1);
      EXPECT_FLOAT_EQ(f32(b, h + 24), 2);
      // The wait before cure: what brings the moves up to layer_move_s, longer than the light-off.
      EXPECT_FLOAT_EQ(f32(b, h + 28), float(8 - 60 * (4.0 / 120 + 4.0 / 180)));
      EXPECT_FLOAT_EQ(f32(b, h + 32), 20);
      EXPECT_FLOAT_EQ(f32(b, h + 36), 1);
      EXPECT_FLOAT_EQ(f32(b, h + 40), 4);
      EXPECT_FLOAT_EQ(f32(b, h + 44), 2);  // mm/s
      EXPECT_FLOAT_EQ(f32(b, h + 48), 3);
      EXPECT_FLOAT_EQ(f32(b, h + 52), 0.184f);
      EXPECT_EQ(le32(b, h + 56), 1u);  // binary masks
      EXPECT_EQ(le32(b, h + 60), 240u);
      EXPECT_EQ(le32(b, h + 64), 160u);
      EXPECT_FLOAT_EQ(f32(b, h + 68), 0.184f * 1.1f);
      EXPECT_FLOAT_EQ(f32(b, h + 72), 0);
      EXPECT_EQ(le32(b, h + 76), uint32_t('$'));
      EXPECT_EQ(le32(b, h + 80), 1u);                                     // per-layer settings
      EXPECT_EQ(le32(b, h + 84), uint32_t(std::lround(print_seconds(p, 5))));  // 55 s + 5 x 8 s
      EXPECT_EQ(le32(b, h + 84), 95u);
      EXPECT_EQ(le32(b, h + 88), 3u);  // transition layers
      EXPECT_EQ(le32(b, h + 96), 0u);  // advanced mode
      // PREVIEW, then the colour table.
      const size_t pv = le32(b, kPreviewAt);
      EXPECT_EQ(pv, h + 16 + le32(b, h + 12));
      EXPECT_EQ(text(b, pv, 12), "PREVIEW");
      EXPECT_EQ(le32(b, pv + 12), 28u + 224 * 168 * 2);
      EXPECT_EQ(le32(b, pv + 16), 224u);
      EXPECT_EQ(le32(b, pv + 20), uint32_t('x'));
      EXPECT_EQ(le32(b, pv + 24), 168u);
      const size_t c = le32(b, kColoursAt);
      EXPECT_EQ(c, pv + 28 + 224 * 168 * 2);
      EXPECT_EQ(le32(b, c + 4), 16u);
      for (size_t i = 0; i < 16; ++i) EXPECT_EQ(uint8_t(b[c + 8 + i]), 255) << i;  // anti-aliasing 1
      // LAYERDEF: exposures step down over the 3 transition layers.
      const size_t d = le32(b, kLayerDefAt);
      EXPECT_EQ(d, c + 28);
      EXPECT_EQ(text(b, d, 12), "LAYERDEF");
      EXPECT_EQ(le32(b, d + 12), 4u + 32 * 5);
      EXPECT_EQ(le32(b, d + 16), 5u);
      const float exposures[5] = {20, 15.5, 11, 6.5, 2};
      uint32_t next = le32(b, kLayerDataAt);
      for (size_t k = 0; k < 5; ++k) {
        const size_t e = entry(b, k);
        EXPECT_EQ(le32(b, e), next) << k;
        next += le32(b, e + 4);
        EXPECT_FLOAT_EQ(f32(b, e + 8), k == 0 ? 6 : 4) << k;
        EXPECT_FLOAT_EQ(f32(b, e + 12), k == 0 ? 1 : 2) << k;
        EXPECT_FLOAT_EQ(f32(b, e + 16), exposures[k]) << k;
        EXPECT_FLOAT_EQ(f32(b, e + 20), 1) << k;
        const std::vector<uint8_t> mask = raster(s, k, p);
        EXPECT_EQ(le32(b, e + 24), size_t(std::count_if(mask.begin(), mask.end(), [](uint8_t x) { return x != 0; })));
        EXPECT_EQ(le32(b, e + 28), 0u);
      }
      EXPECT_EQ(next, b.size());
      EXPECT_GT(le32(b, entry(b, 0) + 24), 0u);
      EXPECT_EQ(le32(b, entry(b, 3) + 24), 0u);
      // EXTRA: bottom, then other layers: 2 stages of (height, lift speed, retract speed).
      const size_t x = le32(b, kExtraAt);
      EXPECT_EQ(x, d + 20 + 32 * 5);
      EXPECT_EQ(text(b, x, 12), "EXTRA");
      EXPECT_EQ(le32(b, x + 12), 24u);
      const float extra[14] = {0, 6, 1, 1.5, 0, 1, 1.5, 0, 4, 2, 3, 0, 2, 3};
      for (size_t i = 0; i < 14; ++i) {
        if (i == 0 || i == 7)
          EXPECT_EQ(le32(b, x + 16 + 4 * i), 2u);
        else
          EXPECT_FLOAT_EQ(f32(b, x + 16 + 4 * i), extra[i]) << i;
      }
      // MACHINE.
      const size_t m = le32(b, kMachineAt);
      EXPECT_EQ(m, x + 72);
      EXPECT_EQ(text(b, m, 12), "MACHINE");
      EXPECT_EQ(le32(b, m + 12), v == 518 ? 224u : 156u);
      EXPECT_EQ(text(b, m + 16, 96),
                named ? "My Mono" : v == 516 ? "Photon Mono X" : v == 517 ? "Photon Mono M5" : "Photon Mono M5s");
      EXPECT_EQ(text(b, m + 112, 16), "pw0Img");
      EXPECT_EQ(le32(b, m + 128), 16u);
      EXPECT_EQ(le32(b, m + 132), v == 516 ? 1u : v == 517 ? 7u : 15u);
      EXPECT_FLOAT_EQ(f32(b, m + 136), 19.2f);
      EXPECT_FLOAT_EQ(f32(b, m + 140), 19.2f);
      EXPECT_FLOAT_EQ(f32(b, m + 144), 150);
      EXPECT_EQ(le32(b, m + 148), v);
      EXPECT_EQ(le32(b, m + 152), 6506241u);
      size_t end = m + le32(b, m + 12);
      if (v >= 518) {
        EXPECT_FLOAT_EQ(f32(b, m + 156), 80);
        EXPECT_FLOAT_EQ(f32(b, m + 160), 120);
        EXPECT_EQ(le32(b, m + 196), 1u);  // displays
        EXPECT_EQ(le16(b, m + 204), 240);
        EXPECT_EQ(le16(b, m + 206), 160);
      }
      if (v >= 517) {
        const size_t sw = le32(b, kSoftwareAt);
        EXPECT_EQ(sw, end);
        EXPECT_EQ(text(b, sw, 32), "slicereuse");
        EXPECT_EQ(le32(b, sw + 32), 164u);
        const size_t md = le32(b, kModelAt);
        EXPECT_EQ(md, sw + 164);
        EXPECT_EQ(text(b, md, 12), "MODEL");
        EXPECT_EQ(le32(b, md + 12), 48u);
        // The 10 x 10 mm square around the origin, moved by the offset.
        const float model[6] = {-5 + 0.37f, -5 - 1.21f, 0, 5 + 0.37f, 5 - 1.21f, 5};
        for (size_t i = 0; i < 6; ++i) EXPECT_NEAR(f32(b, md + 16 + 4 * i), model[i], 1e-5) << i;
        end = md + 48;
      } else {
        EXPECT_EQ(le32(b, kSoftwareAt), 0u);
      }
      if (v >= 518) {
        const size_t sl = le32(b, kSubLayerDefAt);
        EXPECT_EQ(sl, end);
        EXPECT_EQ(text(b, sl, 12), "SUBIMGS");
        EXPECT_EQ(le32(b, sl + 12), 24u + 44 * 5);
        EXPECT_EQ(le32(b, sl + 16), 5u);
        EXPECT_EQ(le32(b, sl + 20), 1u);
        for (size_t k = 0; k < 5; ++k) {
          const size_t e = sl + 24 + 44 * k;
          EXPECT_EQ(le32(b, e), le32(b, entry(b, k)));
          EXPECT_EQ(le32(b, e + 4), le32(b, entry(b, k) + 4));
          EXPECT_EQ(le32(b, e + 8), le32(b, entry(b, k) + 24));
        }
        const size_t p2 = le32(b, kPreview2At);
        EXPECT_EQ(p2, sl + 24 + 44 * 5);
        EXPECT_EQ(text(b, p2, 12), "PREVIEW2");
        EXPECT_EQ(le32(b, p2 + 12), 28u + 320 * 190 * 2);
        EXPECT_EQ(le32(b, p2 + 16), 320u);
        EXPECT_EQ(le16(b, p2 + 20), 4293);
        EXPECT_EQ(le32(b, p2 + 24), 190u);
        end = p2 + 28 + 320 * 190 * 2;
      }
      EXPECT_EQ(le32(b, kLayerDataAt), end);
    }
  }
}

TEST_F(PhotonWorkshopFiles, AntialiasedFilesSayLevel16AndFillTheGreyTable) {
  PrinterProfile p = small_display();
  p.antialiasing = true;
  p.grey_levels = 16;
  export_masks(make_slices(part_layers()), p, path("aa.pwmb"));
  const std::string b = read_bytes(path("aa.pwmb"));
  EXPECT_EQ(le32(b, le32(b, kHeaderAt) + 56), 16u);
  const size_t c = le32(b, kColoursAt);
  const uint8_t grey[16] = {15, 31, 47, 63, 79, 95, 111, 127, 143, 159, 175, 191, 207, 223, 239, 255};
  for (size_t i = 0; i < 16; ++i) EXPECT_EQ(uint8_t(b[c + 8 + i]), grey[i]) << i;
}

TEST_F(PhotonWorkshopFiles, PreviewsAreTheTopViewsPictures) {
  PrinterProfile p = small_display();
  p.mirror_x = true;
  const Slices s = make_slices({{rect(-10, -10, 0, 10)}, {star(0.3, -0.2, 3, 7.5, 9)}});
  export_masks(s, p, path("v.pm5s"));
  TopView view(p, s.layers());
  for (size_t k = 0; k < s.layers(); ++k) view.add(LayerView(s, k), k);
  const std::string b = read_bytes(path("v.pm5s"));
  for (const auto& [at, width, height] : {std::make_tuple(le32(b, kPreviewAt), 224, 168),
                                          std::make_tuple(le32(b, kPreview2At), 320, 190)}) {
    const std::vector<uint16_t> expected = rgb565_preview(view.finish(), width, height);
    std::vector<uint16_t> got(expected.size());
    for (size_t i = 0; i < got.size(); ++i) got[i] = le16(b, at + 28 + 2 * i);
    EXPECT_TRUE(got == expected) << width;
    EXPECT_TRUE(std::any_of(got.begin(), got.end(), [](uint16_t x) { return x != 0; }));
  }
}

TEST_F(PhotonWorkshopFiles, CompareMaskStacksReadsThemAgainstFoldersAndGoo) {
  const Slices s = make_slices(part_layers());
  PrinterProfile p = mirrored_display();
  p.antialiasing = true;
  p.grey_levels = 16;
  export_masks(s, p, path("m.pm4n"));
  export_masks(s, p, path("m"));
  export_masks(s, p, path("m.goo"));
  for (const char* other : {"m", "m.goo", "m.pm4n"}) {
    const StackComparison c = compare_mask_stacks(path("m.pm4n"), path(other), "");
    EXPECT_EQ(c.layers.size(), s.layers());
    EXPECT_EQ(c.differing_pixels, 0u) << other;
  }
  // The format, not the name: a file that starts with "ANYCUBIC" under any name.
  fs::copy_file(path("m.pm4n"), path("m.bin"));
  EXPECT_EQ(compare_mask_stacks(path("m.bin"), path("m"), "").differing_pixels, 0u);
  std::vector<Layer> other = part_layers();
  other[0][0] = rect(-5, -5, 5, 5.3);
  export_masks(make_slices(other), p, path("o.pm4n"));
  EXPECT_GT(compare_mask_stacks(path("m.pm4n"), path("o.pm4n"), "").layers[0].differing_pixels, 0u);
}

TEST_F(PhotonWorkshopFiles, BadJobsAreRefusedInWordsBeforeAnythingIsWritten) {
  const Slices s = make_slices(part_layers());
  PrinterProfile p = small_display();
  p.portrait = true;
  EXPECT_ERROR(export_masks(s, p, path("p.pwmx")), "no portrait orientation");
  p = small_display();
  p.file_version = 517;
  EXPECT_ERROR(export_masks(s, p, path("v.pwmx")),
               "file version 517 is not one slicereuse writes for a .pwmx file (the Photon Mono X takes version 516)");
  p.file_version = 515;
  EXPECT_ERROR(export_masks(s, p, path("v.pm4n")), "file version 515 is not one slicereuse writes for a .pm4n file (the "
                                                   "Photon Mono 4 takes version 516, 517, 518)");
  p = small_display();
  p.exposure_s = 1e39;
  EXPECT_ERROR(export_masks(s, p, path("e.pm5")), "an exposure (exposure_s) of 1e+39 s, out of the range");
  p = small_display();
  p.bottom_exposure_s = 1e9;
  p.bottom_layers = 10;
  EXPECT_ERROR(export_masks(s, p, path("t.pm5")), "a print time of");
  // Straight to the writer: what a validated profile cannot ask for.
  int records = 0;
  const auto record = [&](size_t) -> const std::vector<uint8_t>& {
    ++records;
    static const std::vector<uint8_t> none;
    return none;
  };
  const auto summary = [] { return PhotonWorkshopSummary{}; };
  p = small_display();
  p.width_px = 70000;
  EXPECT_ERROR(write_photon_workshop(path("r.pwmx"), {p, 1, 0.05}, record, summary),
               "an image of 70000 x 200 pixels, beyond the 1..65535 pixels a side");
  EXPECT_ERROR(write_photon_workshop(path("l.pwmx"), {small_display(), 140000000, 0.05}, record, summary),
               "140000000 layers, more than the tables of a .pwmx file hold");
  EXPECT_ERROR(write_photon_workshop(path("x.ctb"), {small_display(), 1, 0.05}, record, summary),
               "its extension is none of .pwmx");
  EXPECT_EQ(records, 0);
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST_F(PhotonWorkshopFiles, AFailedWriteLeavesNothing) {
  // A layer that fails while the file is written (cancelled exports: test_print_formats.cpp).
  const PhotonWorkshopJob job{small_display(), 3, 0.05};
  EXPECT_ERROR(write_photon_workshop(
                   path("f.pm5s"), job,
                   [&](size_t k) -> const std::vector<uint8_t>& {
                     if (k == 2) throw Error("layer 2 failed");
                     static std::vector<uint8_t> record;
                     MaskRuns runs;
                     runs.width = 200;
                     runs.height = 200;
                     runs.row_begin.assign(201, 0);
                     encode_pw0_layer(job, k, runs, record);
                     return record;
                   },
                   [] { return PhotonWorkshopSummary{}; }),
               "layer 2 failed");
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST_F(PhotonWorkshopFiles, MaskStackRefusesTruncatedAndCorruptFilesInWords) {
  export_masks(make_slices(part_layers()), small_display(), path("a.pwmx"));
  const std::string bytes = read_bytes(path("a.pwmx"));
  const size_t defs = le32(bytes, kLayerDefAt), header = le32(bytes, kHeaderAt);
  const auto check = [&](const std::string& b, const std::string& message) {
    write_bytes(path("x.pwmx"), b);
    EXPECT_ERROR(MaskStack(path("x.pwmx")), message);
  };
  const auto set32 = [](std::string b, size_t at, uint32_t v) {
    for (size_t i = 0; i < 4; ++i) b[at + i] = char(v >> (8 * i));
    return b;
  };
  check(bytes.substr(0, 30), "x.pwmx' is truncated: it ends inside the file mark");
  check(bytes.substr(0, defs + 30), "is truncated: it ends inside the LAYERDEF table of 5 layers");
  check(bytes.substr(0, bytes.size() - 1), "is truncated: layer 4's data");
  check("ANYCUBIX" + bytes.substr(8), "is not an Anycubic Photon Workshop file: it does not begin with \"ANYCUBIC\"");
  check(set32(bytes, 12, 600), "is an Anycubic file of version 600, which is not one known");
  check(set32(bytes, kLayerDefAt, uint32_t(defs + 4)), "the file mark says the LAYERDEF table is at byte");
  check(set32(bytes, kHeaderAt, 0), "the file mark says the HEADER table is at byte 0, but it is not there");
  check(set32(bytes, defs + 16, 4), "its LAYERDEF table is 164 bytes long, but 4 layers take 132");
  // A layer count the file cannot hold, with a length to match: refused before any allocation.
  check(set32(set32(bytes, defs + 16, 100000000), defs + 12, 4 + 32 * 100000000u),
        "is truncated: it ends inside the LAYERDEF table of 100000000 layers");
  check(set32(set32(bytes, header + 60, 70000), header + 64, 70000), "has images of 70000 x 70000 pixels");
  check(set32(bytes, entry(bytes, 2) + 4, 1u << 30), "is truncated: layer 2's data (1073741824 bytes at byte");
  check(set32(set32(bytes, defs + 16, 0), defs + 12, 4), "holds no layers");
  EXPECT_ERROR(MaskStack(path("missing.pm5s")), "does not exist");

  // Runs that make too many or too few pixels, and one cut off.
  const auto decode_error = [&](const std::vector<uint8_t>& data) {
    MaskImage image;
    return test::error_of([&] { decode_pw0_layer(data.data(), data.size(), 200, 200, "f.pwmx: layer 1", image); });
  };
  EXPECT_NE(decode_error({0x9F, 0x9C, 0x0F, 0xFF}).find("cannot make the 200 x 200 pixels"), std::string::npos);
  std::vector<uint8_t> runs;
  for (int i = 0; i < 10; ++i) runs.insert(runs.end(), {0x0F, 0xA0});  // 10 x 4000 black: the image
  MaskImage image;
  decode_pw0_layer(runs.data(), runs.size(), 200, 200, "f", image);
  EXPECT_EQ(std::count(image.pixels.begin(), image.pixels.end(), 0), 40000);
  runs.push_back(0x11);
  EXPECT_NE(decode_error(runs).find("'f.pwmx: layer 1' is corrupt: its runs make more than the 200 x 200 pixels"),
            std::string::npos);
  runs.pop_back();
  runs.back() = 0x9F;  // 3999 in the last run
  EXPECT_NE(decode_error(runs).find("its runs make 39999 of the 40000 pixels"), std::string::npos);
  std::vector<uint8_t> cut;
  for (int i = 0; i < 9; ++i) cut.insert(cut.end(), {0x0F, 0xFF});
  cut.insert(cut.end(), {0x9F, 0x0F});
  EXPECT_NE(decode_error(cut).find("its last run is cut off"), std::string::npos);
}
