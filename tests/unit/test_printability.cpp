// The printability checks (check_layers.h) on hand-built stacks whose findings are known exactly.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "fake_host.h"
#include "air_regions.h"
#include "level_runs.h"
#include "mask_layers.h"
#include "shapes.h"
#include "slicereuse/printability/check_layers.h"
#include "slicereuse/printfiles/check_print_file.h"
#include "slicereuse/printfiles/export_masks.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/util/error.h"
#include "temp_folder.h"

namespace slicereuse {
namespace {

constexpr double kPixel = 0.05, kHeight = 0.05;

struct Rect {
  int x0, y0, x1, y1;
  uint8_t level = 255;
};

// A layer of w x h pixels: rects drawn in order (a later one overwrites, level 0 cuts a hole).
MaskImage layer(int w, int h, const std::vector<Rect>& rects) {
  MaskImage m;
  m.width = w;
  m.height = h;
  m.pixels.assign(size_t(w) * size_t(h), 0);
  for (const Rect& r : rects)
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) m.pixels[size_t(y) * size_t(w) + size_t(x)] = r.level;
  return m;
}

// layers[k] are the rects of layer k.
PrintabilityReport check(int w, int h, const std::vector<std::vector<Rect>>& layers) {
  LayerChecker checker(kPixel, kPixel, kHeight);
  for (const auto& rects : layers) checker.add_layer(layer(w, h, rects));
  return checker.finish();
}

std::vector<Finding> of_kind(const PrintabilityReport& r, FindingKind kind) {
  std::vector<Finding> out;
  for (const Finding& f : r.findings)
    if (f.kind == kind) out.push_back(f);
  return out;
}

void expect_box(const Finding& f, int x0, int y0, int x1, int y1) {
  EXPECT_EQ(f.x0, x0);
  EXPECT_EQ(f.y0, y0);
  EXPECT_EQ(f.x1, x1);
  EXPECT_EQ(f.y1, y1);
}

void expect_counts(const PrintabilityReport& r, size_t islands, size_t overhangs, size_t traps, size_t cups,
                   size_t touching) {
  EXPECT_EQ(r.count(FindingKind::Island), islands);
  EXPECT_EQ(r.count(FindingKind::Overhang), overhangs);
  EXPECT_EQ(r.count(FindingKind::ResinTrap), traps);
  EXPECT_EQ(r.count(FindingKind::SuctionCup), cups);
  EXPECT_EQ(r.count(FindingKind::TouchingBounds), touching);
  EXPECT_EQ(r.findings.size(), islands + overhangs + traps + cups + touching);
}

// A closed box [10, 50)^2 of 20 layers: floor layers 0-4, roof 15-19, walls around the cavity
// [20, 40)^2 in between; roof_hole and wall_vent open it.
std::vector<std::vector<Rect>> hollow_box(bool roof_hole, bool wall_vent) {
  std::vector<std::vector<Rect>> layers(20);
  for (int k = 0; k < 20; ++k) {
    layers[size_t(k)].push_back({10, 10, 50, 50});
    if (k >= 5 && k < 15) layers[size_t(k)].push_back({20, 20, 40, 40, 0});
    if (roof_hole && k >= 15) layers[size_t(k)].push_back({28, 28, 32, 32, 0});
    if (wall_vent && k >= 8 && k < 11) layers[size_t(k)].push_back({10, 28, 20, 32, 0});
  }
  return layers;
}

// Row 0's runs as [lo, hi) pairs.
std::vector<int> row0(const LevelRuns& r) {
  std::vector<int> out;
  for (uint32_t i = r.row_begin[0]; i < r.row_begin[1]; ++i) out.insert(out.end(), {r.lo[i], r.hi[i]});
  return out;
}

TEST(LevelRuns, SetOperationsAndLabels) {
  // Levels 255, then 40, then 90 beside it: runs of their own in the mask, one run at level 40.
  const MaskRuns a = mask_runs_of(layer(16, 2, {{0, 0, 5, 1}, {8, 0, 10, 1, 40}, {10, 0, 12, 1, 90}, {5, 1, 8, 2}}));
  EXPECT_EQ(a.row_begin[1], 3u);
  const std::vector<LevelRuns> at = runs_at_levels(a, {1, 41, 91});
  const LevelRuns& nonzero = at[0];
  EXPECT_EQ(row0(nonzero), (std::vector<int>{0, 5, 8, 12}));
  EXPECT_EQ(row0(at[1]), (std::vector<int>{0, 5, 10, 12}));
  EXPECT_EQ(row0(at[2]), (std::vector<int>{0, 5}));
  EXPECT_EQ(row0(air_layer_of(nonzero).runs), (std::vector<int>{5, 8, 12, 16}));
  const LevelRuns b = runs_at_levels(mask_runs_of(layer(16, 2, {{3, 0, 10, 1}})), {1})[0];
  EXPECT_EQ(row0(subtract_runs(nonzero, b)), (std::vector<int>{0, 3, 10, 12}));
  std::vector<int> overlaps;
  for_each_overlap(nonzero, b, 0,
                   [&](uint32_t, uint32_t, int lo, int hi) { overlaps.insert(overlaps.end(), {lo, hi}); });
  EXPECT_EQ(overlaps, (std::vector<int>{3, 5, 8, 10}));
  // Row 1's [5, 8) touches row 0's runs only at corners: one region with diagonals, three without.
  EXPECT_EQ(label_runs(nonzero, false).count, 3u);
  EXPECT_EQ(label_runs(nonzero, true).count, 1u);
}

// A width x height image of random pixels: of every 8, 3 black and `full` at 255 on average, the
// others of any level.
MaskImage random_image(std::mt19937& rng, int width, int height, uint32_t full) {
  MaskImage image;
  image.width = width, image.height = height;
  image.pixels.assign(size_t(width) * size_t(height), 0);
  for (uint8_t& p : image.pixels) {
    const uint32_t r = rng() % 8;
    p = r < 3 ? 0 : r < 3 + full ? 255 : uint8_t(rng() % 256);
  }
  return image;
}

// Every level's runs are exactly the pixels at or above it, on random grey images (runs of every
// level side by side, gaps, rows empty and full), the levels given in no order, the image's
// edges included.
TEST(LevelRuns, AtLevelsAreThePixelsAtOrAboveEachLevel) {
  std::mt19937 rng(11);
  const std::vector<uint8_t> levels{150, 2, 101, 10, 128, 255, 1};
  for (int trial = 0; trial < 40; ++trial) {
    const int width = 1 + int(rng() % 90), height = 1 + int(rng() % 6);
    const MaskImage image = random_image(rng, width, height, 2);
    const std::vector<LevelRuns> at = runs_at_levels(mask_runs_of(image), levels);
    ASSERT_EQ(at.size(), levels.size());
    for (size_t j = 0; j < levels.size(); ++j) {
      std::vector<uint8_t> drawn(image.pixels.size(), 0);
      for (int y = 0; y < height; ++y)
        for (uint32_t i = at[j].row_begin[size_t(y)]; i < at[j].row_begin[size_t(y) + 1]; ++i) {
          if (i > at[j].row_begin[size_t(y)]) EXPECT_LT(at[j].hi[i - 1], at[j].lo[i]) << "runs apart";
          for (int x = at[j].lo[i]; x < at[j].hi[i]; ++x) drawn[size_t(y) * size_t(width) + size_t(x)] = 1;
        }
      for (size_t k = 0; k < drawn.size(); ++k)
        ASSERT_EQ(drawn[k], image.pixels[k] >= levels[j] && image.pixels[k] > 0) << trial << " level " << int(levels[j]) << " pixel " << k;
    }
  }
}

// A layer's air is its pixels <= 100, as runs, in the 4-connected regions a flood fill finds, each
// numbered in order of its first pixel, with its pixels, box and whether it touches the image's
// edge; on random images of solid blocks and grey pixels (rows empty and full, air at the edges).
TEST(AirRegions, AirOfALayerIsItsOtherPixelsInTheirFourConnectedRegions) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 60; ++trial) {
    const int width = 1 + int(rng() % 40), height = 1 + int(rng() % 30);
    const MaskImage image = random_image(rng, width, height, 3);
    const AirLayer air = air_layer_of(runs_at_levels(mask_runs_of(image), {101})[0]);
    // The reference: each air pixel's region, numbered as found scanning the rows.
    std::vector<int> region(image.pixels.size(), -1);
    std::vector<AirRegion> regions;
    for (size_t start = 0; start < image.pixels.size(); ++start) {
      if (image.pixels[start] > 100 || region[start] >= 0) continue;
      AirRegion r;
      r.x0 = width, r.y0 = height;
      std::vector<size_t> stack{start};
      region[start] = int(regions.size());
      while (!stack.empty()) {
        const size_t at = stack.back();
        stack.pop_back();
        const int x = int(at % size_t(width)), y = int(at / size_t(width));
        ++r.pixels;
        r.x0 = std::min(r.x0, x), r.x1 = std::max(r.x1, x + 1), r.y0 = std::min(r.y0, y), r.y1 = std::max(r.y1, y + 1);
        r.border |= x == 0 || y == 0 || x == width - 1 || y == height - 1;
        const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
        for (int d = 0; d < 4; ++d) {
          const int nx = x + dx[d], ny = y + dy[d];
          if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
          const size_t n = size_t(ny) * size_t(width) + size_t(nx);
          if (image.pixels[n] > 100 || region[n] >= 0) continue;
          region[n] = int(regions.size());
          stack.push_back(n);
        }
      }
      regions.push_back(r);
    }
    std::vector<int> drawn(image.pixels.size(), -1);
    for (int y = 0; y < height; ++y)
      for (uint32_t i = air.runs.row_begin[size_t(y)]; i < air.runs.row_begin[size_t(y) + 1]; ++i)
        for (int x = air.runs.lo[i]; x < air.runs.hi[i]; ++x)
          drawn[size_t(y) * size_t(width) + size_t(x)] = int(air.labels.of_run[i]);
    ASSERT_EQ(drawn, region) << "trial " << trial;
    ASSERT_EQ(air.labels.count, regions.size());
    ASSERT_EQ(air.regions.size(), regions.size());
    for (size_t c = 0; c < regions.size(); ++c) {
      const AirRegion &a = air.regions[c], &b = regions[c];
      EXPECT_EQ(a.pixels, b.pixels);
      EXPECT_EQ(std::vector<int>({a.x0, a.y0, a.x1, a.y1}), std::vector<int>({b.x0, b.y0, b.x1, b.y1}));
      EXPECT_EQ(a.border, b.border);
      EXPECT_EQ(air.solid[c], b.pixels < 4 && !b.border);
    }
  }
}

