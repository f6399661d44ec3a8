// The .sl1 archive as PrusaSlicer 2.5 writes one: its entries and their order, the profile keys
// PrusaSlicer's import takes over, numbers the firmware reads, the thumbnails (a top view of the
// part gathered while the layers are encoded), and what is refused because PrusaSlicer or the
// printer's firmware would misread it. (Pixels against PrusaSlicer's own export:
// tests/python/test_prusaslicer_sl1.py.)
#include <gtest/gtest.h>
#include <png.h>
#include <zip.h>

#include <algorithm>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "error_of.h"
#include "mask_layers.h"
#include "slicereuse/png/mask_png.h"
#include "slicereuse/printer/printer_presets.h"
#include "slicereuse/printfiles/export_masks.h"
#include "slicereuse/raster/top_view.h"
#include "slicereuse/util/format.h"
#include "test_files.h"
#include "thumbnail_png.h"

using namespace slicereuse;
using test::Layer;
using test::Loop;
using test::make_slices;
using test::rect;
using test::small_display;

namespace {

class Sl1Archive : public test::TempFolderTest {};

// An L seen from above: the foot x in [-6, 6], y in [-6, -2], the arm x in [-6, -2], y in
// [-2, 6] (mm). Layers 0-4 are the whole L, layers 5-9 only the arm, so the foot is lower.
Slices l_stack() {
  const Loop l{{{-6, -6}, {6, -6}, {6, -2}, {-2, -2}, {-2, 6}, {-6, 6}}};
  std::vector<Layer> layers(5, Layer{l});
  layers.resize(10, Layer{rect(-6, -6, -2, 6)});
  return make_slices(layers);
}

struct Entry {
  std::string name;
  bool stored;
  time_t mtime;
};

std::vector<Entry> entries(const std::string& archive) {
  int err = 0;
  zip_t* z = zip_open(archive.c_str(), ZIP_RDONLY | ZIP_CHECKCONS, &err);
  EXPECT_NE(z, nullptr) << archive;
  std::vector<Entry> list;
  if (!z) return list;
  for (zip_int64_t i = 0; i < zip_get_num_entries(z, 0); ++i) {
    zip_stat_t st;
    zip_stat_index(z, zip_uint64_t(i), 0, &st);
    list.push_back({st.name, st.comp_method == ZIP_CM_STORE, st.mtime});
  }
  zip_discard(z);
  return list;
}

struct Rgba {
  int width = 0, height = 0;
  std::vector<uint8_t> pixels;  // 4 bytes per pixel
  const uint8_t* at(int x, int y) const { return pixels.data() + 4 * (size_t(y) * size_t(width) + size_t(x)); }
};

Rgba decode_rgba(const std::string& png) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  Rgba out;
  EXPECT_TRUE(png_image_begin_read_from_memory(&image, png.data(), png.size())) << image.message;
  // Written as RGBA, 8 bits per channel: colour type 6 in the header.
  EXPECT_EQ(png.size() > 25 ? int(uint8_t(png[24])) * 256 + uint8_t(png[25]) : -1, 8 * 256 + 6);
  image.format = PNG_FORMAT_RGBA;
  out.width = int(image.width);
  out.height = int(image.height);
  out.pixels.resize(PNG_IMAGE_SIZE(image));
  EXPECT_TRUE(png_image_finish_read(&image, nullptr, out.pixels.data(), 0, nullptr)) << image.message;
  return out;
}

std::vector<uint8_t> pixel(const Rgba& image, int x, int y) {
  const uint8_t* p = image.at(x, y);
  return {p[0], p[1], p[2], p[3]};
}

