// Mask images: exact pixel counts for known geometry, placement, invariance to loop start and
// contour order, PNG folder and .sl1 export, stack comparison and its errors.
#include <gtest/gtest.h>
#include <zip.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

#include "error_of.h"
#include "mask_layers.h"
#include "mask_stack.h"
#include "slicereuse/png/mask_png.h"
#include "slicereuse/printer/printer_presets.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/printfiles/compare_mask_stacks.h"
#include "slicereuse/printfiles/export_masks.h"
#include "slicereuse/raster/rasterize_layer.h"
#include "slicereuse/util/error.h"
#include "temp_folder.h"
#include "test_files.h"

namespace fs = std::filesystem;
using namespace slicereuse;

namespace {

using test::Layer;
using test::Loop;
using test::make_slices;
using test::raster;
using test::rect;
using test::small_display;
using test::star;

size_t on_pixels(const std::vector<uint8_t>& img) {
  size_t n = 0;
  for (uint8_t v : img) {
    EXPECT_TRUE(v == 0 || v == 255);
    n += v == 255;
  }
  return n;
}

class MaskFiles : public test::TempFolderTest {
 protected:
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
};

// Three layers: a square, a square with a hole, a star.
Slices sample_stack() {
  return make_slices({{rect(-5, -5, 5, 5)},
                      {rect(-5, -5, 5, 5), rect(-2, -2, 2, 2, true)},
                      {star(0.3, -0.2, 3, 7.5, 9)}});
}

std::string read_text(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

}  // namespace

TEST(RasterizeLayer, AlignedSquareIsExactly100By100) {
  const PrinterProfile p = small_display();
  const auto img = raster(make_slices({{rect(-5, -5, 5, 5)}}), 0, p);
  EXPECT_EQ(on_pixels(img), 100u * 100u);
  for (int r = 0; r < 200; ++r)
    for (int c = 0; c < 200; ++c)
      ASSERT_EQ(img[size_t(r) * 200 + c], (r >= 50 && r < 150 && c >= 50 && c < 150) ? 255 : 0);
}

TEST(RasterizeLayer, EdgesThroughPixelCentresAreHalfOpen) {
  // Edges at x = -4.95 and 5.05 pass exactly through centres; still exactly 100 columns/rows.
  const auto img = raster(make_slices({{rect(-4.95, -4.95, 5.05, 5.05)}}), 0, small_display());
  EXPECT_EQ(on_pixels(img), 100u * 100u);
}

TEST(RasterizeLayer, ClockwiseHoleIsOff) {
  const auto img =
      raster(make_slices({{rect(-5, -5, 5, 5), rect(-2, -2, 2, 2, true)}}), 0, small_display());
  EXPECT_EQ(on_pixels(img), 100u * 100u - 40u * 40u);
  EXPECT_EQ(img[100 * 200 + 100], 0);
  EXPECT_EQ(img[60 * 200 + 60], 255);
}

TEST(RasterizeLayer, OverlappingCounterClockwiseSquaresAreUnited) {
  const auto img = raster(make_slices({{rect(-5, -5, 5, 5), rect(0, 0, 9, 9)}}), 0, small_display());
  EXPECT_EQ(on_pixels(img), 100u * 100u + 90u * 90u - 50u * 50u);
}

TEST(RasterizeLayer, OpenContoursAreIgnoredAndCounted) {
  Loop line = rect(-5, -5, 5, 5);
  line.open = true;
  size_t open = 0;
  auto img = raster(make_slices({{line}}), 0, small_display(), &open);
  EXPECT_EQ(open, 1u);
  EXPECT_EQ(on_pixels(img), 0u);
  img = raster(make_slices({{line, rect(-1, -1, 1, 1), line}}), 0, small_display(), &open);
  EXPECT_EQ(open, 2u);
  EXPECT_EQ(on_pixels(img), 400u);
}

TEST(RasterizeLayer, MirrorsFlipTheImage) {
  const Slices s = make_slices({{rect(1, 2, 4, 3), star(-3, -4, 1, 2.5, 5)}});
  PrinterProfile p = small_display();
  const auto plain = raster(s, 0, p);
  p.mirror_x = true;
  const auto mx = raster(s, 0, p);
  p.mirror_x = false;
  p.mirror_y = true;
  const auto my = raster(s, 0, p);
  ASSERT_GT(on_pixels(plain), 0u);
  for (int r = 0; r < 200; ++r)
    for (int c = 0; c < 200; ++c) {
      ASSERT_EQ(mx[size_t(r) * 200 + c], plain[size_t(r) * 200 + (199 - c)]);
      ASSERT_EQ(my[size_t(r) * 200 + c], plain[size_t(199 - r) * 200 + c]);
    }
}

TEST(RasterizeLayer, RowZeroIsTheTop) {
  // A square above the origin (y > 0) lands in the upper half of the image.
  const auto img = raster(make_slices({{rect(-1, 3, 1, 4)}}), 0, small_display());
  EXPECT_EQ(on_pixels(img), 200u);
  for (int r = 0; r < 200; ++r)
    EXPECT_EQ(img[size_t(r) * 200 + 100], (r >= 60 && r < 70) ? 255 : 0) << r;
}

TEST(RasterizeLayer, OffsetShiftsByWholePixels) {
  const Slices s = make_slices({{star(0.3, -0.2, 3, 7.5, 9)}});
  PrinterProfile p = small_display();
  const auto plain = raster(s, 0, p);
  p.offset_x_mm = 0.3;   // 3 pixels right
  p.offset_y_mm = -0.5;  // 5 pixels down
  const auto shifted = raster(s, 0, p);
  EXPECT_EQ(on_pixels(shifted), on_pixels(plain));
  for (int r = 5; r < 200; ++r)
    for (int c = 3; c < 200; ++c)
      ASSERT_EQ(shifted[size_t(r) * 200 + c], plain[size_t(r - 5) * 200 + (c - 3)]);
}

TEST(RasterizeLayer, LoopStartAndContourOrderDoNotMatter) {
  Loop outer = star(0.3, -0.2, 3, 7.5, 9), hole = star(0.1, 0.2, 1, 2, 5);
  std::reverse(hole.pts.begin(), hole.pts.end());
  Loop outer2 = outer, hole2 = hole;
  std::rotate(outer2.pts.begin(), outer2.pts.begin() + 5, outer2.pts.end());
  std::rotate(hole2.pts.begin(), hole2.pts.begin() + 3, hole2.pts.end());
  const Slices a = make_slices({{outer, hole}}), b = make_slices({{hole2, outer2}});
  for (bool aa : {false, true}) {
    PrinterProfile p = small_display();
    p.antialiasing = aa;
    p.pixel_size_x_um = 73.1;  // nothing lines up with the grid
    p.pixel_size_y_um = 81.7;
    const auto ia = raster(a, 0, p), ib = raster(b, 0, p);
    EXPECT_TRUE(ia == ib) << "antialiasing " << aa;
    EXPECT_GT(std::count(ia.begin(), ia.end(), 255), 1000);
  }
}

TEST(RasterizeLayer, AntialiasingGivesCoverage) {
  PrinterProfile p = small_display();
  p.antialiasing = true;
  auto img = raster(make_slices({{rect(-5, -5, 5, 5)}}), 0, p);
  EXPECT_EQ(std::accumulate(img.begin(), img.end(), size_t(0)), 255u * 100u * 100u);
  // Shifted by half a pixel in x: the two edge columns are half covered.
  img = raster(make_slices({{rect(-4.95, -5, 5.05, 5)}}), 0, p);
  EXPECT_EQ(img[100 * 200 + 50], 128);
  EXPECT_EQ(img[100 * 200 + 150], 128);
  EXPECT_EQ(img[100 * 200 + 51], 255);
  EXPECT_EQ(img[100 * 200 + 49], 0);
}

TEST(RasterizeLayer, RejectsBadInput) {
  const Slices s = make_slices({{rect(-5, -5, 5, 5)}});
  std::vector<uint8_t> img(200 * 200);
  PrinterProfile p = small_display();
  EXPECT_THROW(rasterize_layer(s, 1, p, img.data()), Error);
  p.pixel_size_x_um = 0;
  EXPECT_THROW(rasterize_layer(s, 0, p, img.data()), Error);
}

TEST(MaskPng, RoundTripsOneAndEightBit) {
  // 13 columns: one full byte and a 5-pixel tail per row in the 1-bit encoding.
  const int w = 13, h = 5;
  std::vector<uint8_t> img(w * h);
  for (int i = 0; i < w * h; ++i) img[size_t(i)] = uint8_t((i * 37 + i / 3) % 256);
  std::vector<uint8_t> png;
  MaskImage back;
  encode_mask_png(img.data(), w, h, 8, png);
  decode_mask_png(png.data(), png.size(), "8-bit", back);
  EXPECT_EQ(back.width, w);
  EXPECT_EQ(back.height, h);
  EXPECT_EQ(back.pixels, img);
  encode_mask_png(img.data(), w, h, 1, png);
  EXPECT_EQ(png[24], 1);
  decode_mask_png(png.data(), png.size(), "1-bit", back);
  for (size_t i = 0; i < img.size(); ++i) ASSERT_EQ(back.pixels[i], img[i] >= 128 ? 255 : 0) << i;
  EXPECT_THROW(decode_mask_png(png.data(), png.size() / 2, "half", back), Error);
}

TEST_F(MaskFiles, FolderExportComparesEqualToItself) {
  const Slices s = sample_stack();
  const std::string out = dir + "/masks";
  const MaskExportStats st = export_masks(s, small_display(), out);
  EXPECT_EQ(st.layers, 3u);
  EXPECT_EQ(listing(), std::vector<std::string>{"masks"});
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(out)) files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"layer00000.png", "layer00001.png", "layer00002.png"}));
  // The PNG holds exactly the rasterized layer.
  MaskStack stack(out);
  std::vector<uint8_t> bytes;
  stack.read(1, bytes);
  ASSERT_GT(bytes.size(), 25u);
  EXPECT_EQ(bytes[24], 1) << "binary masks in a folder are 1-bit PNGs";
  MaskImage img;
  decode_mask_png(bytes.data(), bytes.size(), "layer1", img);
  EXPECT_EQ(img.pixels, raster(s, 1, small_display()));

  const StackComparison c = compare_mask_stacks(out, out, dir + "/report.csv");
  ASSERT_EQ(c.layers.size(), 3u);
  for (const auto& l : c.layers) {
    EXPECT_EQ(l.similarity, 1.0);
    EXPECT_EQ(l.differing_pixels, 0u);
  }
  EXPECT_EQ(c.min_similarity, 1.0);
  EXPECT_EQ(c.differing_pixels, 0u);
  EXPECT_EQ(read_text(dir + "/report.csv"),
            "layer,similarity,differing_pixels,max_grey_difference,over_one_level_pixels\n"
            "0,1,0,0,0\n1,1,0,0,0\n2,1,0,0,0\n");
}