TEST(Printability, SolidBoxHasNothing) {
  const PrintabilityReport r = check(100, 80, std::vector<std::vector<Rect>>(20, {{20, 20, 60, 50}}));
  EXPECT_EQ(r.layers, 20u);
  expect_counts(r, 0, 0, 0, 0, 0);
}

TEST(Printability, FloatingBlockIsOneIslandAtItsFirstLayer) {
  std::vector<std::vector<Rect>> layers(15);
  for (int k = 0; k < 15; ++k) {
    if (k < 10) layers[size_t(k)].push_back({10, 10, 30, 30});
    if (k >= 5) layers[size_t(k)].push_back({60, 20, 80, 40});
  }
  const PrintabilityReport r = check(100, 80, layers);
  expect_counts(r, 1, 0, 0, 0, 0);
  const Finding& f = r.findings[0];
  EXPECT_EQ(f.kind, FindingKind::Island);
  EXPECT_EQ(f.first_layer, 5u);
  EXPECT_EQ(f.last_layer, 5u);
  expect_box(f, 60, 20, 80, 40);
  EXPECT_DOUBLE_EQ(f.area_mm2, 400 * kPixel * kPixel);
  EXPECT_DOUBLE_EQ(f.center_mm[0], 70 * kPixel);
  EXPECT_DOUBLE_EQ(f.center_mm[1], 30 * kPixel);
  EXPECT_DOUBLE_EQ(f.center_mm[2], 5.5 * kHeight);
  EXPECT_DOUBLE_EQ(f.size_mm[0], 20 * kPixel);
  EXPECT_DOUBLE_EQ(f.size_mm[2], kHeight);
}

