// Elephant-foot compensation faded over an object's first layers as PrusaSlicer fades it: the
// values layer by layer, exact areas of shrunk boxes, layers above the fade untouched, ranges
// equal to the whole stack, a member on its supports and pad counted from the pad's bottom,
// objects faded apart, narrow features kept, faded_layers 0 to 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "error_of.h"
#include "shapes.h"
#include "slicereuse/plates/faded_layers.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/slicing/slice_layers.h"

using namespace slicereuse;

namespace {

constexpr double kFoot = 0.2;

PrinterProfile profile_fading(int faded_layers) {
  PrinterProfile p;
  p.elephant_foot_mm = kFoot;
  p.elephant_foot_min_width_mm = 0.2;
  p.faded_layers = faded_layers;
  return p;
}

// A box's layers [a, b) of 0.1 mm from z = 0, as a part from range layer `first`.
SlicePart box_part(double x0, double y0, double x1, double y1, size_t a, size_t b, size_t first) {
  SliceOptions so;
  so.thickness = 0.1;
  so.z_start = 0;
  const Slices s = slice_layers(test::make_box(x0, y0, 0, x1, y1, 2), so);
  SlicePart p;
  layers_into(s, a, b, p.slices, true);
  p.first = first;
  return p;
}

// The parts' layers [a, b) as a range's (counted from a), with their owners.
std::vector<SlicePart> range_of(const std::vector<SlicePart>& parts, const std::vector<size_t>& owners, size_t a,
                                size_t b, std::vector<size_t>& range_owners) {
  std::vector<SlicePart> range;
  range_owners.clear();
  for (size_t i = 0; i < parts.size(); ++i) {
    const SlicePart& p = parts[i];
    const size_t lo = std::max(a, p.first), hi = std::min(b, p.first + p.slices.layers());
    if (lo >= hi) continue;
    range.emplace_back();
    layers_into(p.slices, lo - p.first, hi - p.first, range.back().slices, true);
    range.back().first = lo - a;
    range_owners.push_back(owners[i]);
  }
  return range;
}

// The region of the parts' layer r, all parts together.
ClipperLib::Paths region_at(const std::vector<SlicePart>& parts, size_t r) {
  std::vector<LayerPart> at;
  for (const SlicePart& p : parts)
    if (p.first <= r && r < p.first + p.slices.layers()) at.push_back({&p.slices, r - p.first});
  return layer_region(LayerView(at.data(), at.size()));
}

double area_at(const std::vector<SlicePart>& parts, size_t r) { return region_area_mm2(region_at(parts, r)); }

// PrusaSlicer's fade, written out: (E - k) efc / E over k < E = max(1, min(layers, faded) - 1).
double expected_mm(size_t e, size_t k) { return k < e ? double(e - k) * kFoot / double(e) : 0; }

// The offset the regions take: to the nearest Clipper unit (1 nm, layer_region.h).
double in_units(double mm) { return std::round(mm * kRegionScale) / kRegionScale; }

// A square of side s shrunk by c with miter joins.
double square(double s, double c) { return (s - 2 * c) * (s - 2 * c); }

}  // namespace

TEST(FadedLayers, TheCompensationFadesLinearlyFromTheFullValueOnLayerZero) {
  const PrinterProfile p = profile_fading(10);
  // 10 faded layers of a tall object: layer 0 full, down by a ninth a layer, none from layer 9.
  for (size_t k = 0; k < 14; ++k) EXPECT_DOUBLE_EQ(faded_compensation_mm(p, 100, k), expected_mm(9, k)) << k;
  EXPECT_DOUBLE_EQ(faded_compensation_mm(p, 100, 1), 8 * kFoot / 9);
  EXPECT_EQ(faded_compensation_mm(p, 100, 9), 0);
  // An object of 5 layers fades over them: F = 5, E = 4.
  for (size_t k = 0; k < 6; ++k) EXPECT_DOUBLE_EQ(faded_compensation_mm(p, 5, k), expected_mm(4, k)) << k;
  // One or two layers: layer 0 full (E = 1).
  EXPECT_EQ(faded_compensation_mm(p, 1, 0), kFoot);
  EXPECT_EQ(faded_compensation_mm(p, 2, 0), kFoot);
  EXPECT_EQ(faded_compensation_mm(p, 2, 1), 0);
  // faded_layers 0, 1 and 2: layer 0 alone; 3: a half on layer 1.
  for (int f : {0, 1, 2}) {
    EXPECT_EQ(faded_compensation_mm(profile_fading(f), 100, 0), kFoot) << f;
    EXPECT_EQ(faded_compensation_mm(profile_fading(f), 100, 1), 0) << f;
  }
  EXPECT_DOUBLE_EQ(faded_compensation_mm(profile_fading(3), 100, 1), kFoot / 2);
  EXPECT_EQ(faded_compensation_mm(profile_fading(3), 100, 2), 0);
}

