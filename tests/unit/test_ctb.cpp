// Chitubox .ctb export, versions 3 and 4: every layer, read back through MaskStack, equals
// rasterize_layer's pixels (binary, 128 grey levels, 256 levels folded to the format's codes,
// encrypted or not); the header, tables and previews carry the profile and the job; hand-encoded
// runs; atomic writes and refusals in words; MaskStack's .ctb reading and its errors.
// (The reader written from the format's documentation alone, to check the writer against, is
// another's work.)
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <ctime>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <tuple>
#include <vector>

#include "ctb_writer.h"
#include "error_of.h"
#include "mask_layers.h"
#include "print_file_tests.h"
#include "mask_stack.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/printfiles/compare_mask_stacks.h"
#include "slicereuse/printfiles/export_masks.h"
#include "slicereuse/raster/rasterize_layer.h"
#include "slicereuse/raster/top_view.h"
#include "slicereuse/util/error.h"
#include "temp_folder.h"
#include "thumbnail_png.h"

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

// The fixed sections' places, from the documentation's sizes: header 112, large preview header
// 32 and its place of 2 bytes a pixel, the small one's, print parameters 60, slicer info 76.
constexpr size_t kLargeAt = 112, kSmallAt = kLargeAt + 32 + 2 * 400 * 300,
                 kParametersAt = kSmallAt + 32 + 2 * 200 * 125,
                 kSlicerAt = kParametersAt + 60, kNameAt = kSlicerAt + 76;

void put32(std::string& b, size_t at, uint32_t v) {
  for (size_t i = 0; i < 4; ++i) b[at + i] = char(v >> (8 * i));
}

// A .ctb level: the code level >> 1 decoded as 0 or 2c + 1.
uint8_t ctb_level(uint8_t level) { return level < 2 ? 0 : uint8_t((level >> 1) * 2 + 1); }

void expect_layers_equal_the_masks(const std::string& path, const Slices& s, const PrinterProfile& p) {
  const std::vector<MaskImage> images = read_stack(path);
  ASSERT_EQ(images.size(), s.layers());
  const MaskImageLayout m = mask_image_layout(p);
  for (size_t k = 0; k < s.layers(); ++k) {
    std::vector<uint8_t> expected = raster(s, k, p);
    for (uint8_t& v : expected) v = ctb_level(v);
    EXPECT_EQ(images[k].width, m.width);
    EXPECT_EQ(images[k].height, m.height);
    EXPECT_TRUE(images[k].pixels == expected) << path << " layer " << k;
  }
}

// write_ctb of a stack's masks, as export does, with the given key.
void write_stack(const std::string& path, const Slices& s, const PrinterProfile& p, uint32_t key) {
  const CtbJob job{p, s.layers(), s.thickness, key};
  std::vector<std::vector<uint8_t>> data(s.layers());
  TopView top_view(p, s.layers());
  for (size_t k = 0; k < s.layers(); ++k) {
    MaskRuns runs;
    if (p.antialiasing)
      rasterize_layer_antialiased_runs(LayerView(s, k), p, runs);
    else
      rasterize_layer_runs(LayerView(s, k), p, runs);
    top_view.add(LayerView(s, k), k);
    encode_ctb_layer(job, k, runs, data[k]);
  }
  write_ctb(path, job, [&](size_t k) -> const std::vector<uint8_t>& { return data[k]; },
            [&] {
              return CtbSummary{0, rgb565_preview(top_view.finish(), 400, 300),
                                rgb565_preview(top_view.finish(), 200, 125)};
            });
}

// The layer table's entry k: where its data lies and how long it is.
std::pair<size_t, size_t> layer_data(const std::string& b, size_t k) {
  const size_t d = le32(b, 64) + 36 * k;
  return {le32(b, d + 12), le32(b, d + 16)};
}

// A preview's RGB565 pixels from its run-length words (a run word: the colour with bit 5 set,
// then 0x3000 | (count - 1)).
std::vector<uint16_t> decode_preview(const std::string& b, size_t header_at) {
  const size_t at = le32(b, header_at + 8), size = le32(b, header_at + 12);
  std::vector<uint16_t> pixels;
  for (size_t i = at; i < at + size; i += 2) {
    const uint16_t v = le16(b, i);
    size_t n = 1;
    if (v & 0x20) {
      i += 2;
      EXPECT_EQ(le16(b, i) & 0xF000, 0x3000);
      n += le16(b, i) & 0xFFF;
    }
    pixels.insert(pixels.end(), n, uint16_t(v & ~0x20));
  }
  return pixels;
}