TEST(Printability, SealedCavityIsOneResinTrapOfItsVolume) {
  const PrintabilityReport r = check(60, 60, hollow_box(false, false));
  expect_counts(r, 0, 0, 1, 0, 0);
  const Finding& f = r.findings[0];
  EXPECT_EQ(f.kind, FindingKind::ResinTrap);
  EXPECT_EQ(f.first_layer, 5u);
  EXPECT_EQ(f.last_layer, 14u);
  expect_box(f, 20, 20, 40, 40);
  EXPECT_DOUBLE_EQ(f.volume_mm3, 20 * 20 * 10 * kPixel * kPixel * kHeight);
  EXPECT_DOUBLE_EQ(r.trapped_mm3(), f.volume_mm3);
  EXPECT_DOUBLE_EQ(f.center_mm[2], 10 * kHeight);
}

// UVtools: a cavity closed towards the plate that drains only through the top is a suction cup.
TEST(Printability, CavityWithRoofHoleIsNoTrapButASuctionCup) {
  const PrintabilityReport r = check(60, 60, hollow_box(true, false));
  expect_counts(r, 0, 0, 0, 1, 0);
  const Finding& f = r.findings[0];
  EXPECT_EQ(f.first_layer, 5u);
  EXPECT_EQ(f.last_layer, 19u);
  EXPECT_DOUBLE_EQ(f.volume_mm3, (20 * 20 * 10 + 4 * 4 * 5) * kPixel * kPixel * kHeight);
}

