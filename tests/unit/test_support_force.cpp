// The support force's model (support_force.h), on layers given by their parts' areas and
// links: what a part inherits from the parts below, shared by overlap and cut where it grows
// more than 20 times; and how many points its slopes ask for.
#include <gtest/gtest.h>

#include "support_force.h"

using namespace slicereuse;

namespace {

// A layer of parts of these areas (mm2) and links to the layer below.
LayerAreas layer(const std::vector<double>& part_mm2, const std::vector<PartLink>& links) {
  LayerAreas a;
  a.parts.resize(part_mm2.size());
  a.part_mm2 = part_mm2;
  a.links = links;
  return a;
}

}  // namespace

TEST(SupportForce, APartInheritsWhatThePartsBelowItHoldShared) {
  // Part 0 rests on parts 0 and 1 below (forces 30 and 12); part 1 on part 1 too, with twice the
  // overlap: part 1's 12 splits 4 / 8. Part 2 rests on nothing.
  const LayerAreas a = layer({20, 20, 5}, {{0, 0, 15, 18}, {0, 1, 2, 16}, {1, 1, 4, 16}});
  const std::vector<double> f = inherited_force(a, {30, 12});
  ASSERT_EQ(f.size(), 3u);
  EXPECT_DOUBLE_EQ(f[0], 30 + 4);
  EXPECT_DOUBLE_EQ(f[1], 8);
  EXPECT_DOUBLE_EQ(f[2], 0);
}

TEST(SupportForce, GrowingPastTwentyTimesCutsIt) {
  // A part of 100 mm2 on one of 2 mm2: 20 x 2 / 100 of its force passes; on one of 5, all of it.
  EXPECT_DOUBLE_EQ(inherited_force(layer({100}, {{0, 0, 2, 2}}), {50})[0], 50 * 0.4);
  EXPECT_DOUBLE_EQ(inherited_force(layer({100}, {{0, 0, 5, 5}}), {50})[0], 50);
}

TEST(SupportForce, SlopesGetPointsWhileThePartIsShortOfItsArea) {
  // ceil(slope x (1 - force / area) / point force).
  EXPECT_EQ(slope_points_needed(30, 100, 0, 10), 3u);
  EXPECT_EQ(slope_points_needed(30, 100, 50, 10), 2u);   // 1.5
  EXPECT_EQ(slope_points_needed(0.2, 100, 99, 10), 1u);  // any shortfall asks for one
  EXPECT_EQ(slope_points_needed(30, 100, 100, 10), 0u);
  EXPECT_EQ(slope_points_needed(30, 100, 250, 10), 0u);
  EXPECT_EQ(slope_points_needed(0, 100, 0, 10), 0u);
}