// A thumbnail of l_stack() shows the L: the part fills 90 % of the picture's smaller side about
// its centre, +x to the right and +y up. Pixels a pixel or more inside the L are opaque, those
// a pixel or more outside it are clear (the edge pixels between are anti-aliased).
void expect_shows_the_l(const Rgba& image) {
  const double w = image.width, h = image.height, px_per_mm = 0.9 * std::min(w, h) / 12;
  const double margin = 1 / px_per_mm;
  auto in_l = [](double x, double y, double grow) {
    const bool foot = x >= -6 - grow && x <= 6 + grow && y >= -6 - grow && y <= -2 + grow;
    const bool arm = x >= -6 - grow && x <= -2 + grow && y >= -6 - grow && y <= 6 + grow;
    return foot || arm;
  };
  size_t opaque = 0, clear = 0, wrong = 0;
  std::string first;
  for (int r = 0; r < image.height; ++r)
    for (int c = 0; c < image.width; ++c) {
      const double x = (c + 0.5 - w / 2) / px_per_mm, y = (h / 2 - r - 0.5) / px_per_mm;
      const uint8_t* p = image.at(c, r);
      const bool on = in_l(x, y, -margin), off = !in_l(x, y, margin);
      const bool ok = on ? p[3] == 255 : off ? p[0] == 0 && p[1] == 0 && p[2] == 0 && p[3] == 0 : true;
      opaque += on && ok;
      clear += off && ok;
      if (!ok && !wrong++) first = format("pixel (%d, %d) at (%g, %g) mm has alpha %d", c, r, x, y, p[3]);
    }
  EXPECT_EQ(wrong, 0u) << image.width << "x" << image.height << ": " << first;
  // The L's 80 mm2 against the rest of the picture, less its edge pixels.
  EXPECT_GT(opaque, size_t(0.95 * 80 * px_per_mm * px_per_mm)) << image.width << "x" << image.height;
  EXPECT_GT(clear, size_t(0.95 * (w * h - 80 * px_per_mm * px_per_mm))) << image.width << "x" << image.height;
}

}  // namespace

TEST_F(Sl1Archive, HoldsPrusaSlicersEntriesLayersAndThumbnailsStored) {
  export_masks(l_stack(), printer_preset("prusa_sl1").profile, path("part.sl1"));
  std::vector<std::string> names;
  for (const Entry& e : entries(path("part.sl1"))) {
    names.push_back(e.name);
    // PNGs are deflated already; the ini files are text.
    EXPECT_EQ(e.stored, e.name.size() > 4 && e.name.substr(e.name.size() - 4) == ".png") << e.name;
  }
  std::vector<std::string> expected{"prusaslicer.ini"};
  for (int k = 0; k < 10; ++k) expected.push_back("part0000" + std::to_string(k) + ".png");
  expected.insert(expected.end(),
                  {"config.ini", "thumbnail/thumbnail400x400.png", "thumbnail/thumbnail800x480.png"});
  EXPECT_EQ(names, expected);
}

TEST_F(Sl1Archive, ProfileTellsPrusaSlicersImportTheDisplayAndThatNothingIsAddedToThePart) {
  export_masks(l_stack(), printer_preset("prusa_sl1s_speed").profile, path("part.sl1s"));
  const std::string slicer = test::zip_entry(path("part.sl1s"), "prusaslicer.ini");
  // The keys the import reads (it throws "Invalid SL1 / SL1S file" without any of them) ...
  for (const char* line : {"display_pixels_x = 2560\n", "display_pixels_y = 1620\n", "display_width = 128\n",
                           "display_height = 81\n", "display_orientation = portrait\n", "display_mirror_x = 1\n",
                           "display_mirror_y = 0\n", "layer_height = 0.1\n", "initial_layer_height = 0.1\n",
                           // ... and what a profile taken over with the model must say about these masks.
                           "supports_enable = 0\n", "pad_enable = 0\n", "hollowing_enable = 0\n",
                           "elefant_foot_compensation = 0\n", "printer_technology = SLA\n", "printer_model = SL1S\n",
                           "thumbnails = 400x400,800x480\n"})
    EXPECT_NE(slicer.find(line), std::string::npos) << line;
}

TEST_F(Sl1Archive, NumbersAreDecimalsWithoutExponent) {
  // The firmware's TOML reader would take 1e-05 for a string.
  export_masks(make_slices({{rect(-1, -1, 1, 1)}}, 0.00001), small_display(), path("fine.sl1"));
  EXPECT_NE(test::zip_entry(path("fine.sl1"), "config.ini").find("layerHeight = 0.00001\n"), std::string::npos);
  EXPECT_NE(test::zip_entry(path("fine.sl1"), "prusaslicer.ini").find("layer_height = 0.00001\n"),
            std::string::npos);
}