TEST(FadedLayers, ABoxShrinksLessOnEveryFadedLayerAndNotAboveThem) {
  const SlicePart whole = box_part(-5, -5, 5, 5, 0, 20, 0);
  std::vector<SlicePart> parts;
  parts.push_back(box_part(-5, -5, 5, 5, 0, 20, 0));
  compensate_faded_layers(parts, 0, {}, {20}, profile_fading(10), true);
  double below = 0;
  for (size_t k = 0; k < 20; ++k) {
    const double area = area_at(parts, k);
    EXPECT_NEAR(area, square(10, in_units(expected_mm(9, k))), 1e-9) << "layer " << k;
    if (k > 0 && k <= 9) EXPECT_GT(area, below + 0.8) << "layer " << k;  // 4 sides of 10 mm by 0.022 mm
    below = area;
  }
  // From layer 9 the layers are the slicing's own, points and all.
  std::vector<const SlicePart*> above;
  for (const SlicePart& p : parts)
    if (p.first + p.slices.layers() > 9) above.push_back(&p);
  ASSERT_EQ(above.size(), 1u);
  EXPECT_EQ(above[0]->first, 9u);
  Slices own;
  layers_into(whole.slices, 9, 20, own, true);
  EXPECT_EQ(above[0]->slices.layer_z, own.layer_z);
  EXPECT_EQ(above[0]->slices.contour_begin, own.contour_begin);
  EXPECT_TRUE(std::equal(own.xyz.begin(), own.xyz.end(), above[0]->slices.xyz.begin()));
  // Each faded layer is a part of one layer at the slicing's plane.
  for (const SlicePart& p : parts)
    if (p.first < 9) {
      EXPECT_EQ(p.slices.layers(), 1u);
      EXPECT_EQ(p.slices.layer_z[0], whole.slices.layer_z[p.first]);
    }
}

TEST(FadedLayers, InRangesTheLayersAreThoseOfTheWholeStack) {
  std::vector<SlicePart> whole;
  whole.push_back(box_part(-5, -5, 5, 5, 0, 20, 0));
  const std::vector<SlicePart> uncompensated = whole;
  compensate_faded_layers(whole, 0, {}, {20}, profile_fading(10), true);
  const size_t starts[] = {0, 1, 4, 8, 9, 13, 20};
  for (size_t i = 0; i + 1 < std::size(starts); ++i) {
    const size_t a = starts[i], b = starts[i + 1];
    std::vector<size_t> owners;
    std::vector<SlicePart> range = range_of(uncompensated, {0}, a, b, owners);
    compensate_faded_layers(range, a, owners, {20}, profile_fading(10), i % 2 == 0);
    for (size_t r = 0; r < b - a; ++r) EXPECT_EQ(region_at(range, r), region_at(whole, a + r)) << "layer " << a + r;
  }
}

