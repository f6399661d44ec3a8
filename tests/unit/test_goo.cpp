// Elegoo .goo export: every layer, read back by a reader written from Elegoo's specification
// (tests/support/goo_reader.h), equals rasterize_layer's pixels; the header carries the profile;
// hand-encoded chunks; previews; checksums; atomic writes; ranges of layers; and MaskStack's own
// .goo reading (compare_mask_stacks) with its errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "error_of.h"
#include "goo_reader.h"
#include "goo_writer.h"
#include "mask_layers.h"
#include "print_file_tests.h"
#include "mask_stack.h"
#include "slicereuse/printer/printer_presets.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/printfiles/compare_mask_stacks.h"
#include "slicereuse/printfiles/export_masks.h"
#include "slicereuse/raster/rasterize_layer.h"
#include "slicereuse/util/error.h"
#include "temp_folder.h"

namespace fs = std::filesystem;
using namespace slicereuse;

namespace {

using test::Layer;
using test::Loop;
using test::make_slices;
using test::mirrored_display;
using test::raster;
using test::part_layers;
using test::read_bytes;
using test::rect;
using test::write_bytes;
using test::small_display;
using test::star;

constexpr size_t kHeaderBytes = 195477;  // the specification's fields, added up

uint32_t be32(const std::string& b, size_t at) {
  uint32_t v = 0;
  for (size_t i = 0; i < 4; ++i) v = v << 8 | uint8_t(b[at + i]);
  return v;
}

// Where layer k's image data (0x55 ... checksum) lies in a .goo file's bytes, and its size.
std::pair<size_t, size_t> layer_data(const std::string& b, size_t k) {
  size_t at = kHeaderBytes;
  for (size_t i = 0;; ++i) {
    const size_t size = be32(b, at + 66);
    if (i == k) return {at + 70, size};
    at += 70 + size + 2;
  }
}

// Every layer of the file, read by the specification's reader, equals rasterize_layer's image.
void expect_layers_equal_the_masks(const test::SpecGoo& g, const Slices& s, const PrinterProfile& p) {
  ASSERT_EQ(g.layers.size(), s.layers());
  for (size_t k = 0; k < s.layers(); ++k) EXPECT_TRUE(g.layers[k].pixels == raster(s, k, p)) << "layer " << k;
}

class GooFiles : public test::TempFolderTest {
 protected:
  test::SpecGoo export_and_read(const Slices& s, const PrinterProfile& p, const std::string& name = "part.goo") {
    export_masks(s, p, path(name));
    return test::read_goo_per_spec(read_bytes(path(name)));
  }
};

}  // namespace

TEST_F(GooFiles, EveryLayerReadsBackAsTheMaskBinaryAndAntialiasedLandscapeAndMirrored) {
  const Slices s = make_slices(part_layers());
  for (PrinterProfile p : {small_display(), mirrored_display()})
    for (bool aa : {false, true}) {
      p.antialiasing = aa;
      const test::SpecGoo g = export_and_read(s, p);
      expect_layers_equal_the_masks(g, s, p);
      EXPECT_EQ(g.x_mirror, p.mirror_x);
      EXPECT_EQ(g.y_mirror, p.mirror_y);
      // Anti-aliased layers hold grey levels (the thin wall is half a pixel wide).
      const std::vector<uint8_t>& wall = g.layers[1].pixels;
      EXPECT_EQ(std::any_of(wall.begin(), wall.end(), [](uint8_t v) { return v != 0 && v != 255; }), aa);
    }
}

TEST_F(GooFiles, TheSaturn3UltraPresetOnASmallPart) {
  // 11520 x 5120 pixels of 19 x 24 um, anti-aliased as the preset says, and binary.
  const Slices s = make_slices({{star(0.3, -0.2, 3, 7.5, 9), rect(-1, -1, 1, 1, true)},
                                {rect(-6, -6, 6, 6), rect(-5.985, -5.985, 5.985, 5.985, true)}},
                               0.05);
  PrinterProfile p = printer_preset("elegoo_saturn_3_ultra").profile;
  for (bool aa : {true, false}) {
    p.antialiasing = aa;
    const test::SpecGoo g = export_and_read(s, p);
    EXPECT_EQ(g.x_resolution, 11520);
    EXPECT_EQ(g.y_resolution, 5120);
    EXPECT_FLOAT_EQ(g.x_size, 218.88f);
    EXPECT_FLOAT_EQ(g.y_size, 122.88f);
    EXPECT_EQ(g.antialiasing_level, aa ? 8 : 1);
    expect_layers_equal_the_masks(g, s, p);
  }
}