TEST(Printability, CavityVentedThroughAWallDrains) {
  expect_counts(check(60, 60, hollow_box(false, true)), 0, 0, 0, 0, 0);
}

TEST(Printability, TwoShaftsJoinedAboveAreOneTrap) {
  std::vector<std::vector<Rect>> layers(20);
  for (int k = 0; k < 20; ++k) {
    layers[size_t(k)].push_back({10, 10, 60, 60});
    if (k >= 5 && k < 13) {
      layers[size_t(k)].push_back({20, 20, 28, 40, 0});
      layers[size_t(k)].push_back({40, 20, 48, 40, 0});
    }
    if (k >= 13 && k < 15) layers[size_t(k)].push_back({20, 20, 48, 40, 0});
  }
  const PrintabilityReport r = check(70, 70, layers);
  expect_counts(r, 0, 0, 1, 0, 0);
  expect_box(r.findings[0], 20, 20, 48, 40);
  EXPECT_EQ(r.findings[0].first_layer, 5u);
  EXPECT_DOUBLE_EQ(r.findings[0].volume_mm3, (2 * 8 * 20 * 8 + 28 * 20 * 2) * kPixel * kPixel * kHeight);
}

TEST(Printability, CupOpenAtTheTopIsOneSuctionCup) {
  std::vector<std::vector<Rect>> layers(20);
  for (int k = 0; k < 20; ++k) {
    layers[size_t(k)].push_back({10, 10, 50, 50});
    if (k >= 5) layers[size_t(k)].push_back({20, 20, 40, 40, 0});
  }
  const PrintabilityReport r = check(60, 60, layers);
  expect_counts(r, 0, 0, 0, 1, 0);
  const Finding& f = r.findings[0];
  EXPECT_EQ(f.kind, FindingKind::SuctionCup);
  EXPECT_EQ(f.first_layer, 5u);
  EXPECT_EQ(f.last_layer, 19u);
  expect_box(f, 20, 20, 40, 40);
  EXPECT_DOUBLE_EQ(f.volume_mm3, 20 * 20 * 15 * kPixel * kPixel * kHeight);
}

TEST(Printability, CupTooShallowIsNoSuctionCup) {
  // 9 layers of 0.05 mm: under UVtools' 0.5 mm.
  std::vector<std::vector<Rect>> layers(14);
  for (int k = 0; k < 14; ++k) {
    layers[size_t(k)].push_back({10, 10, 50, 50});
    if (k >= 5) layers[size_t(k)].push_back({20, 20, 40, 40, 0});
  }
  expect_counts(check(60, 60, layers), 0, 0, 0, 0, 0);
}