TEST_F(MaskFiles, OnePixelDifferenceGivesExactSimilarity) {
  const Slices s = sample_stack();
  const PrinterProfile p = small_display();
  export_masks(s, p, dir + "/a");
  export_masks(s, p, dir + "/b");
  auto img = raster(s, 2, p);
  img[123 * 200 + 45] ^= 255;
  std::vector<uint8_t> png;
  encode_mask_png(img.data(), 200, 200, 1, png);
  std::ofstream(dir + "/b/layer00002.png", std::ios::binary)
      .write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
  const StackComparison c = compare_mask_stacks(dir + "/a", dir + "/b", dir + "/r.csv");
  EXPECT_EQ(c.differing_pixels, 1u);
  EXPECT_EQ(c.worst_layer, 2u);
  EXPECT_EQ(c.min_similarity, 1.0 - 1.0 / 40000.0);
  EXPECT_EQ(c.layers[2].differing_pixels, 1u);
  EXPECT_EQ(c.layers[0].similarity, 1.0);
  EXPECT_EQ(read_text(dir + "/r.csv"),
            "layer,similarity,differing_pixels,max_grey_difference,over_one_level_pixels\n"
            "0,1,0,0,0\n1,1,0,0,0\n2,0.999975,1,255,1\n");
}

TEST_F(MaskFiles, Sl1RoundTripMatchesFolder) {
  const Slices s = sample_stack();
  for (bool aa : {false, true}) {
    PrinterProfile p = small_display();
    p.antialiasing = aa;
    p.mirror_x = true;
    const std::string sl1 = dir + "/job.sl1", folder = dir + "/folder";
    export_masks(s, p, sl1);
    export_masks(s, p, folder);
    const StackComparison c = compare_mask_stacks(sl1, folder, "");
    ASSERT_EQ(c.layers.size(), 3u);
    EXPECT_EQ(c.min_similarity, 1.0);
    EXPECT_EQ(c.differing_pixels, 0u);
    EXPECT_EQ(c.max_grey_difference, 0);  // S alone would not see grey levels differ
    // PrusaSlicer's SL1 import reads only 8-bit greyscale layers.
    MaskStack archive(sl1);
    std::vector<uint8_t> bytes;
    archive.read(2, bytes);
    ASSERT_GT(bytes.size(), 25u);
    EXPECT_EQ(bytes[24], 8);
    EXPECT_EQ(bytes[25], 0);

    int err = 0;
    zip_t* z = zip_open(sl1.c_str(), ZIP_RDONLY | ZIP_CHECKCONS, &err);
    ASSERT_NE(z, nullptr);
    EXPECT_GE(zip_name_locate(z, "config.ini", 0), 0);
    EXPECT_GE(zip_name_locate(z, "prusaslicer.ini", 0), 0);
    EXPECT_GE(zip_name_locate(z, "job00002.png", 0), 0);
    zip_discard(z);
    EXPECT_EQ(listing(), (std::vector<std::string>{"folder", "job.sl1"}));
    fs::remove_all(folder);
  }
}

