// Elephant-foot compensation: exact shrinking of straight contours, narrow features kept and
// joined to the rest, compensation 0 as the identity, errors in words.
#include <gtest/gtest.h>

#include <cmath>

#include "error_of.h"
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

// A sliced curved part: a disc of radius r as a dense polygon with bumps of a few nanometres at
// its vertices, as a mesh's slice gives (1000 points 0.03 mm apart), centred at (cx, cy).
Path dense_disc(double cx, double cy, double r) {
  Path p;
  for (int i = 0; i < 1000; ++i) {
    const double a = 2 * M_PI * i / 1000, rr = r + (i % 3 == 0 ? 4e-6 : 0);
    p.emplace_back(region_units(cx + rr * std::cos(a)), region_units(cy + rr * std::sin(a)));
  }
  return p;
}

TEST(ElephantFoot, ADenseCurvedContourShrinksAllAlong) {
  // The opening leaves micrometre slivers all along such a boundary; they are no narrow
  // features, so the disc shrinks by the compensation all round (before, nearly all its boundary
  // stayed unshrunk: 78.5 mm^2 of its 78.5).
  const double shrunk = region_area_mm2(compensated({dense_disc(0, 0, 5)}, 0.2));
  EXPECT_NEAR(shrunk, M_PI * 4.8 * 4.8, 0.01 * M_PI * 4.8 * 4.8) << "uncompensated " << M_PI * 25;
}

TEST(ElephantFoot, FarPartsShrinkTogetherAsEachAlone) {
  // Two curved parts 3 mm apart and a small one, together or each alone: the same region.
  const Paths parts = {dense_disc(0, 0, 5), dense_disc(13, 0, 5), rect(20, -0.05, 20.1, 0.05)};
  Paths alone;
  for (const Path& p : parts) {
    const Paths one = compensated({p}, 0.2);
    alone.insert(alone.end(), one.begin(), one.end());
  }
  ClipperLib::Clipper c;
  c.AddPaths(compensated(parts, 0.2), ClipperLib::ptSubject, true);
  c.AddPaths(alone, ClipperLib::ptClip, true);
  Paths differ;
  c.Execute(ClipperLib::ctXor, differ, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  EXPECT_LT(std::abs(region_area_mm2(differ)), 1e-9);
  EXPECT_NEAR(region_area_mm2(alone), 2 * M_PI * 4.8 * 4.8 + 0.01, 0.02 * M_PI * 4.8 * 4.8);
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