// UVtools: a cavity on the plate (open at the bottom, closed above) is neither a trap nor a cup.
TEST(Printability, UpsideDownCupOnThePlateIsNothing) {
  std::vector<std::vector<Rect>> layers(20);
  for (int k = 0; k < 20; ++k) {
    layers[size_t(k)].push_back({10, 10, 50, 50});
    if (k < 15) layers[size_t(k)].push_back({20, 20, 40, 40, 0});
  }
  expect_counts(check(60, 60, layers), 0, 0, 0, 0, 0);
}

TEST(Printability, PartWithinFivePixelsOfTheEdgeTouchesBounds) {
  std::vector<std::vector<Rect>> layers(6);
  for (int k = 0; k < 6; ++k) {
    layers[size_t(k)].push_back({30, 30, 60, 60});
    if (k >= 1 && k < 4) layers[size_t(k)].push_back({2, 30, 30, 40});
  }
  const PrintabilityReport r = check(100, 80, layers);
  ASSERT_EQ(r.count(FindingKind::TouchingBounds), 1u);
  const Finding f = of_kind(r, FindingKind::TouchingBounds)[0];
  EXPECT_EQ(f.first_layer, 1u);
  EXPECT_EQ(f.last_layer, 3u);
  expect_box(f, 2, 30, 5, 40);
  EXPECT_DOUBLE_EQ(f.area_mm2, 3 * 3 * 10 * kPixel * kPixel);
  // Five pixels from every edge is clear.
  expect_counts(check(100, 80, std::vector<std::vector<Rect>>(3, {{5, 5, 95, 75}})), 0, 0, 0, 0, 0);
}

TEST(Printability, TouchingBoundsCountsBothMarginsOfARowAndOnlyBrightPixels) {
  // A bar across the image (rows 30-31): 5 pixels in each margin of each row; a grey block (100,
  // under UVtools' 127) in the right margin: nothing; a bright one (200) there: 4 pixels.
  const PrintabilityReport r = check(100, 80, {{{0, 30, 100, 32}, {93, 50, 100, 52, 100}, {96, 60, 100, 61, 200}}});
  ASSERT_EQ(r.count(FindingKind::TouchingBounds), 1u);
  const Finding f = of_kind(r, FindingKind::TouchingBounds)[0];
  expect_box(f, 0, 30, 100, 61);
  EXPECT_DOUBLE_EQ(f.area_mm2, (2 * 2 * 5 + 4) * kPixel * kPixel);
}

TEST(Printability, LedgeOverhangsAtItsLayer) {
  // A column [10, 60) x [10, 90); from layer 10 a ledge [60, 130) beside it. Eroding 40 from the
  // column's side (the other sides are the layers' box, which does not erode) leaves x >= 100.
  std::vector<std::vector<Rect>> layers(15);
  for (int k = 0; k < 15; ++k) {
    layers[size_t(k)].push_back({10, 10, 60, 90});
    if (k >= 10) layers[size_t(k)].push_back({60, 10, 130, 90});
  }
  const PrintabilityReport r = check(200, 100, layers);
  expect_counts(r, 0, 1, 0, 0, 0);
  const Finding& f = r.findings[0];
  EXPECT_EQ(f.kind, FindingKind::Overhang);
  EXPECT_EQ(f.first_layer, 10u);
  expect_box(f, 100, 10, 130, 90);
  EXPECT_DOUBLE_EQ(f.area_mm2, 30 * 80 * kPixel * kPixel);
}

TEST(Printability, LedgeErodesFromEverySideButTheLayersBox) {
  // The column [10, 60) x [10, 190) sets the box; the ledge [60, 200) x [50, 150) erodes from the
  // column (x >= 100 remain) and from above and below (rows [90, 110) remain), not from x = 200.
  std::vector<std::vector<Rect>> layers(12);
  for (int k = 0; k < 12; ++k) {
    layers[size_t(k)].push_back({10, 10, 60, 190});
    if (k >= 10) layers[size_t(k)].push_back({60, 50, 200, 150});
  }
  const PrintabilityReport r = check(250, 200, layers);
  ASSERT_EQ(r.count(FindingKind::Overhang), 1u);
  const Finding f = of_kind(r, FindingKind::Overhang)[0];
  EXPECT_EQ(f.first_layer, 10u);
  expect_box(f, 100, 90, 200, 110);
  EXPECT_DOUBLE_EQ(f.area_mm2, 100 * 20 * kPixel * kPixel);
}

