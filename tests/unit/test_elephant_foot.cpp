// Elephant-foot compensation: exact shrinking of straight contours, narrow features kept and
// joined to the rest, compensation 0 as the identity, errors in words; faded over the first
// layers of a stack as PrusaSlicer fades it.
#include <gtest/gtest.h>

#include "error_of.h"
#include "mask_layers.h"
#include "slicereuse/plates/faded_elephant_foot.h"
#include "slicereuse/regions/elephant_foot.h"
#include "slicereuse/regions/layer_region.h"

using namespace slicereuse;
using ClipperLib::Path;
using ClipperLib::Paths;

namespace {

Path rect(double x0, double y0, double x1, double y1) {
  return {{region_units(x0), region_units(y0)},
          {region_units(x1), region_units(y0)},
          {region_units(x1), region_units(y1)},
          {region_units(x0), region_units(y1)}};
}

// The region of the layer compensate_elephant_foot makes from a layer of the given polygons.
Paths compensated(const Paths& polygons, double compensation, double min_width = 0.2) {
  Slices in, out;
  region_into_layer(polygons, 0.025, in);
  compensate_elephant_foot(LayerView(in, 0), 0.025, compensation, min_width, out);
  EXPECT_EQ(out.layer_z, std::vector<double>{0.025});
  return layer_region(LayerView(out, 0));
}

}  // namespace

TEST(ElephantFoot, SquareShrinksByTheCompensationOnEverySide) {
  const Paths r = compensated({rect(0, 0, 10, 10)}, 0.2);
  // Miter joins: the shrunk square is exactly 9.6 mm wide.
  EXPECT_NEAR(region_area_mm2(r), 9.6 * 9.6, 9.6 * 9.6 * 1e-12);
  ASSERT_EQ(r.size(), 1u);
  ClipperLib::cInt x0 = r[0][0].X, x1 = x0;
  for (const auto& p : r[0]) x0 = std::min(x0, p.X), x1 = std::max(x1, p.X);
  EXPECT_EQ(x0, region_units(0.2));
  EXPECT_EQ(x1, region_units(9.8));
}

TEST(ElephantFoot, NarrowFeaturesKeepTheirWidth) {
  // Narrower than the minimal width, and narrower than it once shrunk: both kept as they are.
  EXPECT_NEAR(region_area_mm2(compensated({rect(0, 0, 0.15, 5)}, 0.2)), 0.75, 1e-12);
  EXPECT_NEAR(region_area_mm2(compensated({rect(0, 0, 0.3, 5)}, 0.2)), 1.5, 1e-12);
  // Wider than the minimal width once shrunk.
  EXPECT_NEAR(region_area_mm2(compensated({rect(0, 0, 0.7, 5)}, 0.2)), 0.3 * 4.6, 1e-12);
  EXPECT_NEAR(region_area_mm2(compensated({rect(0, 0, 1, 5)}, 0.2)), 0.6 * 4.6, 1e-12);
}