TEST_F(MaskFiles, Sl1ConfigCarriesTheDisplay) {
  PrinterProfile p = small_display();
  p.mirror_y = true;
  export_masks(sample_stack(), p, dir + "/x.sl1");
  const std::string config = test::zip_entry(dir + "/x.sl1", "config.ini"),
                    slicer = test::zip_entry(dir + "/x.sl1", "prusaslicer.ini");
  // A custom display names no printer model, as PrusaSlicer writes it for a custom printer.
  for (const char* line : {"jobDir = x\n", "numFast = 3\n", "numSlow = 0\n", "layerHeight = 0.1\n",
                           "action = print\n", "printerModel = \n", "expTime = 6\n", "expTimeFirst = 35\n",
                           "numFade = 10\n"})
    EXPECT_NE(config.find(line), std::string::npos) << line;
  for (const char* line : {"display_pixels_x = 200\n", "display_pixels_y = 200\n",
                           "display_width = 20\n", "display_height = 20\n",
                           "display_orientation = landscape\n", "display_mirror_x = 0\n",
                           "display_mirror_y = 1\n", "printer_technology = SLA\n"})
    EXPECT_NE(slicer.find(line), std::string::npos) << line;
}

TEST_F(MaskFiles, AnSl1sOfTheSl1sPresetIsWhatPrusaSlicerWritesForIt) {
  // PrusaSlicer 2.5's "Original Prusa SL1S SPEED": 2560 x 1620 pixels over 128 x 81 mm,
  // portrait (images 1620 wide, 2560 tall), display_mirror_x = 1; printerModel SL1S.
  const PrinterProfile p = printer_preset("prusa_sl1s_speed").profile;
  export_masks(sample_stack(), p, dir + "/part.sl1s");
  const std::string config = test::zip_entry(dir + "/part.sl1s", "config.ini"),
                    slicer = test::zip_entry(dir + "/part.sl1s", "prusaslicer.ini");
  for (const char* line : {"jobDir = part\n", "printerModel = SL1S\n", "expTime = 2\n", "expTimeFirst = 25\n",
                           "numFade = 10\n", "numFast = 3\n"})
    EXPECT_NE(config.find(line), std::string::npos) << line;
  for (const char* line : {"display_pixels_x = 2560\n", "display_pixels_y = 1620\n", "display_width = 128\n",
                           "display_height = 81\n", "display_orientation = portrait\n", "display_mirror_x = 1\n",
                           "display_mirror_y = 0\n", "printer_model = SL1S\n"})
    EXPECT_NE(slicer.find(line), std::string::npos) << line;
  MaskStack stack(dir + "/part.sl1s");
  ASSERT_EQ(stack.layers(), 3u);
  std::vector<uint8_t> bytes;
  stack.read(0, bytes);
  MaskImage image;
  decode_mask_png(bytes.data(), bytes.size(), "layer 0", image);
  EXPECT_EQ(image.width, 1620);
  EXPECT_EQ(image.height, 2560);
}