TEST(Printability, LedgeErodesFromTheUnlitRowsOfItsOwnLayersBox) {
  // Below: a band [10, 150) x [0, 20). Above: the band, a ledge [10, 150) x [20, 140) under it
  // and a speck at row 160, so the box of the two layers reaches row 161 though the layer below
  // ends at row 20. The ledge erodes from the band (rows >= 60 remain) and from the unlit rows
  // [140, 160) (rows < 100 remain), not from its sides, the box's. (The box once ended at the
  // layer below's last row, and the ledge then kept rows [60, 140).)
  const std::vector<std::vector<Rect>> layers = {{{10, 0, 150, 20}},
                                                 {{10, 0, 150, 20}, {10, 20, 150, 140}, {10, 160, 11, 161}}};
  const PrintabilityReport r = check(200, 180, layers);
  ASSERT_EQ(r.count(FindingKind::Overhang), 1u);
  const Finding f = of_kind(r, FindingKind::Overhang)[0];
  expect_box(f, 10, 60, 150, 100);
  EXPECT_DOUBLE_EQ(f.area_mm2, 140 * 40 * kPixel * kPixel);
}

TEST(Printability, NarrowLedgeErodesAway) {
  std::vector<std::vector<Rect>> layers(15);
  for (int k = 0; k < 15; ++k) {
    layers[size_t(k)].push_back({10, 10, 100, 90});
    if (k >= 10) layers[size_t(k)].push_back({100, 10, 140, 90});
  }
  expect_counts(check(200, 100, layers), 0, 0, 0, 0, 0);
}

TEST(Printability, GreyIslandNeedsBrightSupport) {
  // A block resting on pixels of level 149 (under UVtools' 150 for support) is an island.
  std::vector<std::vector<Rect>> layers = {{{10, 10, 30, 30, 149}}, {{10, 10, 30, 30}}};
  const PrintabilityReport r = check(60, 60, layers);
  ASSERT_EQ(r.count(FindingKind::Island), 1u);
  EXPECT_EQ(of_kind(r, FindingKind::Island)[0].first_layer, 1u);
  layers[0][0].level = 150;
  EXPECT_EQ(check(60, 60, layers).count(FindingKind::Island), 0u);
}

// 10,000 layers stream through: the regions are carried layer to layer, not kept per layer.
TEST(Printability, TenThousandLayersStream) {
  LayerChecker checker(kPixel, kPixel, kHeight);
  const MaskImage floor = layer(40, 40, {{5, 5, 35, 35}});
  const MaskImage walls = layer(40, 40, {{5, 5, 35, 35}, {10, 10, 30, 30, 0}});
  for (size_t k = 0; k < 10000; ++k) checker.add_layer(k < 5 || k >= 9995 ? floor : walls);
  const PrintabilityReport r = checker.finish();
  expect_counts(r, 0, 0, 1, 0, 0);
  EXPECT_EQ(r.findings[0].first_layer, 5u);
  EXPECT_EQ(r.findings[0].last_layer, 9994u);
  EXPECT_DOUBLE_EQ(r.findings[0].volume_mm3, 20.0 * 20 * 9990 * kPixel * kPixel * kHeight);
}

TEST(Printability, LayersOfAnotherSizeAreRefused) {
  LayerChecker checker(kPixel, kPixel, kHeight);
  checker.add_layer(layer(10, 10, {}));
  EXPECT_THROW(checker.add_layer(layer(10, 11, {})), Error);
}

TEST(Printability, CsvHasOneRowPerFinding) {
  const PrintabilityReport r = check(60, 60, hollow_box(false, false));
  const std::string path = testing::TempDir() + "printability.csv";
  write_printability_csv(r, path);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(),
            "kind,first_layer,last_layer,x0,y0,x1,y1,center_x_mm,center_y_mm,center_z_mm,size_x_mm,size_y_mm,"
            "size_z_mm,area_mm2,volume_mm3\n"
            "resin_trap,5,14,20,20,40,40,1.5,1.5,0.5,1,1,0.5,0,0.5\n");
  std::remove(path.c_str());
}