TEST_F(GooFiles, TheHeaderCarriesTheProfileAndTheJob) {
  // 1 mm layers: a 10 x 10 mm square, then the same square with a 4 x 4 mm hole: 184 mm^3; then
  // three empty layers.
  const Slices s = make_slices({{rect(-5, -5, 5, 5)}, {rect(-5, -5, 5, 5), rect(-2, -2, 2, 2, true)}, {}, {}, {}}, 1.0);
  PrinterProfile p = mirrored_display();
  p.mirror_y = false;
  p.exposure_s = 2;
  p.bottom_exposure_s = 20;
  p.bottom_layers = 1;
  p.faded_layers = 3;
  p.layer_move_s = 8;
  p.printer_model = "Saturn";
  const test::SpecGoo g = export_and_read(s, p);
  EXPECT_EQ(g.version, "V3.0");
  EXPECT_EQ(g.software, "slicereuse");
  EXPECT_EQ(g.printer_name, "Saturn");
  EXPECT_EQ(g.file_time.size(), 19u);  // YYYY-MM-DD HH:MM:SS
  EXPECT_EQ(g.small_preview.size(), 116u * 116u);
  EXPECT_EQ(g.big_preview.size(), 290u * 290u);
  EXPECT_EQ(g.layer_count, 5u);
  EXPECT_EQ(g.x_resolution, 240);
  EXPECT_EQ(g.y_resolution, 160);
  EXPECT_TRUE(g.x_mirror);
  EXPECT_FALSE(g.y_mirror);
  EXPECT_FLOAT_EQ(g.x_size, 19.2f);
  EXPECT_FLOAT_EQ(g.y_size, 19.2f);
  EXPECT_FLOAT_EQ(g.z_size, 150.0f);  // at least what any resin printer reaches
  EXPECT_FLOAT_EQ(g.layer_thickness, 1.0f);
  EXPECT_FLOAT_EQ(g.exposure, 2.0f);
  EXPECT_FLOAT_EQ(g.bottom_exposure, 20.0f);
  EXPECT_EQ(g.bottom_layers, 1u);
  EXPECT_EQ(g.transition_layers, 3u);
  EXPECT_TRUE(g.advance_mode);
  EXPECT_TRUE(g.grey_scale_256);
  EXPECT_TRUE(g.delay_mode_static);
  EXPECT_EQ(g.antialiasing_level, 1);
  EXPECT_EQ(g.layer_content_offset, kHeaderBytes);
  EXPECT_FLOAT_EQ(g.volume, 184.0f);
  EXPECT_FLOAT_EQ(g.weight, 184.0f * 1.1e-3f);
  EXPECT_EQ(g.price_unit, "$");
  // Exposures: the bottom layer, three stepping down by (20 - 2) / 4, then the normal one.
  const float exposures[5] = {20, 15.5, 11, 6.5, 2};
  // Lift 5 mm at 65 mm/min and retract 5 mm at 150 mm/min take 6.615 s of the 8 s per layer.
  const float wait = 8 - 60 * (5.0f / 65 + 5.0f / 150);
  // 55 s of exposure and 5 layers of 8 s.
  EXPECT_EQ(g.print_time, 95u);
  EXPECT_EQ(g.moves, (std::array<float, 16>{5, 65, 5, 65, 5, 150, 5, 150, 0, 65, 0, 65, 0, 150, 0, 150}));
  EXPECT_FLOAT_EQ(g.waits[2], wait);
  EXPECT_FLOAT_EQ(g.waits[5], wait);
  for (size_t k = 0; k < 5; ++k) {
    const test::SpecGooLayer& l = g.layers[k];
    EXPECT_FLOAT_EQ(l.z, float(k + 1)) << k;
    EXPECT_FLOAT_EQ(l.exposure, exposures[k]) << k;
    EXPECT_FLOAT_EQ(l.after_retract, wait) << k;
    EXPECT_EQ(l.moves, (std::array<float, 8>{5, 65, 0, 65, 5, 150, 0, 150})) << k;
    EXPECT_EQ(l.pwm, 255) << k;
    EXPECT_EQ(l.pause, 0) << k;
  }
}