class CtbFiles : public test::TempFolderTest {};

}  // namespace

TEST_F(CtbFiles, EveryLayerReadsBackAsTheMaskVersions3And4BinaryAndAntialiased) {
  const Slices s = make_slices(part_layers());
  for (PrinterProfile p : {small_display(), mirrored_display()})
    for (int version : {3, 4, 0})
      for (bool aa : {false, true}) {
        p.file_version = version;
        p.antialiasing = aa;
        p.grey_levels = aa ? 128 : 256;
        export_masks(s, p, path("part.ctb"));
        const std::string b = read_bytes(path("part.ctb"));
        EXPECT_EQ(le32(b, 4), uint32_t(version == 0 ? 4 : version));
        expect_layers_equal_the_masks(path("part.ctb"), s, p);
        // Anti-aliased layers hold grey levels (the thin wall is half a pixel wide), all of them
        // levels the file holds: the 128-level raster is what it decodes to.
        const std::vector<uint8_t> wall = raster(s, 1, p);
        EXPECT_EQ(std::any_of(wall.begin(), wall.end(), [](uint8_t v) { return v != 0 && v != 255; }), aa);
        for (uint8_t v : wall) ASSERT_EQ(ctb_level(v), v);
      }
}

TEST_F(CtbFiles, Levels256AreExportedAsTheNearestLevelsTheFileHolds) {
  // A 256-level anti-aliased profile: export draws the masks with the 128 levels a .ctb holds
  // (grey_levels.h), each stored as its code level >> 1 and read back as 0 or 2c + 1.
  const Slices s = make_slices(part_layers());
  PrinterProfile p = small_display();
  p.antialiasing = true;
  ASSERT_EQ(p.grey_levels, 256);
  export_masks(s, p, path("grey.ctb"));
  PrinterProfile held = p;
  held.grey_levels = 128;
  expect_layers_equal_the_masks(path("grey.ctb"), s, held);
  const std::vector<uint8_t> wall = raster(s, 1, p);
  EXPECT_TRUE(std::any_of(wall.begin(), wall.end(), [](uint8_t v) { return ctb_level(v) != v; }));
}

TEST_F(CtbFiles, PortraitImagesAreWrittenAsTheLayoutGivesThem) {
  const Slices s = make_slices(part_layers());
  PrinterProfile p = mirrored_display();
  p.portrait = true;
  export_masks(s, p, path("portrait.ctb"));
  const std::string b = read_bytes(path("portrait.ctb"));
  EXPECT_EQ(le32(b, 52), 160u);
  EXPECT_EQ(le32(b, 56), 240u);
  EXPECT_FLOAT_EQ(f32(b, 8), 160 * 0.12f);
  EXPECT_FLOAT_EQ(f32(b, 12), 240 * 0.08f);
  expect_layers_equal_the_masks(path("portrait.ctb"), s, p);
}

TEST_F(CtbFiles, EncryptedLayersReadBackWithTheHeadersKey) {
  const Slices s = make_slices(part_layers());
  for (int version : {3, 4})
    for (bool aa : {false, true}) {
      PrinterProfile p = mirrored_display();
      p.file_version = version;
      p.antialiasing = aa;
      p.grey_levels = 128;
      write_stack(path("plain.ctb"), s, p, 0);
      write_stack(path("secret.ctb"), s, p, 0x5EC2E7u);
      expect_layers_equal_the_masks(path("plain.ctb"), s, p);
      expect_layers_equal_the_masks(path("secret.ctb"), s, p);
      const std::string plain = read_bytes(path("plain.ctb")), secret = read_bytes(path("secret.ctb"));
      EXPECT_EQ(le32(plain, 100), 0u);
      EXPECT_EQ(le32(secret, 100), 0x5EC2E7u);
      ASSERT_EQ(plain.size(), secret.size());
      for (size_t k = 0; k < s.layers(); ++k) {
        const auto [at, size] = layer_data(plain, k);
        EXPECT_EQ(layer_data(secret, k), std::make_pair(at, size));
        // Byte i of layer k is XORed with byte i % 4 of word i / 4 of the key stream, which
        // starts at (k * 0x1E1530CD + 0xEC3D47CD) * c and steps by c = key * 0x2D83CDAC + 0xD8A83423.
        const uint32_t c = 0x5EC2E7u * 0x2D83CDACu + 0xD8A83423u;
        uint32_t word = (uint32_t(k) * 0x1E1530CDu + 0xEC3D47CDu) * c;
        for (size_t i = 0; i < size; ++i) {
          ASSERT_EQ(uint8_t(secret[at + i]), uint8_t(plain[at + i] ^ uint8_t(word >> (8 * (i % 4))))) << k << ", " << i;
          if (i % 4 == 3) word += c;
        }
      }
    }
}