TEST_F(MaskFiles, EveryPresetIsAValidProfileWithItsPrintersFigures) {
  // Display sizes in mm as the printers' makers give them.
  const std::vector<std::tuple<std::string, double, double>> sizes = {
      {"method", 76.8, 57.6},           {"prusa_sl1", 120.96, 68.04},
      {"prusa_sl1s_speed", 128, 81},    {"anycubic_photon_mono_x", 192, 120},
      {"elegoo_saturn_3_ultra", 218.88, 122.88},   {"elegoo_mars_2_pro", 82.62, 130.56},
      {"phrozen_sonic_mighty_4k", 199.68, 124.8},  {"anycubic_photon_mono_x_6k", 198.15, 123.84},
      {"anycubic_photon_mono_4", 153.408, 87.04},  {"anycubic_photon_mono_m5s", 218.88, 122.88}};
  ASSERT_EQ(printer_presets().size(), sizes.size());
  for (const auto& [id, w, h] : sizes) {
    const PrinterProfile& p = printer_preset(id).profile;
    validate_printer_profile(p);
    EXPECT_NEAR(p.width_px * p.pixel_size_x_um / 1000, w, 1e-9) << id;
    EXPECT_NEAR(p.height_px * p.pixel_size_y_um / 1000, h, 1e-9) << id;
  }
  EXPECT_EQ(test::error_of([] { printer_preset("sl2"); }),
            "no printer profile named 'sl2' (the profiles are: method, prusa_sl1, prusa_sl1s_speed, "
            "anycubic_photon_mono_x, elegoo_saturn_3_ultra, elegoo_mars_2_pro, phrozen_sonic_mighty_4k, "
            "anycubic_photon_mono_x_6k, anycubic_photon_mono_4, anycubic_photon_mono_m5s)");
}