TEST_F(Sl1Archive, TopViewKeepsTheHighestLayerOfEveryCell) {
  // small_display: 200 x 200 pixels of 100 um, so cells of 100 um; cell (c, r) has its centre at
  // x = -10 + (c + 1/2) * 0.1, y = 10 - (r + 1/2) * 0.1.
  const Slices s = l_stack();
  TopView view(small_display(), s.layers());
  for (size_t k : {9, 3, 0, 7, 1, 2, 8, 4, 6, 5}) view.add(LayerView(s, k), k);  // any order
  const HeightMap& map = view.finish();
  ASSERT_EQ(map.cols, 200);
  ASSERT_EQ(map.rows, 200);
  size_t arm = 0, foot = 0, other = 0;
  for (int r = 0; r < 200; ++r)
    for (int c = 0; c < 200; ++c) {
      const uint8_t level = map.level[size_t(r) * 200 + size_t(c)];
      const bool in_arm = c >= 40 && c < 80 && r >= 40 && r < 160;
      const bool in_foot = c >= 80 && c < 160 && r >= 120 && r < 160;
      // The arm reaches layer 9 (1 + 254 * 9 / 9), the foot only layer 4 (1 + 254 * 4 / 9).
      EXPECT_EQ(level, in_arm ? 255 : in_foot ? 113 : 0) << c << ", " << r;
      arm += level == 255;
      foot += level == 113;
      other += level != 0 && level != 255 && level != 113;
    }
  EXPECT_EQ(arm, 40u * 120u);
  EXPECT_EQ(foot, 80u * 40u);
  EXPECT_EQ(other, 0u);
}

TEST(TopView, IsDrawnFromTheTopLayerOfEachOf128Bands) {
  // Every layer of a short stack; of a tall one, 128 layers spread evenly up to the last one.
  static_assert(kTopViewLayers == 128);
  const PrinterProfile display = small_display();
  for (size_t layers : {size_t(1), size_t(10), size_t(128), size_t(129), size_t(290), size_t(14484)}) {
    const TopView view(display, layers);
    std::vector<size_t> drawn;
    for (size_t k = 0; k < layers; ++k)
      if (view.draws(k)) drawn.push_back(k);
    ASSERT_EQ(drawn.size(), std::min<size_t>(layers, 128)) << layers;
    EXPECT_EQ(drawn.back(), layers - 1);
    for (size_t i = 0; i < drawn.size(); ++i)  // band i's top layer: the last k with k * 128 / layers == i
      EXPECT_EQ(drawn[i], layers <= 128 ? i : ((i + 1) * layers + 127) / 128 - 1) << layers << ", band " << i;
  }
}

// The pictures' PNG writer (Sub rows, RunDeflater): libpng reads back every pixel, for noise,
// runs of one colour across rows and channels that wrap around (a byte less the one 4 before it),
// at odd sizes; a size PNG cannot hold is refused in words.
TEST(RgbaPng, ReadsBackEveryPixel) {
  std::mt19937 random(3);
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{1, 1}, {3, 7}, {400, 400}, {801, 37}}) {
    std::vector<uint8_t> rgba(size_t(w) * size_t(h) * 4);
    for (size_t i = 0; i < rgba.size(); ++i) {
      const size_t pixel = i / 4, x = pixel % size_t(w);
      rgba[i] = x < size_t(w) / 3 ? uint8_t(random()) : x < 2 * size_t(w) / 3 ? uint8_t(250 - 90 * (i % 4)) : uint8_t(x * 7 + i % 4);
    }
    std::vector<uint8_t> png;
    encode_rgba_png(rgba.data(), w, h, png);
    const Rgba back = decode_rgba(std::string(png.begin(), png.end()));
    ASSERT_EQ(back.width, w);
    ASSERT_EQ(back.height, h);
    EXPECT_TRUE(back.pixels == rgba) << w << "x" << h;
  }
  std::vector<uint8_t> png;
  EXPECT_EQ(test::error_of([&] { encode_rgba_png(nullptr, 0, 5, png); }), "cannot encode a 0x5 RGBA picture as PNG");
}