TEST_F(CtbFiles, RunsAreEncodedAsTheFormatSays) {
  // One layer of 60000 x 80 pixels given as runs. Row 0: 255 (one pixel), 200 x 2, 254 x 127
  // and 255 x 1 (the same code 127: one run of 128), 101 x 0x3FFF, 1 (code 0: with the black
  // after it) up to row 35's column 13665, 0x1FFFFF pixels of code 0; then 255 for 0x200000
  // pixels, to row 70's column 10817; black to the end (589183 pixels).
  MaskRuns runs;
  runs.width = 60000;
  runs.height = 80;
  const auto row = [&](std::vector<std::array<int, 3>> row_runs) {
    for (const auto& [c0, c1, v] : row_runs) {
      runs.columns.push_back(uint16_t(c0));
      runs.columns.push_back(uint16_t(c1));
      runs.levels.push_back(uint8_t(v));
    }
    runs.row_begin.push_back(uint32_t(runs.levels.size()));
  };
  runs.row_begin.push_back(0);
  row({{0, 1, 255}, {1, 3, 200}, {3, 130, 254}, {130, 131, 255}, {131, 131 + 0x3FFF, 101}, {16514, 16515, 1}});
  for (int r = 1; r < 35; ++r) row({});
  row({{13665, 60000, 255}});
  for (int r = 36; r < 70; ++r) row({{0, 60000, 255}});
  row({{0, 10817, 255}});
  for (int r = 71; r < 80; ++r) row({});

  PrinterProfile p;
  p.width_px = 60000;
  p.height_px = 80;
  const CtbJob job{p, 1, 0.05};
  std::vector<uint8_t> data;
  encode_ctb_layer(job, 0, runs, data);
  const std::vector<uint8_t> expected = {0x7F,                          // 127 alone
                                         0xE4, 0x02,                    // code 100 x 2
                                         0xFF, 0x80, 0x80,              // code 127 x 128
                                         0xB2, 0xBF, 0xFF,              // code 50 x 0x3FFF
                                         0x80, 0xDF, 0xFF, 0xFF,        // code 0 x 0x1FFFFF
                                         0xFF, 0xE0, 0x20, 0x00, 0x00,  // code 127 x 0x200000
                                         0x80, 0xC8, 0xFD, 0x7F};       // code 0 x 589183
  EXPECT_EQ(data, expected);
  write_ctb(path("runs.ctb"), job, [&](size_t) -> const std::vector<uint8_t>& { return data; },
            [] { return CtbSummary{0, std::vector<uint16_t>(400 * 300), std::vector<uint16_t>(200 * 125)}; });
  std::vector<uint8_t> pixels(size_t(60000) * 80, 0);
  for (size_t r = 0; r < 80; ++r)
    for (uint32_t i = runs.row_begin[r]; i < runs.row_begin[r + 1]; ++i)
      std::fill(pixels.begin() + long(r * 60000 + runs.columns[2 * i]),
                pixels.begin() + long(r * 60000 + runs.columns[2 * i + 1]), ctb_level(runs.levels[i]));
  const std::vector<MaskImage> images = read_stack(path("runs.ctb"));
  ASSERT_EQ(images.size(), 1u);
  EXPECT_EQ(images[0].width, 60000);
  EXPECT_EQ(images[0].height, 80);
  EXPECT_TRUE(images[0].pixels == pixels);
}