TEST_F(MaskFiles, Sl1ConfigCarriesTheResinVolumeSummedWhileTheLayersAreMade) {
  // 1 mm layers: a 10 x 10 mm square, then the same square with a 4 x 4 mm hole: 184 mm^3.
  const Slices s = make_slices({{rect(-5, -5, 5, 5)}, {rect(-5, -5, 5, 5), rect(-2, -2, 2, 2, true)}}, 1.0);
  export_masks(s, small_display(), dir + "/v.sl1");
  const std::string config = test::zip_entry(dir + "/v.sl1", "config.ini");
  EXPECT_NE(config.find("usedMaterial = 0.184\n"), std::string::npos) << config;
}

TEST_F(MaskFiles, ANonFinitePointIsRefusedAndNothingIsWritten) {
  Slices s = sample_stack();
  s.xyz[3 * (s.points() - 2) + 1] = std::nan("");
  for (const char* name : {"/n.sl1", "/n.goo", "/n"}) {
    const std::string e = test::error_of([&] { export_masks(s, small_display(), dir + name); });
    EXPECT_NE(e.find("is not a finite number"), std::string::npos) << e;
    EXPECT_NE(e.find("layer 2"), std::string::npos) << e;
    EXPECT_FALSE(fs::exists(dir + name));
  }
}

TEST_F(MaskFiles, ReexportIntoFolderReplacesOldLayers) {
  const Slices s = sample_stack();
  const std::string out = dir + "/m";
  export_masks(make_slices({{rect(0, 0, 1, 1)}, {}, {}, {}, {}}), small_display(), out);
  std::ofstream(out + "/notes.txt") << "kept";
  export_masks(s, small_display(), out);
  EXPECT_EQ(MaskStack(out).layers(), 3u);
  EXPECT_TRUE(fs::exists(out + "/notes.txt"));
  export_masks(s, small_display(), dir + "/ref");
  EXPECT_EQ(compare_mask_stacks(out, dir + "/ref", "").differing_pixels, 0u);
  EXPECT_EQ(listing(), (std::vector<std::string>{"m", "ref"}));
}

TEST_F(MaskFiles, MismatchedStacksAreErrors) {
  const Slices s = sample_stack();
  export_masks(s, small_display(), dir + "/a");
  export_masks(make_slices({{rect(-5, -5, 5, 5)}, {rect(-5, -5, 5, 5)}}), small_display(),
               dir + "/two");
  PrinterProfile wide = small_display();
  wide.width_px = 240;
  export_masks(s, wide, dir + "/wide.sl1");
  try {
    compare_mask_stacks(dir + "/a", dir + "/two", "");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("layer count"), std::string::npos) << e.what();
  }
  try {
    compare_mask_stacks(dir + "/a", dir + "/wide.sl1", dir + "/never.csv");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("200x200"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("240x200"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir + "/never.csv"));
  EXPECT_THROW(compare_mask_stacks(dir + "/a", dir + "/missing", ""), Error);
  EXPECT_THROW(compare_mask_stacks(dir + "/a", dir + "/a/layer00000.png", ""), Error);
}