TEST_F(Sl1Archive, ThumbnailsPictureThePartFromAboveShadedByHeight) {
  export_masks(l_stack(), small_display(), path("l.sl1"));
  const Rgba square = decode_rgba(test::zip_entry(path("l.sl1"), "thumbnail/thumbnail400x400.png"));
  ASSERT_EQ(square.width, 400);
  ASSERT_EQ(square.height, 400);
  // The L's 12 x 12 mm fill 90 % of the picture: 30 pixels per mm around the centre (200, 200),
  // +x to the right and +y up, so (x, y) mm is pixel (200 + 30 x, 200 - 30 y).
  const std::vector<uint8_t> clear{0, 0, 0, 0};
  EXPECT_EQ(pixel(square, 80, 80), (std::vector<uint8_t>{255, 128, 64, 255}));  // arm (-4, 4): top layer
  EXPECT_EQ(pixel(square, 320, 320), (std::vector<uint8_t>{169, 85, 43, 255}));  // foot (4, -4): layer 4
  EXPECT_EQ(pixel(square, 320, 80), clear);                                        // the L's notch (4, 4)
  EXPECT_EQ(pixel(square, 5, 5), clear);
  EXPECT_EQ(pixel(square, 395, 200), clear);
  EXPECT_EQ(pixel(square, 19, 200), clear);  // the arm's left side, x = -6 mm, is at pixel 20
  EXPECT_EQ(pixel(square, 20, 200)[3], 255);

  // 800 x 480: the part's height (12 mm) fills 90 % of 480 pixels, 36 pixels per mm, centred.
  const Rgba wide = decode_rgba(test::zip_entry(path("l.sl1"), "thumbnail/thumbnail800x480.png"));
  ASSERT_EQ(wide.width, 800);
  ASSERT_EQ(wide.height, 480);
  EXPECT_EQ(pixel(wide, 400 - 144, 240 - 144), (std::vector<uint8_t>{255, 128, 64, 255}));  // arm (-4, 4)
  EXPECT_EQ(pixel(wide, 400 + 144, 240 + 144), (std::vector<uint8_t>{169, 85, 43, 255}));  // foot (4, -4)
  EXPECT_EQ(pixel(wide, 400 + 144, 240 - 144), clear);                                      // notch (4, 4)
  EXPECT_EQ(pixel(wide, 400 - 220, 240), clear);  // left of the part (x = -6.1 mm)
}

TEST_F(Sl1Archive, ThumbnailOutlinesAreAntiAliased) {
  // A star's slanted sides cross pixels: their alpha is the share of 4 x 4 samples on the part.
  export_masks(make_slices({{test::star(0.3, -0.2, 3, 7.5, 9)}}), small_display(), path("star.sl1"));
  const Rgba image = decode_rgba(test::zip_entry(path("star.sl1"), "thumbnail/thumbnail400x400.png"));
  size_t partial = 0, other = 0;
  for (size_t i = 3; i < image.pixels.size(); i += 4) {
    const int alpha = image.pixels[i];
    bool sixteenth = false;
    for (int n = 0; n <= 16; ++n) sixteenth |= alpha == (255 * n + 8) / 16;
    other += !sixteenth;
    partial += alpha > 0 && alpha < 255;
  }
  EXPECT_EQ(other, 0u);
  EXPECT_GT(partial, 1000u);
}

TEST_F(Sl1Archive, ThumbnailsShowThePartNotThePrintersMirroredImage) {
  PrinterProfile turned = small_display();
  turned.portrait = true;
  turned.mirror_x = true;
  turned.antialiasing = true;
  export_masks(l_stack(), small_display(), path("plain.sl1"));
  export_masks(l_stack(), turned, path("turned.sl1"));
  for (const char* entry : {"thumbnail/thumbnail400x400.png", "thumbnail/thumbnail800x480.png"}) {
    const std::string turned_png = test::zip_entry(path("turned.sl1"), entry);
    EXPECT_EQ(test::zip_entry(path("plain.sl1"), entry), turned_png) << entry;
    expect_shows_the_l(decode_rgba(turned_png));
  }
}

TEST_F(Sl1Archive, AStackWithNothingOnTheDisplayHasTransparentThumbnails) {
  export_masks(make_slices({{rect(30, 30, 32, 32)}}), small_display(), path("off.sl1"));
  const Rgba image = decode_rgba(test::zip_entry(path("off.sl1"), "thumbnail/thumbnail400x400.png"));
  ASSERT_EQ(image.pixels.size(), 400u * 400u * 4u);
  EXPECT_EQ(image.pixels, std::vector<uint8_t>(image.pixels.size(), 0));
}

