// Every print format presets.json lists (print_formats.h) is written as a file of its own, not a
// folder, and reads back (MaskStack) as the masks of the profile with the grey levels it holds;
// every preset's own format is one of them.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "mask_layers.h"
#include "mask_stack.h"
#include "slicereuse/printer/print_formats.h"
#include "slicereuse/printer/printer_presets.h"
#include "slicereuse/printfiles/export_masks.h"
#include "temp_folder.h"

using namespace slicereuse;

namespace {

class PrintFormats : public test::TempFolderTest {};

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

TEST(PrintFormatsOfPresets, EveryPresetWritesOneOfTheFormatsOrPngImages) {
  for (const PrinterPreset& p : printer_presets()) {
    if (p.extension.empty()) continue;
    const PrintFormat* f = print_format(p.extension);
    ASSERT_NE(f, nullptr) << p.id;
    // A printer whose file holds fewer grey levels has those levels in its PNG folder too.
    EXPECT_EQ(p.profile.grey_levels, f->grey_levels) << p.id;
  }
}