// A .goo file from contours (small_display: 200 x 200 pixels of 0.1 mm, 20 x 20 mm around the
// origin; layers of 0.1 mm): a box [-5, 5]^2 whose cavity [-2, 2]^2 of layers 5-14 is sealed,
// and a block [6, 8]^2 floating from layer 10.
class PrintabilityFile : public test::TempFolderTest {
 protected:
  std::string make_print_file() {
    std::vector<test::Layer> layers(20);
    for (size_t k = 0; k < 20; ++k) {
      layers[k].push_back(test::rect(-5, -5, 5, 5));
      if (k >= 5 && k < 15) layers[k].push_back(test::rect(-2, -2, 2, 2, true));
      if (k >= 10) layers[k].push_back(test::rect(6, 6, 8, 8));
    }
    const std::string file = path("box.goo");
    export_masks(test::make_slices(layers, 0.1), test::small_display(), file);
    return file;
  }
};

TEST_F(PrintabilityFile, CheckOfAPrintFileFindsTheTrapAndTheIsland) {
  const PrintabilityReport r = check_print_file(make_print_file(), 0.1, 0.1, 0.1, path("r.csv"));
  EXPECT_EQ(r.layers, 20u);
  expect_counts(r, 1, 0, 1, 0, 0);
  const Finding island = of_kind(r, FindingKind::Island)[0];
  EXPECT_EQ(island.first_layer, 10u);
  expect_box(island, 160, 20, 180, 40);  // row 0 at y = 10 mm
  const Finding trap = of_kind(r, FindingKind::ResinTrap)[0];
  expect_box(trap, 80, 80, 120, 120);
  EXPECT_NEAR(trap.volume_mm3, 40 * 40 * 10 * 0.01 * 0.1, 1e-9);
  std::ifstream csv(path("r.csv"));
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(csv, line)) rows.push_back(line);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1].rfind("island,10,10,160,20,180,40,", 0), 0u) << rows[1];
  EXPECT_EQ(rows[2].rfind("resin_trap,5,14,80,80,120,120,", 0), 0u) << rows[2];
}

TEST_F(PrintabilityFile, FilterCountsLogsAndShowsTheFindings) {
  using namespace plugin;
  const std::string file = make_print_file();
  FakeHost host;
  const FilterSpec& spec = spec_named("check_printability");
  const PrinterProfile display = test::small_display();
  const Result r = spec.run(defaults(spec, {{"print_file", file}, {"report_file", path("f.csv")}},
                                     {{"layer_thickness", 0.1},
                                      {"width_px", display.width_px},
                                      {"height_px", display.height_px},
                                      {"pixel_size_x_um", display.pixel_size_x_um},
                                      {"pixel_size_y_um", display.pixel_size_y_um}}),
                            host);
  EXPECT_EQ(keys_of(r), (std::set<std::string>{"islands", "overhangs", "resin_traps", "suction_cups",
                                               "touching_bounds", "layers", "trapped_mm3", "seconds"}));
  EXPECT_EQ(count(r, "islands"), 1);
  EXPECT_EQ(count(r, "overhangs"), 0);
  EXPECT_EQ(count(r, "resin_traps"), 1);
  EXPECT_EQ(count(r, "suction_cups"), 0);
  EXPECT_EQ(count(r, "touching_bounds"), 0);
  EXPECT_EQ(count(r, "layers"), 20);
  EXPECT_NEAR(std::get<double>(r.at("trapped_mm3")), 16, 1e-9);
  // One point per finding at its centre on the build plate: the island's block, the cavity.
  const std::vector<double>& xyz = host.point_layers.at("printability findings");
  ASSERT_EQ(xyz.size(), 6u);
  const double expected[6] = {7, 7, 1.05, 0, 0, 1.0};
  for (size_t i = 0; i < 6; ++i) EXPECT_NEAR(xyz[i], expected[i], 1e-9) << i;
  size_t finding_lines = 0;
  for (const std::string& l : host.lines) finding_lines += l.find("layers 10-10, centre (17.00, 3.00) mm") != std::string::npos ||
                                                           l.find("resin_trap, layers 5-14") != std::string::npos;
  EXPECT_EQ(finding_lines, 2u);
  EXPECT_TRUE(std::filesystem::exists(path("f.csv")));
}