TEST_F(GooFiles, ChunksAreEncodedAsTheSpecificationSays) {
  // One layer of 60000 x 40 pixels given as runs; row 0: 255, grey 100, 105, 3 x 110,
  // 300 x 120, 118, then 255 up to column 20000; rows 1..38 empty; row 39 ends in a grey 7.
  MaskRuns runs;
  runs.width = 60000;
  runs.height = 40;
  const std::vector<std::array<int, 3>> row0 = {{0, 1, 255},     {1, 2, 100},     {2, 3, 105},      {3, 6, 110},
                                                {6, 306, 120},   {306, 307, 118}, {307, 20000, 255}};
  runs.row_begin.push_back(0);
  for (const auto& [c0, c1, v] : row0) {
    runs.columns.push_back(uint16_t(c0));
    runs.columns.push_back(uint16_t(c1));
    runs.levels.push_back(uint8_t(v));
  }
  for (int r = 0; r < 39; ++r) runs.row_begin.push_back(uint32_t(runs.levels.size()));
  runs.columns.push_back(59999);
  runs.columns.push_back(60000);
  runs.levels.push_back(7);
  runs.row_begin.push_back(uint32_t(runs.levels.size()));

  PrinterProfile p;
  p.width_px = 60000;
  p.height_px = 40;
  const GooJob job{p, 1, 0.05};
  std::vector<uint8_t> record;
  encode_goo_layer(job, 0, runs, record);
  write_goo(path("runs.goo"), job, [&](size_t) -> const std::vector<uint8_t>& { return record; },
            [] { return GooSummary{0, std::vector<uint16_t>(116 * 116), std::vector<uint16_t>(290 * 290)}; });
  const std::string bytes = read_bytes(path("runs.goo"));
  const auto [at, size] = layer_data(bytes, 0);
  // By hand from the specification: white x1 (1 byte); grey 100 x1 (2: 155 from 255 is too far
  // for a diff); +5 x1 (1); +5 x3 (2); grey 120 x 300 = 0x12C (3: too long for a diff);
  // -2 x1 (1); white x 19693 = 0x4CED (3); black x 2379999 = 0x2450DF (4: across 38 empty rows);
  // +7 x1 from black (1).
  const std::vector<uint8_t> chunks = {0xC1, 0x41, 100,  0x85, 0x95, 3,    0x5C, 120,  0x12, 0xA2,
                                       0xED, 0x04, 0xCE, 0x3F, 0x02, 0x45, 0x0D, 0x87};
  uint8_t sum = 0;
  for (uint8_t c : chunks) sum = uint8_t(sum + c);
  std::vector<uint8_t> expected = {0x55};
  expected.insert(expected.end(), chunks.begin(), chunks.end());
  expected.push_back(uint8_t(~sum));
  EXPECT_EQ(std::vector<uint8_t>(bytes.begin() + long(at), bytes.begin() + long(at + size)), expected);

  // Both readers give back the pixels.
  std::vector<uint8_t> pixels(size_t(60000) * 40, 0);
  for (size_t r = 0; r < 40; ++r)
    for (uint32_t i = runs.row_begin[r]; i < runs.row_begin[r + 1]; ++i)
      std::fill(pixels.begin() + long(r * 60000 + runs.columns[2 * i]),
                pixels.begin() + long(r * 60000 + runs.columns[2 * i + 1]), runs.levels[i]);
  const test::SpecGoo g = test::read_goo_per_spec(bytes);
  ASSERT_EQ(g.layers.size(), 1u);
  EXPECT_TRUE(g.layers[0].pixels == pixels);
  MaskStack stack(path("runs.goo"));
  std::vector<uint8_t> data;
  MaskImage image;
  stack.read(0, data);
  stack.decode(0, data, image);
  EXPECT_EQ(image.width, 60000);
  EXPECT_EQ(image.height, 40);
  EXPECT_TRUE(image.pixels == pixels);
}

TEST_F(GooFiles, PreviewsShowWhereThePartStandsWithTheMirrorsUndone) {
  // The left half of the 20 x 20 mm plate, mirrored in x on the display: the previews still show
  // it on the left. The top view has 200 cells across (one per 0.1 mm pixel), the left 100
  // covered: every sample of preview pixels 0..144 of 290 (0..57 of 116) falls on them, none of
  // the others'.
  PrinterProfile p = small_display();
  p.mirror_x = true;
  const test::SpecGoo g = export_and_read(make_slices({{rect(-10, -10, 0, 10)}}), p);
  for (const auto& [preview, n, lit] :
       {std::make_tuple(&g.big_preview, 290, 145), std::make_tuple(&g.small_preview, 116, 58)})
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        ASSERT_EQ((*preview)[size_t(y * n + x)], x < lit ? 0xFFFF : 0) << n << ": " << x << ", " << y;
}

