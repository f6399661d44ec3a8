// The grey levels a printer's file holds (grey_levels.h): the nearest representable level, and
// anti-aliased masks of a profile with fewer levels equal to the 256-level masks mapped to them.
#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <vector>

#include "mask_layers.h"
#include "slicereuse/printer/grey_levels.h"
#include "slicereuse/printer/print_formats.h"
#include "slicereuse/printer/printer_profile.h"

using namespace slicereuse;

TEST(GreyLevels, TheNearestLevelTheFileHolds) {
  // Chitubox: 0, then 2c + 1 for c = 1..127; a tie goes to the lower level.
  EXPECT_EQ(representable_grey_level(0, 128), 0);
  EXPECT_EQ(representable_grey_level(1, 128), 0);
  EXPECT_EQ(representable_grey_level(2, 128), 3);
  EXPECT_EQ(representable_grey_level(4, 128), 3);
  EXPECT_EQ(representable_grey_level(5, 128), 5);
  EXPECT_EQ(representable_grey_level(254, 128), 253);
  EXPECT_EQ(representable_grey_level(255, 128), 255);
  // Anycubic: multiples of 17.
  EXPECT_EQ(representable_grey_level(8, 16), 0);
  EXPECT_EQ(representable_grey_level(9, 16), 17);
  EXPECT_EQ(representable_grey_level(25, 16), 17);
  EXPECT_EQ(representable_grey_level(26, 16), 34);
  EXPECT_EQ(representable_grey_level(246, 16), 238);
  EXPECT_EQ(representable_grey_level(247, 16), 255);
  std::set<int> held128, held16;
  for (int v = 0; v < 256; ++v) {
    EXPECT_EQ(representable_grey_level(uint8_t(v), 256), v);
    held128.insert(representable_grey_level(uint8_t(v), 128));
    held16.insert(representable_grey_level(uint8_t(v), 16));
  }
  EXPECT_EQ(held128.size(), 128u);
  EXPECT_EQ(held16.size(), 16u);
}

TEST(GreyLevels, FewerLevelsAreThe256LevelMasksMappedToThem) {
  const Slices s = test::make_slices({{test::star(0.3, -0.2, 2.1, 5.3, 7)}});
  PrinterProfile p = test::small_display();
  p.antialiasing = true;
  for (double gamma : {1.0, 0.7}) {
    p.gamma = gamma;
    p.grey_levels = 256;
    const std::vector<uint8_t> full = test::raster(s, 0, p);
    size_t grey = 0;
    for (uint8_t v : full) grey += v != 0 && v != 255;
    ASSERT_GT(grey, 100u);
    for (int levels : {128, 16}) {
      p.grey_levels = levels;
      const std::vector<uint8_t> held = test::raster(s, 0, p);
      ASSERT_EQ(held.size(), full.size());
      for (size_t i = 0; i < full.size(); ++i)
        ASSERT_EQ(held[i], representable_grey_level(full[i], levels)) << "pixel " << i << ", " << levels << " levels";
    }
  }
}

TEST(GreyLevels, AFormatWithFewerLevelsLowersTheProfiles) {
  PrinterProfile p;
  EXPECT_EQ(profile_for_format(p, print_format(".ctb")).grey_levels, 128);
  EXPECT_EQ(profile_for_format(p, print_format(".pwmx")).grey_levels, 16);
  EXPECT_EQ(profile_for_format(p, print_format(".sl1")).grey_levels, 256);
  EXPECT_EQ(profile_for_format(p, nullptr).grey_levels, 256);
  p.grey_levels = 16;
  EXPECT_EQ(profile_for_format(p, print_format(".goo")).grey_levels, 16);
  EXPECT_EQ(print_format(".CTB"), nullptr);  // callers lower-case the extension
}