TEST_F(MaskFiles, CorruptAndMissingImagesAreErrors) {
  export_masks(sample_stack(), small_display(), dir + "/a");
  export_masks(sample_stack(), small_display(), dir + "/b");
  std::ofstream(dir + "/b/layer00001.png", std::ios::binary) << "not a png at all";
  try {
    compare_mask_stacks(dir + "/a", dir + "/b", "");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("layer00001.png"), std::string::npos) << e.what();
  }
  fs::remove(dir + "/b/layer00001.png");
  try {
    compare_mask_stacks(dir + "/a", dir + "/b", "");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos) << e.what();
  }
  // A damaged .sl1: flip a byte inside the stored PNG data; the entry's CRC catches it.
  export_masks(sample_stack(), small_display(), dir + "/c.sl1");
  std::string zip = read_text(dir + "/c.sl1");
  const size_t at = zip.find("IDAT");
  ASSERT_NE(at, std::string::npos);
  zip[at + 10] ^= 0x55;
  std::ofstream(dir + "/c.sl1", std::ios::binary) << zip;
  EXPECT_THROW(compare_mask_stacks(dir + "/a", dir + "/c.sl1", ""), Error);
}

TEST_F(MaskFiles, FailedOrCancelledExportLeavesNothing) {
  const Slices s = sample_stack();
  EXPECT_THROW(export_masks(s, small_display(), dir + "/no/such/folder/m"), Error);
  EXPECT_THROW(export_masks(s, small_display(), dir + "/no/such/folder/m.sl1"), Error);
  int calls = 0, cancel_at = 1;
  const Progress cancel = [&](double, const char*) { return ++calls < cancel_at; };
  EXPECT_THROW(export_masks(s, small_display(), dir + "/m", cancel), Cancelled);
  calls = 0;
  EXPECT_THROW(export_masks(s, small_display(), dir + "/m.sl1", cancel), Cancelled);
  EXPECT_TRUE(listing().empty());
  // Cancelled in the middle: the .sl1 asks per batch of layers, the folder per layer done on
  // the calling thread.
  std::vector<Layer> many(300, Layer{star(0.3, -0.2, 3, 7.5, 9)});
  const Slices big = make_slices(many);
  cancel_at = 3;
  calls = 0;
  EXPECT_THROW(export_masks(big, small_display(), dir + "/m", cancel), Cancelled);
  calls = 0;
  EXPECT_THROW(export_masks(big, small_display(), dir + "/m.sl1", cancel), Cancelled);
  EXPECT_TRUE(listing().empty());
  // An existing archive survives a failed export untouched.
  export_masks(s, small_display(), dir + "/keep.sl1");
  const std::string before = read_text(dir + "/keep.sl1");
  calls = 0;
  EXPECT_THROW(export_masks(big, small_display(), dir + "/keep.sl1", cancel), Cancelled);
  EXPECT_EQ(read_text(dir + "/keep.sl1"), before);
  EXPECT_EQ(listing(), std::vector<std::string>{"keep.sl1"});
  // A file where the mask folder should go.
  std::ofstream(dir + "/file") << "x";
  EXPECT_THROW(export_masks(s, small_display(), dir + "/file"), Error);
}

TEST_F(MaskFiles, ReportsAPartThatLeavesTheDisplay) {
  // A 10 mm square on layer 0 of a 20 x 20 mm display: it fits, until the offset pushes it out.
  const Slices s = make_slices({{rect(-5, -5, 5, 5)}, {rect(-5, -5, 5, 5)}});
  PrinterProfile p = small_display();
  MaskExportStats st = export_masks(s, p, dir + "/fits");
  EXPECT_FALSE(st.outside_display);
  EXPECT_EQ(st.min_x, -5.0);
  EXPECT_EQ(st.max_x, 5.0);
  EXPECT_EQ(st.min_y, -5.0);
  EXPECT_EQ(st.max_y, 5.0);
  p.offset_x_mm = 5;  // right edge exactly at the display edge: still inside
  EXPECT_FALSE(export_masks(s, p, dir + "/edge").outside_display);
  p.offset_x_mm = 0;
  p.offset_y_mm = -5.5;
  EXPECT_TRUE(export_masks(s, p, dir + "/cut").outside_display);
}