TEST_F(PrintabilityFile, FilterLogsTwentyFindingsAndCountsTheRest) {
  using namespace plugin;
  // 22 blocks of 1 x 1 mm floating from layer 1 over a plate layer elsewhere: 22 islands.
  std::vector<test::Layer> layers(3);
  layers[0].push_back(test::rect(-9, -9, -7, -7));
  for (size_t k = 1; k < 3; ++k)
    for (int i = 0; i < 22; ++i) {
      const double x = -8 + 1.5 * (i % 11), y = 2 + 2 * (i / 11);
      layers[k].push_back(test::rect(x, y, x + 1, y + 1));
    }
  export_masks(test::make_slices(layers, 0.1), test::small_display(), path("blocks.goo"));
  FakeHost host;
  const FilterSpec& spec = spec_named("check_printability");
  const PrinterProfile display = test::small_display();
  const Result r = spec.run(defaults(spec, {{"print_file", path("blocks.goo")}},
                                     {{"width_px", display.width_px},
                                      {"height_px", display.height_px},
                                      {"pixel_size_x_um", display.pixel_size_x_um},
                                      {"pixel_size_y_um", display.pixel_size_y_um}}),
                            host);
  EXPECT_EQ(count(r, "islands"), 22);
  size_t finding_lines = 0, more = 0;
  for (const std::string& l : host.lines) {
    finding_lines += l.rfind("Check Printability: island, layers 1-1", 0) == 0;
    more += l == "Check Printability: and 2 more";
  }
  EXPECT_EQ(finding_lines, 20u);
  EXPECT_EQ(more, 1u);
  EXPECT_EQ(host.point_layers.at("printability findings").size(), 3u * 22);
}

}  // namespace
// With no print file, the current layer's masks: a hollow mesh shows its resin trap and a cup its
// suction cup, as the print job's file of the same mesh shows them; a contour layer is checked
// with its own layers.
TEST_F(PrintabilityFile, FilterChecksTheCurrentMeshOrContourLayerAsItsPrintJob) {
  using namespace plugin;
  FakeHost host;
  host.meshes = {test::make_hollow_box(-5, -5, 0, 5, 5, 6, 2), test::make_cup(-5, -5, 0, 5, 5, 6, 2)};
  const PrinterProfile display = test::small_display();
  const std::map<std::string, double> printer = {{"layer_thickness", 0.1},
                                                 {"width_px", display.width_px},
                                                 {"height_px", display.height_px},
                                                 {"pixel_size_x_um", display.pixel_size_x_um},
                                                 {"pixel_size_y_um", display.pixel_size_y_um}};
  const FilterSpec& spec = spec_named("check_printability");
  const FilterSpec& job = spec_named("make_print_job");
  for (int m = 0; m < 2; ++m) {
    SCOPED_TRACE(m);
    host.current = m;
    const Result current = spec.run(defaults(spec, {{"report_file", path("c.csv")}}, printer), host);
    EXPECT_EQ(count(current, "layers"), 60);
    EXPECT_EQ(count(current, "resin_traps"), m == 0 ? 1 : 0);
    EXPECT_EQ(count(current, "suction_cups"), m == 1 ? 1 : 0);
    EXPECT_EQ(count(current, "islands"), 0);
    const Result made = job.run(defaults(job, {{"output_path", path("job.goo")}}, printer), host);
    const Result file = spec.run(defaults(spec, {{"print_file", path("job.goo")}, {"report_file", path("f.csv")}}, printer), host);
    for (const char* key : {"islands", "overhangs", "resin_traps", "suction_cups", "touching_bounds"}) {
      EXPECT_EQ(count(current, key), count(file, key)) << key;
      EXPECT_EQ(count(made, key), count(file, key)) << key;
    }
    std::ifstream a(path("c.csv")), b(path("f.csv"));
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(a), {}), std::string(std::istreambuf_iterator<char>(b), {}));
  }
  SliceOptions so;
  so.thickness = 0.2;
  host.contour_layer = slice_layers(host.meshes[1], so);
  const Result contours = spec.run(defaults(spec, {}, printer), host);
  EXPECT_EQ(count(contours, "layers"), 30);
  EXPECT_EQ(count(contours, "suction_cups"), 1);
}

}  // namespace slicereuse