TEST_F(Sl1Archive, AJobNameTheReadersWouldMixUpWithTheThumbnailsIsRefused) {
  const Slices s = l_stack();
  for (const char* name : {"thumbnail.sl1", "My_Thumbnail_1.sl1", "t.sl1", "thumb.sl1s"}) {
    const std::string e = test::error_of([&] { export_masks(s, small_display(), path(name)); });
    EXPECT_NE(e.find("cannot tell from its thumbnails"), std::string::npos) << name << ": " << e;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  export_masks(s, small_display(), path("tx.sl1"));  // starts with t, but not as thumbnail/ does
}

TEST_F(Sl1Archive, WhatThePrintersFirmwareWouldNotPrintAsWrittenIsRefused) {
  PrinterProfile sl1 = printer_preset("prusa_sl1").profile;
  const Slices part = l_stack();
  EXPECT_ERROR(export_masks(make_slices({{rect(-1, -1, 1, 1)}}, 0.005), sl1, path("a.sl1")),
               "cannot write '" + path("a.sl1") + "' for the SL1: its layer height 0.005 mm is under 0.01 mm");
  sl1.faded_layers = 1;
  EXPECT_ERROR(export_masks(part, sl1, path("a.sl1")), "its 1 faded layers (numFade) are outside 2..200");
  sl1.faded_layers = 201;
  EXPECT_ERROR(export_masks(part, sl1, path("a.sl1")), "its 201 faded layers (numFade) are outside 2..200");
  sl1 = printer_preset("prusa_sl1s_speed").profile;
  sl1.exposure_s = 61;
  EXPECT_ERROR(export_masks(part, sl1, path("a.sl1s")),
               "for the SL1S: its exposure time 61 s (expTime) is outside 0.1..60 s");
  sl1.exposure_s = 2;
  sl1.bottom_exposure_s = 0.05;
  EXPECT_ERROR(export_masks(part, sl1, path("a.sl1s")),
               "its first layers' exposure time 0.05 s (expTimeFirst) is outside 0.1..120 s");
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  // Other printers' archives (no printerModel) are for converters, which take them as they are.
  PrinterProfile custom = small_display();
  custom.faded_layers = 0;
  export_masks(make_slices({{rect(-1, -1, 1, 1)}}, 0.001), custom, path("fine.sl1"));
}

// SOURCE_DATE_EPOCH set for the scope, restored (unset) after: the creation time print files record.
class SourceDateEpoch {
 public:
  explicit SourceDateEpoch(const char* value) { setenv("SOURCE_DATE_EPOCH", value, 1); }
  ~SourceDateEpoch() { unsetenv("SOURCE_DATE_EPOCH"); }
};

TEST_F(Sl1Archive, SourceDateEpochMakesPrintFilesByteIdenticalWheneverTheyAreMade) {
  // What family.py's batches rely on: a member made again on another worker, or a second later,
  // gives the same bytes as the first time (config.ini's time and the entries' times included).
  // The same file name in two folders: an archive's jobDir (and so its entries' names) is its stem.
  const SourceDateEpoch epoch("1764000000");  // 2025-11-24 16:00:00 UTC
  for (const char* folder : {"first", "second"}) {
    std::filesystem::create_directory(path(folder));
    export_masks(l_stack(), printer_preset("prusa_sl1").profile, path(folder) + "/part.sl1");
    export_masks(l_stack(), printer_preset("elegoo_saturn_3_ultra").profile, path(folder) + "/part.goo");
  }
  EXPECT_EQ(test::slurp(path("first/part.sl1")), test::slurp(path("second/part.sl1")));
  EXPECT_EQ(test::slurp(path("first/part.goo")), test::slurp(path("second/part.goo")));
  EXPECT_NE(test::zip_entry(path("first/part.sl1"), "config.ini")
                .find("fileCreationTimestamp = 2025-11-24 at 16:00:00 UTC\n"),
            std::string::npos);
  for (const Entry& e : entries(path("first/part.sl1"))) EXPECT_EQ(e.mtime, time_t(1764000000)) << e.name;
}

TEST_F(Sl1Archive, AMalformedSourceDateEpochIsRefusedInWords) {
  for (const char* bad : {"yesterday", "-5", "1.5", "1e9"}) {
    const SourceDateEpoch epoch(bad);
    EXPECT_EQ(test::error_of([&] { export_masks(l_stack(), small_display(), path("bad.sl1")); }),
              std::string("SOURCE_DATE_EPOCH is '") + bad +
                  "': it must be the creation time as a whole number of seconds since 1970-01-01 UTC, or unset")
        << bad;
    EXPECT_FALSE(std::filesystem::exists(path("bad.sl1")));
  }
}