TEST_F(CtbFiles, ARunLongerThan28BitsIsSplit) {
  // 16384 x 16384 black pixels: 2^28, one more than a run holds.
  MaskRuns runs;
  runs.width = runs.height = 16384;
  runs.row_begin.assign(16385, 0);
  PrinterProfile p;
  p.width_px = p.height_px = 16384;
  std::vector<uint8_t> data;
  encode_ctb_layer(CtbJob{p, 1, 0.05}, 0, runs, data);
  EXPECT_EQ(data, (std::vector<uint8_t>{0x80, 0xEF, 0xFF, 0xFF, 0xFF, 0x00}));
}

TEST_F(CtbFiles, TheHeaderAndTablesCarryTheProfileAndTheJob) {
  // 1 mm layers: a 10 x 10 mm square, then the same square with a 4 x 4 mm hole: 184 mm^3; then
  // three empty layers.
  const Slices s = make_slices({{rect(-5, -5, 5, 5)}, {rect(-5, -5, 5, 5), rect(-2, -2, 2, 2, true)}, {}, {}, {}}, 1.0);
  for (int version : {3, 4}) {
    PrinterProfile p = mirrored_display();
    p.mirror_y = false;
    p.file_version = version;
    p.exposure_s = 2;
    p.bottom_exposure_s = 20;
    p.bottom_layers = 1;
    p.faded_layers = 3;
    p.layer_move_s = 20;
    p.bottom_lift_mm = 7;
    p.lift_mm = 4;
    p.bottom_lift_speed_mm_min = 40;
    p.lift_speed_mm_min = 60;
    p.bottom_retract_speed_mm_min = 100;
    p.retract_speed_mm_min = 120;
    p.bottom_light_off_s = 1.5;
    p.light_off_s = 0.5;
    p.printer_model = "ELEGOO MARS";
    export_masks(s, p, path("h.ctb"));
    const std::string b = read_bytes(path("h.ctb"));
    // The light-off delays: what brings the moves up to 20 s, longer than each light-off.
    const float bottom_off = 20 - 60 * (7.0f / 40 + 7.0f / 100), off = 20 - 60 * (4.0f / 60 + 4.0f / 120);
    const size_t v4_at = kNameAt + 11 + 320, table_at = version == 4 ? v4_at + 464 : kNameAt + 11;
    SCOPED_TRACE(version);
    // Header.
    EXPECT_EQ(le32(b, 0), version == 4 ? 0x12FD0106u : 0x12FD0086u);  // as Chitubox writes each version
    EXPECT_EQ(le32(b, 4), uint32_t(version));
    EXPECT_FLOAT_EQ(f32(b, 8), 19.2f);
    EXPECT_FLOAT_EQ(f32(b, 12), 19.2f);
    EXPECT_FLOAT_EQ(f32(b, 16), 150.0f);
    EXPECT_EQ(le32(b, 20), 0u);
    EXPECT_EQ(le32(b, 24), 0u);
    EXPECT_FLOAT_EQ(f32(b, 28), 5.0f);
    EXPECT_FLOAT_EQ(f32(b, 32), 1.0f);
    EXPECT_FLOAT_EQ(f32(b, 36), 2.0f);
    EXPECT_FLOAT_EQ(f32(b, 40), 20.0f);
    EXPECT_FLOAT_EQ(f32(b, 44), off);
    EXPECT_EQ(le32(b, 48), 1u);
    EXPECT_EQ(le32(b, 52), 240u);
    EXPECT_EQ(le32(b, 56), 160u);
    EXPECT_EQ(le32(b, 60), kLargeAt);
    EXPECT_EQ(le32(b, 64), table_at);
    EXPECT_EQ(le32(b, 68), 5u);
    EXPECT_EQ(le32(b, 72), kSmallAt);
    EXPECT_EQ(le32(b, 76), 155u);  // 55 s of exposure and 5 layers of 20 s
    EXPECT_EQ(le32(b, 80), 1u);    // mirrored
    EXPECT_EQ(le32(b, 84), kParametersAt);
    EXPECT_EQ(le32(b, 88), 60u);
    EXPECT_EQ(le32(b, 92), 1u);
    EXPECT_EQ(le16(b, 96), 255);
    EXPECT_EQ(le16(b, 98), 255);
    EXPECT_EQ(le32(b, 100), 0u);
    EXPECT_EQ(le32(b, 104), kSlicerAt);
    EXPECT_EQ(le32(b, 108), 76u);
    // Previews' headers.
    EXPECT_EQ(le32(b, kLargeAt), 400u);
    EXPECT_EQ(le32(b, kLargeAt + 4), 300u);
    EXPECT_EQ(le32(b, kLargeAt + 8), kLargeAt + 32);
    EXPECT_EQ(le32(b, kSmallAt), 200u);
    EXPECT_EQ(le32(b, kSmallAt + 4), 125u);
    EXPECT_EQ(le32(b, kSmallAt + 8), kSmallAt + 32);
    // Print parameters.
    const float parameters[] = {7, 40, 4, 60, 120, 0.184f, 0.184f * 1.1f, 0, bottom_off, off};
    for (size_t i = 0; i < std::size(parameters); ++i)
      EXPECT_FLOAT_EQ(f32(b, kParametersAt + 4 * i), parameters[i]) << i;
    EXPECT_EQ(le32(b, kParametersAt + 40), 1u);
    // Slicer info.
    const float second_stages[] = {0, 40, 0, 60, 0, 120, 0};
    for (size_t i = 0; i < std::size(second_stages); ++i)
      EXPECT_FLOAT_EQ(f32(b, kSlicerAt + 4 * i), second_stages[i]) << i;
    EXPECT_EQ(le32(b, kSlicerAt + 28), kNameAt);
    EXPECT_EQ(le32(b, kSlicerAt + 32), 11u);
    EXPECT_EQ(b.substr(kNameAt, 11), "ELEGOO MARS");
    EXPECT_EQ(uint8_t(b[kSlicerAt + 36]), 0x07);  // binary
    EXPECT_EQ(uint8_t(b[kSlicerAt + 39]), version * 0x10);
    EXPECT_NEAR(double(le32(b, kSlicerAt + 40)), double(std::time(nullptr) / 60), 2);
    EXPECT_EQ(le32(b, kSlicerAt + 44), 1u);
    EXPECT_EQ(le32(b, kSlicerAt + 48), version == 4 ? 0x01090000u : 0x01060300u);
    EXPECT_EQ(le32(b, kSlicerAt + 60), 3u);
    EXPECT_EQ(le32(b, kSlicerAt + 64), version == 4 ? v4_at : 0u);
    if (version == 4) {
      EXPECT_EQ(b.substr(kNameAt + 11, 34), "Layout and record format for the c");
      EXPECT_FLOAT_EQ(f32(b, v4_at), 100.0f);
      EXPECT_FLOAT_EQ(f32(b, v4_at + 12), 4.0f);
      EXPECT_FLOAT_EQ(f32(b, v4_at + 20), 4.0f);
      EXPECT_EQ(le32(b, v4_at + 48), 5u);
      EXPECT_EQ(le32(b, v4_at + 52), 4u);  // the last layer
      EXPECT_EQ(le32(b, v4_at + 72), kNameAt + 11);
      EXPECT_EQ(le32(b, v4_at + 76), 320u);
    }
    // The layer table and each layer's extended definition right before its data.
    const float exposures[5] = {20, 15.5, 11, 6.5, 2};
    size_t next = table_at + 5 * 36;
    for (size_t k = 0; k < 5; ++k) {
      const size_t d = table_at + 36 * k;
      const auto [at, size] = layer_data(b, k);
      EXPECT_EQ(at, next + 84) << k;
      next = at + size;
      EXPECT_FLOAT_EQ(f32(b, d), float(k + 1)) << k;
      EXPECT_FLOAT_EQ(f32(b, d + 4), exposures[k]) << k;
      EXPECT_FLOAT_EQ(f32(b, d + 8), k == 0 ? bottom_off : off) << k;
      EXPECT_EQ(le32(b, d + 20), 0u);   // page
      EXPECT_EQ(le32(b, d + 24), 84u);  // table size
      EXPECT_EQ(b.substr(at - 84, 36), b.substr(d, 36)) << k;
      EXPECT_EQ(le32(b, at - 84 + 36), 84 + size) << k;
      const bool v4 = version == 4;
      const float bottom[] = {7, 40, 0, v4 ? 40.0f : 0, 100, 0, v4 ? 100.0f : 0, 0, 0, 0, 255};
      const float other[] = {4, 60, 0, v4 ? 60.0f : 0, 120, 0, v4 ? 120.0f : 0, 0, 0, 0, 255};
      for (size_t i = 0; i < 11; ++i)
        EXPECT_FLOAT_EQ(f32(b, at - 84 + 40 + 4 * i), (k == 0 ? bottom : other)[i]) << k << ", " << i;
    }
    EXPECT_EQ(next, b.size());
  }
}