TEST(FadedLayers, AMemberOnItsSupportsFadesFromThePadsBottomApartFromOtherObjects) {
  // Object 0: a pad (layers 0-2), a column (0-6) and the member standing on it (5-19), all in
  // one range; object 1: a short box of 3 layers far away, faded over its own: F = 3, E = 2.
  std::vector<SlicePart> parts;
  parts.push_back(box_part(30, 0, 34, 4, 0, 3, 0));
  parts.push_back(box_part(-5, -5, 5, 5, 5, 20, 5));
  parts.push_back(box_part(-10, -10, 10, 10, 0, 3, 0));
  parts.push_back(box_part(-1, -1, 1, 1, 0, 7, 0));
  const std::vector<size_t> owners = {1, 0, 0, 0};
  // The same in two ranges, the second starting among the member's faded layers.
  std::vector<size_t> low_owners, high_owners;
  std::vector<SlicePart> low = range_of(parts, owners, 0, 6, low_owners);
  std::vector<SlicePart> high = range_of(parts, owners, 6, 20, high_owners);
  EXPECT_EQ(high_owners, (std::vector<size_t>{0, 0}));
  compensate_faded_layers(parts, 0, owners, {20, 3}, profile_fading(10), true);
  compensate_faded_layers(low, 0, low_owners, {20, 3}, profile_fading(10), false);
  compensate_faded_layers(high, 6, high_owners, {20, 3}, profile_fading(10), true);
  for (size_t k = 0; k < 20; ++k) {
    const double c = in_units(expected_mm(9, k));
    const double object0 = k < 3 ? square(20, c) : k < 5 ? square(2, c) : square(10, c);
    const double object1 = k < 3 ? square(4, expected_mm(2, k)) : 0;
    EXPECT_NEAR(area_at(parts, k), object0 + object1, 1e-9) << "layer " << k;
    EXPECT_EQ(region_at(k < 6 ? low : high, k < 6 ? k : k - 6), region_at(parts, k)) << "layer " << k;
  }
  EXPECT_NEAR(area_at(parts, 2), square(20, in_units(7 * kFoot / 9)) + 16, 1e-9);
}

TEST(FadedLayers, NarrowFeaturesKeepTheirWidthOnEveryFadedLayer) {
  // A 0.15 mm fin on a 10 mm square (two parts of one object): the square shrinks by the faded
  // compensation c, the fin keeps its width and a collar c wide (elephant_foot.h).
  std::vector<SlicePart> parts;
  parts.push_back(box_part(0, 0, 10, 10, 0, 20, 0));
  parts.push_back(box_part(9.9, 4.925, 13, 5.075, 0, 20, 0));
  compensate_faded_layers(parts, 0, {0, 0}, {20}, profile_fading(10), true);
  for (size_t k = 0; k < 20; ++k) {
    const double c = in_units(expected_mm(9, k));
    const double expected = c > 0 ? square(10, c) + 3 * 0.15 + c * (0.15 + 2 * c) : 100 + 3 * 0.15;
    EXPECT_NEAR(area_at(parts, k), expected, 1e-9) << "layer " << k;
  }
}

TEST(FadedLayers, FadedLayersZeroToTwoCompensateLayerZeroOnly) {
  for (int f : {0, 1, 2}) {
    std::vector<SlicePart> parts;
    parts.push_back(box_part(-5, -5, 5, 5, 0, 20, 0));
    compensate_faded_layers(parts, 0, {}, {20}, profile_fading(f), true);
    ASSERT_EQ(parts.size(), 2u) << f;
    EXPECT_EQ(parts[1].first, 1u);
    EXPECT_NEAR(area_at(parts, 0), square(10, kFoot), 1e-9) << f;
    for (size_t k = 1; k < 20; ++k) EXPECT_NEAR(area_at(parts, k), 100, 1e-9) << f << " layer " << k;
  }
}

TEST(FadedLayers, NoCompensationLeavesThePartsAsTheyAre) {
  std::vector<SlicePart> parts;
  parts.push_back(box_part(-5, -5, 5, 5, 0, 20, 0));
  PrinterProfile p = profile_fading(10);
  p.elephant_foot_mm = 0;
  compensate_faded_layers(parts, 0, {}, {20}, p, true);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0].slices.layers(), 20u);
}

TEST(FadedLayers, OwnersNotOnePerPartAreRefused) {
  std::vector<SlicePart> parts;
  parts.push_back(box_part(-5, -5, 5, 5, 0, 20, 0));
  EXPECT_ERROR(compensate_faded_layers(parts, 0, {0, 0}, {20}, profile_fading(10), true),
               "internal error: 2 owners for 1 parts of the faded layers");
  EXPECT_ERROR(compensate_faded_layers(parts, 0, {3}, {20}, profile_fading(10), true),
               "internal error: part 0's owner 3 has no layer count (1 given)");
}