TEST(ElephantFoot, ANarrowFinStaysJoinedToTheShrunkBody) {
  // A 0.15 mm fin on a square: the square shrinks, the fin keeps its width and a collar of
  // 0.2 mm into the square (as wide as the fin plus 0.2 mm each side) joins them.
  Paths r;
  ClipperLib::Clipper c;
  c.AddPaths({rect(0, 0, 10, 10), rect(10, 4.925, 13, 5.075)}, ClipperLib::ptSubject, true);
  c.Execute(ClipperLib::ctUnion, r, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  const Paths out = compensated(r, 0.2);
  EXPECT_EQ(out.size(), 1u);
  EXPECT_NEAR(region_area_mm2(out), 9.6 * 9.6 + 3 * 0.15 + 0.2 * 0.55, 1e-9);
}

TEST(ElephantFoot, ZeroCompensationKeepsTheRegion) {
  const Paths in = {rect(0, 0, 10, 10), rect(12, 0, 12.15, 3)};
  const Paths out = compensated(in, 0);
  EXPECT_NEAR(region_area_mm2(out), 100 + 0.45, 1e-12);
  EXPECT_EQ(out.size(), 2u);
}

TEST(ElephantFoot, BadInputInWords) {
  EXPECT_ERROR(compensated({rect(0, 0, 1, 1)}, -0.1), "the elephant-foot compensation is -0.1 mm");
  EXPECT_ERROR(compensated({rect(0, 0, 1, 1)}, 0.2, NAN), "the elephant-foot minimal width is nan mm");
}

// PrusaSlicer's fade: the full compensation on layer 0, linearly less to none on layer F - 1.
TEST(FadedElephantFoot, FadesLinearlyOverTheFadedLayers) {
  PrinterProfile p;
  p.elephant_foot_mm = 0.2;
  p.faded_layers = 10;
  EXPECT_EQ(faded_elephant_foot_mm(p, 0, 100), 0.2);
  EXPECT_DOUBLE_EQ(faded_elephant_foot_mm(p, 1, 100), 0.2 * 8 / 9);
  EXPECT_DOUBLE_EQ(faded_elephant_foot_mm(p, 8, 100), 0.2 / 9);
  EXPECT_EQ(faded_elephant_foot_mm(p, 9, 100), 0);
  EXPECT_EQ(faded_elephant_foot_mm(p, 50, 100), 0);
  // A stack shorter than the faded layers fades over its own layers.
  EXPECT_DOUBLE_EQ(faded_elephant_foot_mm(p, 1, 4), 0.2 * 2 / 3);
  EXPECT_EQ(faded_elephant_foot_mm(p, 3, 4), 0);
  // No faded layers: layer 0 alone, fully; no compensation: none.
  p.faded_layers = 0;
  EXPECT_EQ(faded_elephant_foot_mm(p, 0, 100), 0.2);
  EXPECT_EQ(faded_elephant_foot_mm(p, 1, 100), 0);
  p.elephant_foot_mm = 0;
  EXPECT_EQ(faded_elephant_foot_mm(p, 0, 100), 0);
}

// A range of a stack's layers, compensated where the fade reaches into it: each such layer one
// part of its compensated region, the rest of the parts' layers as they were.
TEST(FadedElephantFoot, ARangeIsCompensatedWhereTheFadeReachesIntoIt) {
  PrinterProfile p;
  p.elephant_foot_mm = 0.2;
  p.faded_layers = 5;  // layers 0..3 shrink: 0.2, 0.15, 0.1, 0.05
  // Two parts of a range that starts at stack layer 2: 4 layers of a 10 mm square from the
  // range's layer 0, 2 layers of another square from its layer 1.
  std::vector<SlicePart> parts(2);
  parts[0].slices = test::make_slices({{test::rect(0, 0, 10, 10)}, {test::rect(0, 0, 10, 10)},
                                       {test::rect(0, 0, 10, 10)}, {test::rect(0, 0, 10, 10)}});
  parts[1].slices = test::make_slices({{test::rect(20, 0, 30, 10)}, {test::rect(20, 0, 30, 10)}});
  parts[1].first = 1;
  compensate_faded_layers(parts, p, {0.2, 0.1, 20, 2, 4});
  // Range layers 0 and 1 (stack layers 2, 3) compensated; the rest copied out from layer 2.
  ASSERT_GE(parts.size(), 3u);
  EXPECT_EQ(parts[0].first, 0u);
  EXPECT_EQ(parts[1].first, 1u);
  EXPECT_NEAR(region_area_mm2(layer_region(LayerView(parts[0].slices, 0))), 9.8 * 9.8, 1e-9);
  EXPECT_NEAR(region_area_mm2(layer_region(LayerView(parts[1].slices, 0))), 2 * 9.9 * 9.9, 1e-9);
  double rest = 0;
  for (size_t i = 2; i < parts.size(); ++i) {
    EXPECT_EQ(parts[i].first, 2u);
    rest += region_area_mm2(layer_region(LayerView(parts[i].slices, 0)));
  }
  EXPECT_NEAR(rest, 2 * 100, 1e-9);  // range layer 2: both squares, unshrunk
  EXPECT_EQ(parts.size(), 4u);
}