TEST_F(CtbFiles, PreviewsShowWhereThePartStands) {
  // The previews are the top view's, run-length encoded; anti-aliasing sets the flag and level.
  const Slices s = make_slices({{rect(-10, -10, 0, 10)}, {star(0.3, -0.2, 3, 7.5, 9)}});
  PrinterProfile p = mirrored_display();
  p.antialiasing = true;
  p.grey_levels = 128;
  export_masks(s, p, path("v.ctb"));
  const std::string b = read_bytes(path("v.ctb"));
  TopView view(p, s.layers());
  for (size_t k = 0; k < s.layers(); ++k) view.add(LayerView(s, k), k);
  for (const auto& [at, w, h] : {std::make_tuple(kLargeAt, 400, 300), std::make_tuple(kSmallAt, 200, 125)}) {
    std::vector<uint16_t> expected = rgb565_preview(view.finish(), w, h);
    for (uint16_t& v : expected) v &= uint16_t(~0x20);
    const std::vector<uint16_t> got = decode_preview(b, at);
    EXPECT_TRUE(got == expected) << w;
    EXPECT_LT(le32(b, at + 12), size_t(w) * size_t(h) / 4) << w;  // runs, not pixels
  }
  EXPECT_EQ(uint8_t(b[kSlicerAt + 36]), 0x0F);
  EXPECT_EQ(le32(b, kSlicerAt + 44), 8u);
}