TEST_F(GooFiles, TheSpecificationsReaderAndMaskStackCatchACorruptedChecksum) {
  const Slices s = make_slices(part_layers());
  export_masks(s, small_display(), path("a.goo"));
  export_masks(s, small_display(), path("a"));
  std::string bytes = read_bytes(path("a.goo"));
  const auto [at, size] = layer_data(bytes, 2);
  bytes[at + size / 2] = char(bytes[at + size / 2] ^ 0x10);
  write_bytes(path("bad.goo"), bytes);
  try {
    test::read_goo_per_spec(bytes);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "layer 2: checksum mismatch");
  }
  const std::string e = test::error_of([&] { compare_mask_stacks(path("a"), path("bad.goo"), ""); });
  EXPECT_NE(e.find("bad.goo: layer 2"), std::string::npos) << e;
  EXPECT_NE(e.find("checksum mismatch"), std::string::npos) << e;
}

TEST_F(GooFiles, CompareMaskStacksReadsGooAgainstFoldersAndSl1) {
  const Slices s = make_slices(part_layers());
  for (bool aa : {false, true}) {
    PrinterProfile p = mirrored_display();
    p.antialiasing = aa;
    export_masks(s, p, path("m.goo"));
    export_masks(s, p, path("m"));
    export_masks(s, p, path("m.sl1"));
    for (const char* other : {"m", "m.sl1", "m.goo"}) {
      const StackComparison c = compare_mask_stacks(path("m.goo"), path(other), "");
      EXPECT_EQ(c.layers.size(), s.layers());
      EXPECT_EQ(c.min_similarity, 1.0) << other;
      EXPECT_EQ(c.differing_pixels, 0u) << other;
    }
    // A different part differs where it should: more lit pixel rows on layer 0.
    std::vector<Layer> other = part_layers();
    other[0][0] = rect(-5, -5, 5, 5.3);
    export_masks(make_slices(other), p, path("o.goo"));
    EXPECT_GT(compare_mask_stacks(path("m.goo"), path("o.goo"), "").layers[0].differing_pixels, 0u);
    fs::remove_all(path("m"));
  }
  // The format, not the name: Phrozen's .prz is a .goo under another extension.
  fs::copy_file(path("m.goo"), path("m.prz"));
  EXPECT_EQ(compare_mask_stacks(path("m.goo"), path("m.prz"), "").differing_pixels, 0u);
}

TEST_F(GooFiles, MaskStackRefusesTruncatedAndCorruptFilesInWords) {
  export_masks(make_slices(part_layers()), small_display(), path("a.goo"));
  const std::string bytes = read_bytes(path("a.goo"));
  const auto [at1, size1] = layer_data(bytes, 1);
  const auto check = [&](const std::string& b, const std::string& message) {
    write_bytes(path("x.goo"), b);
    EXPECT_ERROR(MaskStack(path("x.goo")), message);
  };
  check(bytes.substr(0, 1000), "is truncated: it ends inside the header");
  check(bytes.substr(0, at1 + 3), "is truncated: it ends inside layer 1's record");
  check(bytes.substr(0, bytes.size() - 4), "is truncated: it ends inside the ending string");
  check(bytes + "x", "1 bytes follow the ending string");
  std::string b = bytes;
  b[6] = 1;
  check(b, "is not a .goo file: bytes 4 to 11 are not its magic");
  b = bytes;
  b[at1 - 5] = 'x';  // layer 1's definition delimiter
  check(b, "layer 1's definition does not end in 0D 0A");
  b = bytes;
  b[at1 - 1] = char(b[at1 - 1] + 1);  // layer 1's data size, one more
  check(b, "layer 1's image data");
  // The header claims more layers than the file holds.
  b = bytes;
  b[195310] = 1;
  check(b, "is truncated: it ends inside layer 5's record");
  b = bytes;
  b[195314] = b[195315] = char(0xFF);  // 65535 x 200 pixels: the layers' chunks fall short
  write_bytes(path("y.goo"), b);
  MaskStack stack(path("y.goo"));
  std::vector<uint8_t> data;
  MaskImage image;
  stack.read(0, data);
  EXPECT_ERROR(stack.decode(0, data, image), "y.goo: layer 0' is corrupt: its chunks make 40000 of the 13107000 pixels");
  EXPECT_ERROR(MaskStack(path("missing.goo")), "does not exist");
}

TEST_F(GooFiles, ARefusedExportLeavesNothing) {
  const Slices s = make_slices(std::vector<Layer>(300, Layer{star(0.3, -0.2, 3, 7.5, 9)}));
  PrinterProfile portrait = small_display();
  portrait.portrait = true;
  EXPECT_ERROR(export_masks(s, portrait, path("p.goo")), "no portrait orientation");
  PrinterProfile faded = small_display();
  faded.faded_layers = 70000;
  EXPECT_ERROR(export_masks(s, faded, path("f.goo")), "70000 faded layers, more than a .goo's transition layers hold");
  EXPECT_TRUE(fs::is_empty(dir));  // cancelled exports: test_print_formats.cpp
}