TEST(RasterizeLayer, RunsEncodeTheSamePngAsPixels) {
  // Every layer of the sample stack, also mirrored and shifted off the display's edge, so runs
  // touch both image borders.
  const Slices s = make_slices({{rect(-5, -5, 5, 5)},
                                {rect(-5, -5, 5, 5), rect(-2, -2, 2, 2, true)},
                                {star(0.3, -0.2, 3, 7.5, 9)},
                                {rect(-30, -3, 30, 3), rect(-1, -20, 1, 20)},
                                {}});
  for (bool mirror : {false, true}) {
    PrinterProfile p = small_display();
    p.mirror_x = mirror;
    p.offset_x_mm = mirror ? 4.5 : 0;
    for (size_t k = 0; k < s.layers(); ++k) {
      MaskRuns runs;
      rasterize_layer_runs(s, k, p, runs);
      ASSERT_EQ(runs.row_begin.size(), 201u);
      std::vector<uint8_t> from_runs, from_pixels;
      encode_mask_png(runs, from_runs);
      const std::vector<uint8_t> img = raster(s, k, p);
      encode_mask_png(img.data(), p.width_px, p.height_px, 8, from_pixels);
      EXPECT_EQ(from_runs, from_pixels) << "layer " << k << (mirror ? ", mirrored" : "");
      MaskImage back;
      decode_mask_png(from_runs.data(), from_runs.size(), "runs", back);
      EXPECT_EQ(back.pixels, img) << "layer " << k;
    }
  }
  MaskRuns runs;
  PrinterProfile aa = small_display();
  aa.antialiasing = true;
  EXPECT_THROW(rasterize_layer_runs(s, 0, aa, runs), Error);
  rasterize_layer_runs(s, 0, small_display(), runs);
  std::swap(runs.columns[0], runs.columns[1]);  // a run that ends before it starts
  std::vector<uint8_t> png;
  EXPECT_THROW(encode_mask_png(runs, png), Error);
}

TEST(RasterizeLayer, APartWiderThanTheDisplayStaysInsideItsRows) {
  // 60 mm wide on a 20 mm display: each row is lit edge to edge and nothing spills into the
  // next row's first pixel or past the image.
  const Slices s = make_slices({{rect(-30, -3, 30, 3)}});
  std::vector<uint8_t> img(200 * 200 + 2, 7);
  rasterize_layer(s, 0, small_display(), img.data() + 1);
  EXPECT_EQ(img.front(), 7);
  EXPECT_EQ(img.back(), 7);
  img.erase(img.begin());
  img.pop_back();
  EXPECT_EQ(on_pixels(img), 200u * 60u);
  EXPECT_EQ(img[69 * 200 + 199], 0);   // the row above the part: dark to its last pixel
  EXPECT_EQ(img[130 * 200], 0);        // the row below: dark from its first pixel
}

TEST_F(MaskFiles, JobNameEndingInDigitsKeepsItsLayerNumbers) {
  // member_001.sl1 holds member_00100000.png ... : the layer number is the last five digits.
  const Slices s = sample_stack();
  const std::string sl1 = dir + "/member_001.sl1", folder = dir + "/folder";
  export_masks(s, small_display(), sl1);
  export_masks(s, small_display(), folder);
  MaskStack archive(sl1);
  ASSERT_EQ(archive.layers(), 3u);
  EXPECT_EQ(archive.layer_name(2), sl1 + ":member_00100002.png");
  const StackComparison c = compare_mask_stacks(sl1, folder, "");
  ASSERT_EQ(c.layers.size(), 3u);
  EXPECT_EQ(c.min_similarity, 1.0);
}