TEST_F(CtbFiles, CompareMaskStacksReadsCtbAgainstFoldersAndOtherFiles) {
  const Slices s = make_slices(part_layers());
  PrinterProfile p = mirrored_display();
  p.antialiasing = true;
  p.grey_levels = 128;
  export_masks(s, p, path("m.ctb"));
  export_masks(s, p, path("m"));
  export_masks(s, p, path("m.goo"));
  for (const char* other : {"m", "m.goo"}) {
    const StackComparison c = compare_mask_stacks(path("m.ctb"), path(other), "");
    EXPECT_EQ(c.layers.size(), s.layers());
    EXPECT_EQ(c.differing_pixels, 0u) << other;
  }
  // The format, not the name.
  fs::copy_file(path("m.ctb"), path("m.bin"));
  EXPECT_EQ(compare_mask_stacks(path("m.ctb"), path("m.bin"), "").differing_pixels, 0u);
}

TEST_F(CtbFiles, MaskStackRefusesTruncatedAndCorruptFilesInWords) {
  export_masks(make_slices(part_layers()), small_display(), path("a.ctb"));
  const std::string bytes = read_bytes(path("a.ctb"));
  const auto [at1, size1] = layer_data(bytes, 1);
  const size_t table_at = le32(bytes, 64);
  const auto check = [&](const std::string& b, const std::string& message) {
    write_bytes(path("x.ctb"), b);
    EXPECT_ERROR(MaskStack(path("x.ctb")), message);
  };
  check(bytes.substr(0, 50), "is truncated: it ends inside the header");
  check(bytes.substr(0, table_at + 100), "its layer table (5 layers of 36 bytes at byte " + std::to_string(table_at) +
                                             ") does not lie within the file's " + std::to_string(table_at + 100));
  check(bytes.substr(0, at1 + 3), "layer 1's image data (" + std::to_string(size1) + " bytes at byte " +
                                      std::to_string(at1) + ") runs past the end of the file");
  std::string b = bytes;
  b[0] = 0;
  check(b, "is not a .ctb file: its first 4 bytes are not the magic 86 00 FD 12");
  put32(b, 0, 0x12FD0107);
  check(b, "is an encrypted .ctb (magic 12FD0107, the closed scheme of newer Chitu boards), which is not read");
  put32(b, 0, 0x12FD0019);
  check(b, "is a .cbddlp/.photon file");
  b = bytes;
  put32(b, 68, 0);
  check(b, "holds no layers");
  b = bytes;
  put32(b, 52, 20000);
  put32(b, 56, 20000);
  check(b, "has images of 20000 x 20000 pixels, which is not within 1..268435456 pixels");
  b = bytes;
  put32(b, table_at + 36 + 20, 1);  // layer 1 on page 1: beyond 4 GB
  check(b, "layer 1's image data");

  // Decoding: a run length of no known form, one cut off, too many and too few pixels.
  const auto decode = [&](const std::string& b, const std::string& message) {
    write_bytes(path("y.ctb"), b);
    MaskStack stack(path("y.ctb"));
    std::vector<uint8_t> data;
    MaskImage image;
    stack.read(1, data);
    EXPECT_ERROR(stack.decode(1, data, image), message);
  };
  b = bytes;
  b[at1] = char(0x80);
  b[at1 + 1] = char(0xF3);
  decode(b, "y.ctb: layer 1' is corrupt: a run length begins with the byte F3, of no known form");
  b = bytes;
  put32(b, table_at + 36 + 16, uint32_t(size1 - 1));  // the last run length loses its last byte
  decode(b, "y.ctb: layer 1' is corrupt: its last run length is cut off by the data's end");
  b = bytes;
  put32(b, 52, 100);  // 100 x 200: the layers' runs make more
  decode(b, "its runs make more than the 100 x 200 pixels of the image");
  b = bytes;
  put32(b, 52, 300);
  decode(b, "its runs make 40000 of the 60000 pixels of the image");
  EXPECT_ERROR(MaskStack(path("missing.ctb")), "does not exist");
}

