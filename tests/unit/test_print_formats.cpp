// Every print format presets.json lists (print_formats.h) is written as a file of its own, not a
// folder, and reads back (MaskStack) as the masks of the profile with the grey levels it holds;
// made from ranges of layers it is the same file byte for byte; a cancelled export leaves
// nothing and keeps an old file; every preset's own format is one of them.
#include <gtest/gtest.h>

#include <stdlib.h>

#include <filesystem>
#include <string>
#include <vector>

#include "mask_layers.h"
#include "mask_stack.h"
#include "print_file_tests.h"
#include "slicereuse/printer/print_formats.h"
#include "slicereuse/printer/printer_presets.h"
#include "slicereuse/printfiles/export_masks.h"
#include "slicereuse/util/error.h"
#include "temp_folder.h"

using namespace slicereuse;

namespace {

class PrintFormats : public test::TempFolderTest {};

namespace fs = std::filesystem;

}  // namespace

TEST_F(PrintFormats, EveryFormatIsWrittenAsAFileAndReadsBackAsItsMasks) {
  const Slices s = test::make_slices({{test::star(0.3, -0.2, 2.1, 5.3, 7)},
                                      {test::star(0.1, 0.4, 1.7, 4.9, 5), test::rect(-9, -9, -7, -6)}});
  PrinterProfile p = test::small_display();
  p.antialiasing = true;
  ASSERT_GE(print_formats().size(), 10u);
  for (const PrintFormat& f : print_formats()) {
    const std::string out = path("job" + f.extension);
    export_masks(s, p, out);
    ASSERT_TRUE(std::filesystem::is_regular_file(out)) << f.extension << " was not written as a file";
    const PrinterProfile held = profile_for_format(p, &f);
    EXPECT_EQ(held.grey_levels, f.grey_levels) << f.extension;
    MaskStack stack(out);
    ASSERT_EQ(stack.layers(), s.layers()) << f.extension;
    std::vector<uint8_t> bytes;
    MaskImage image;
    for (size_t k = 0; k < s.layers(); ++k) {
      stack.read(k, bytes);
      stack.decode(k, bytes, image);
      EXPECT_EQ(image.pixels, test::raster(s, k, held)) << f.extension << ", layer " << k;
    }
  }
}

TEST_F(PrintFormats, EveryFormatMadeFromRangesOfLayersIsTheSameFileByteForByte) {
  ::setenv("SOURCE_DATE_EPOCH", "1764000000", 1);  // one creation time for both files
  const std::vector<test::Layer> layers = test::part_layers();
  SliceChunks chunks;
  chunks.first = {0, 2, 3, layers.size()};
  chunks.thickness = 0.1;
  chunks.make = [&](size_t i, const Progress&) {
    std::vector<SlicePart> parts;
    parts.push_back(
        {test::make_slices({layers.begin() + long(chunks.first[i]), layers.begin() + long(chunks.first[i + 1])}), 0});
    return parts;
  };
  for (const PrintFormat& f : print_formats())
    for (bool aa : {false, true}) {
      PrinterProfile p = test::small_display();
      p.mirror_x = p.mirror_y = true;
      p.offset_x_mm = 0.37;
      p.antialiasing = aa;
      // The same name in two folders: an .sl1 names its entries after the file.
      const std::string whole_path = path("whole/job" + f.extension), ranged_path = path("ranged/job" + f.extension);
      fs::create_directories(path("whole"));
      fs::create_directories(path("ranged"));
      const MaskExportStats whole = export_masks(test::make_slices(layers), p, whole_path);
      const MaskExportStats ranged = export_masks(chunks, p, ranged_path);
      EXPECT_EQ(ranged.layers, whole.layers);
      EXPECT_TRUE(test::read_bytes(whole_path) == test::read_bytes(ranged_path))
          << f.extension << (aa ? ", anti-aliased" : ", binary");
    }
  ::unsetenv("SOURCE_DATE_EPOCH");
}

TEST_F(PrintFormats, ACancelledExportOfEveryFormatLeavesNothingAndKeepsAnOldFile) {
  const Slices s = test::make_slices(std::vector<test::Layer>(300, test::Layer{test::star(0.3, -0.2, 3, 7.5, 9)}));
  for (const PrintFormat& f : print_formats()) {
    int calls = 0;
    const Progress cancel = [&](double, const char*) { return ++calls < 3; };
    EXPECT_THROW(export_masks(s, test::small_display(), path("c" + f.extension), cancel), Cancelled) << f.extension;
    EXPECT_TRUE(fs::is_empty(dir)) << f.extension;
    const std::string keep = path("keep" + f.extension);
    export_masks(test::make_slices(test::part_layers()), test::small_display(), keep);
    const std::string before = test::read_bytes(keep);
    calls = 0;
    EXPECT_THROW(export_masks(s, test::small_display(), keep, cancel), Cancelled) << f.extension;
    EXPECT_EQ(test::read_bytes(keep), before) << f.extension;
    EXPECT_EQ(std::vector<fs::path>(fs::directory_iterator(dir), {}), std::vector<fs::path>{keep});
    fs::remove(keep);
  }
}

TEST(PrintFormatsOfPresets, EveryPresetWritesOneOfTheFormatsOrPngImages) {
  for (const PrinterPreset& p : printer_presets()) {
    if (p.extension.empty()) continue;
    const PrintFormat* f = print_format(p.extension);
    ASSERT_NE(f, nullptr) << p.id;
    // A printer whose file holds fewer grey levels has those levels in its PNG folder too.
    EXPECT_EQ(p.profile.grey_levels, f->grey_levels) << p.id;
  }
}