TEST_F(MaskFiles, Sl1WithRepeatedLayersMatchesFolder) {
  // Runs of equal layers between different ones, more layers than the encoding window.
  std::vector<Layer> layers;
  for (int i = 0; i < 40; ++i)
    layers.push_back(i % 7 < 4 ? Layer{rect(-5, -5, 5, 5)} : Layer{star(0.3, -0.2, 3, 7.5, 9 + i % 3)});
  const Slices s = make_slices(layers);
  export_masks(s, small_display(), dir + "/job.sl1");
  export_masks(s, small_display(), dir + "/folder");
  const StackComparison c = compare_mask_stacks(dir + "/job.sl1", dir + "/folder", "");
  ASSERT_EQ(c.layers.size(), 40u);
  EXPECT_EQ(c.differing_pixels, 0u);
}

// Nonzero winding of the closed loops around (x, y), counted independently of the rasterizer.
int winding_number(const Layer& layer, double x, double y) {
  int w = 0;
  for (const Loop& l : layer) {
    if (l.open) continue;
    for (size_t i = 0; i < l.pts.size(); ++i) {
      const auto& p = l.pts[i];
      const auto& q = l.pts[(i + 1) % l.pts.size()];
      const double side = (q[0] - p[0]) * (y - p[1]) - (x - p[0]) * (q[1] - p[1]);
      if (p[1] <= y && y < q[1] && side > 0) ++w;
      if (q[1] <= y && y < p[1] && side < 0) --w;
    }
  }
  return w;
}

TEST(RasterizeLayer, MatchesTheWindingNumberAtEveryPixelCentre) {
  // Overlapping stars and polygons with 64, 65, 66 and 130 points (the rasterizer looks at 64
  // points at a time), a hole, and rows of 2 to over 20 crossings (sorted by networks up to 4,
  // by insertion beyond).
  auto polygon = [](double cx, double cy, double r, int n) {
    Loop l;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * 3.141592653589793 * i / n + 0.0321;
      l.pts.push_back({cx + r * std::cos(a), cy + r * 0.7 * std::sin(a)});
    }
    return l;
  };
  Loop hole = star(0.47, 0.53, 0.6, 1.7, 7);
  std::reverse(hole.pts.begin(), hole.pts.end());
  const std::vector<Layer> layers = {
      {star(-3.1, 1.2, 2, 6.5, 32), star(4.1, -2.3, 1.5, 5.5, 33), star(0.5, 0.5, 3, 8.7, 65), hole},
      {polygon(-2.03, 0.11, 5.3, 65), polygon(2.07, -0.13, 5.1, 64), rect(-9.37, -0.71, 9.41, 0.69)},
      {rect(-3.33, -3.37, 3.31, 3.29)}};
  const Slices s = make_slices(layers);
  const PrinterProfile p = small_display();
  for (size_t k = 0; k < layers.size(); ++k) {
    const std::vector<uint8_t> img = raster(s, k, p);
    size_t wrong = 0, lit = 0;
    for (int r = 0; r < p.height_px; ++r)
      for (int c = 0; c < p.width_px; ++c) {
        const double x = (c + 0.5) * 0.1 - 10, y = 10 - (r + 0.5) * 0.1;
        const bool inside = winding_number(layers[k], x, y) != 0;
        wrong += inside != (img[size_t(r) * p.width_px + c] == 255);
        lit += inside;
      }
    EXPECT_EQ(wrong, 0u) << "layer " << k;
    EXPECT_GT(lit, 1000u) << "layer " << k;
    MaskRuns runs;
    rasterize_layer_runs(s, k, p, runs);
    std::vector<uint8_t> png;
    encode_mask_png(runs, png);
    MaskImage back;
    decode_mask_png(png.data(), png.size(), "runs", back);
    EXPECT_EQ(back.pixels, img) << "layer " << k;
  }
}

TEST(MaskPng, EncodesCorrectlyAfterAFailedEncoding) {
  // The deflater is kept per thread: an encoding that fails half-way must not leave its runs in
  // the next image.
  const Slices s = sample_stack();
  MaskRuns good, bad;
  rasterize_layer_runs(s, 2, small_display(), good);
  bad = good;
  const size_t last = bad.columns.size() - 1;
  bad.columns[last] = uint16_t(bad.columns[last - 1] - 1);  // the last run ends before it starts
  std::vector<uint8_t> png;
  EXPECT_THROW(encode_mask_png(bad, png), Error);
  encode_mask_png(good, png);
  MaskImage back;
  decode_mask_png(png.data(), png.size(), "after a failure", back);
  EXPECT_EQ(back.pixels, raster(s, 2, small_display()));
}