TEST_F(CtbFiles, RefusalsInWordsBeforeAnythingIsWritten) {
  const Slices s = make_slices(part_layers());
  const auto refused = [&](PrinterProfile p, const std::string& message) {
    EXPECT_ERROR(export_masks(s, p, path("r.ctb")), message);
    EXPECT_TRUE(fs::is_empty(dir));
  };
  PrinterProfile p = small_display();
  p.file_version = 5;
  refused(p, "cannot write '" + path("r.ctb") +
                 "': .ctb version 5 is the encrypted CTB of newer Chitu boards, whose closed scheme is not written");
  p.file_version = 2;
  refused(p, "there is no .ctb version 2 to write: choose 3 or 4");
  p = small_display();
  p.exposure_s = 1e39;
  refused(p, "the exposure is 1e+39, beyond the range of a .ctb's float fields");
  p = small_display();
  p.bottom_retract_speed_mm_min = 5e38;
  refused(p, "the bottom retract speed is 5e+38, beyond the range");
  p = small_display();
  p.width_px = p.height_px = 16385;
  refused(p, "images of 16385 x 16385 pixels, more than the 268435456 pixels");
  p = small_display();
  p.layer_move_s = 1e9;
  refused(p, "a print time of 5e+09 s, more than a .ctb's print time holds");
  // write_ctb itself: no layers, more than a .ctb holds.
  EXPECT_ERROR(write_ctb(path("w.ctb"), CtbJob{small_display(), 0, 0.1}, {}, {}), "the stack has no layers");
  EXPECT_ERROR(write_ctb(path("w.ctb"), CtbJob{small_display(), size_t(1) << 32, 0.1}, {}, {}),
               "4294967296 layers, more than a .ctb holds (4294967295)");
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST_F(CtbFiles, AFailedWriteLeavesNothing) {
  const Slices s = make_slices(std::vector<Layer>(300, Layer{star(0.3, -0.2, 3, 7.5, 9)}));
  const CtbJob job{small_display(), 3, 0.1};
  const std::vector<uint8_t> data = {0x80, 0xC0 | 0x00, 0x9C, 0x40};  // 40000 black pixels
  EXPECT_ERROR(write_ctb(path("f.ctb"), job,
                         [&](size_t k) -> const std::vector<uint8_t>& {
                           if (k == 2) throw Error("layer 2 failed");
                           return data;
                         },
                         [] { return CtbSummary{}; }),
               "layer 2 failed");
  EXPECT_ERROR(write_ctb(path("f.ctb"), job, [&](size_t) -> const std::vector<uint8_t>& { return data; },
                         [] { return CtbSummary{0, {}, {}}; }),
               ".ctb writer: a preview image of 0 pixels, expected 400 x 300");
  EXPECT_TRUE(fs::is_empty(dir));  // cancelled exports: test_print_formats.cpp
}

