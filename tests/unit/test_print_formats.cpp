// Every print format presets.json lists (print_formats.h) is written as a file of its own, not a
// folder, and reads back (MaskStack) as the masks of the profile with the grey levels it holds;
// made from ranges of layers it is the same file byte for byte; a cancelled export leaves
// nothing and keeps an old file; every preset's own format is one of them. A supported stack's
// resin traps are lit in every format, however its layers are made.
#include <gtest/gtest.h>

#include <stdlib.h>

#include <filesystem>
#include <string>
#include <vector>

#include "error_of.h"
#include "mask_layers.h"
#include "mask_stack.h"
#include "print_file_tests.h"
#include "slicereuse/printer/print_formats.h"
#include "slicereuse/printability/printability_report.h"
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

TEST_F(PrintFormats, ASupportedStacksResinTrapsAreLitInEveryFormatHoweverItsLayersAreMade) {
  // A part's floor, three layers of a ring around a 3 x 3 mm pocket a pillar stands in, and a
  // lid: the pocket is a resin trap. With the pillar a support's, every file, made from a range
  // of layers or a layer at a time, reads back as five solid squares and its check finds no
  // trap; with the pillar the part's, the pocket stays and the check finds it.
  const test::Layer solid{test::rect(-3, -3, 3, 3)};
  const test::Layer ring{test::rect(-3, -3, 3, 3), test::rect(-1.5, -1.5, 1.5, 1.5, true)};
  const test::Loop pillar = test::rect(-0.5, -0.5, 0.5, 0.5);
  const std::vector<test::Layer> part{solid, ring, ring, ring, solid};
  const Slices lit = test::make_slices(std::vector<test::Layer>(5, solid));
  const Slices unlit = test::make_slices({solid, {ring[0], ring[1], pillar}, {ring[0], ring[1], pillar},
                                          {ring[0], ring[1], pillar}, solid});
  const PrinterProfile p = test::small_display();
  for (bool supports : {true, false}) {
    SliceChunks chunks{{0, 5}, 0.1, [&](size_t, const Progress&) {
                         std::vector<SlicePart> parts(2);
                         parts[0].slices = test::make_slices(part);
                         parts[1] = {test::make_slices(std::vector<test::Layer>(3, {pillar})), 1, supports};
                         return parts;
                       },
                       supports};
    LayerMaker maker{5, 0.1,
                     [&](size_t k, std::vector<SlicePart>& parts) {
                       parts.assign(k >= 1 && k <= 3 ? 2 : 1, SlicePart());
                       parts[0].slices = test::make_slices({part[k]});
                       if (parts.size() == 2) parts[1] = {test::make_slices({{pillar}}), 0, supports};
                     },
                     supports};
    std::vector<std::string> outputs{path(supports ? "folder_supported" : "folder")};
    for (const PrintFormat& f : print_formats())
      outputs.push_back(path((supports ? "supported" : "job") + f.extension));
    for (const std::string& out : outputs)
      for (bool made_where_drawn : {false, true}) {
        fs::remove_all(out);
        size_t traps = 99;
        const MaskChecks checks{[&](PrintabilityReport r) { traps = r.count(FindingKind::ResinTrap); }};
        if (made_where_drawn)
          export_masks(maker, p, out, {}, &checks);
        else
          export_masks(chunks, p, out, {}, &checks);
        const std::string what = out + (made_where_drawn ? ", made where drawn" : ", a range");
        EXPECT_EQ(traps, supports ? 0u : 1u) << what;
        const PrinterProfile held = profile_for_format(p, print_format(fs::path(out).extension().string()));
        MaskStack stack(out);
        ASSERT_EQ(stack.layers(), 5u) << what;
        std::vector<uint8_t> bytes;
        MaskImage image;
        for (size_t k = 0; k < 5; ++k) {
          stack.read(k, bytes);
          stack.decode(k, bytes, image);
          EXPECT_EQ(image.pixels, test::raster(supports ? lit : unlit, k, held)) << what << ", layer " << k;
        }
      }
    if (!supports) continue;
    // Every mask is held until the traps are found: refused in words beforehand when they would
    // not fit, and nothing written.
    ::setenv("SLICEREUSE_MEMORY_LIMIT", "1K", 1);
    EXPECT_ERROR(export_masks(chunks, p, path("refused.sl1")),
                 "holding the masks of all 5 layers of a supported print to find the resin traps its supports close "
                 "needs");
    ::unsetenv("SLICEREUSE_MEMORY_LIMIT");
    EXPECT_FALSE(fs::exists(path("refused.sl1")));
  }
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
