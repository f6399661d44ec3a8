// simplify_paths (regions/simplify_paths.h): Douglas-Peucker on each loop, and the deviation it
// reports: how far the farthest dropped vertex lay from its chord.
#include <gtest/gtest.h>

#include "slicereuse/regions/simplify_paths.h"

namespace slicereuse {
namespace {

// A 100 x 100 square with a vertex halfway along each edge, the bottom one raised by bump.
ClipperLib::Paths square_with_midpoints(ClipperLib::cInt bump) {
  return {{{0, 0}, {50, bump}, {100, 0}, {100, 50}, {100, 100}, {50, 100}, {0, 100}, {0, 50}}};
}

TEST(SimplifyPaths, DropsCollinearVerticesWithNoDeviation) {
  double deviation = -1;
  const ClipperLib::Paths out = simplify_paths(square_with_midpoints(0), 5, &deviation);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0], (ClipperLib::Path{{0, 0}, {100, 0}, {100, 100}, {0, 100}}));
  EXPECT_EQ(deviation, 0);
}

TEST(SimplifyPaths, ReportsTheFarthestDroppedVertex) {
  double deviation = -1;
  EXPECT_EQ(simplify_paths(square_with_midpoints(3), 5, &deviation)[0].size(), 4u);
  EXPECT_DOUBLE_EQ(deviation, 3);
  // Beyond the tolerance the vertex stays, and what went lay exactly on its chords.
  EXPECT_EQ(simplify_paths(square_with_midpoints(7), 5, &deviation)[0].size(), 5u);
  EXPECT_EQ(deviation, 0);
}

}  // namespace
}  // namespace slicereuse
