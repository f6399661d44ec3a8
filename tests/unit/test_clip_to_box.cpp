// clip_to_box (regions/clip_to_box.h): the same region as Clipper's intersection with the box,
// up to its rounding of crossings, on random loops (crossing each other, holes, loops beyond the
// box).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <utility>

#include "region_perimeter.h"
#include "slicereuse/regions/clip_regions.h"
#include "slicereuse/regions/clip_to_box.h"

namespace slicereuse {
namespace {

using ClipperLib::Paths;

double area(const Paths& region) {
  double a = 0;
  for (const ClipperLib::Path& loop : region) a += ClipperLib::Area(loop);
  return a;
}

TEST(ClipToBox, IsClippersIntersectionWithTheBox) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> loops(1, 4), points(3, 200), coordinate(-1000, 1000);
  std::uniform_real_distribution<double> wobble(0.3, 1.7);
  size_t cut = 0, empty = 0;
  for (int trial = 0; trial < 300; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    Paths region;
    for (int l = loops(rng); l > 0; --l) {
      // A wobbly circle, either way round (a hole where it lies in another), often self-crossing.
      const double cx = coordinate(rng), cy = coordinate(rng), r = 100 + std::abs(coordinate(rng)) / 2.0;
      const int n = points(rng);
      const bool clockwise = rng() % 3 == 0;
      ClipperLib::Path loop;
      for (int i = 0; i < n; ++i) {
        const double t = 2 * M_PI * i / n * (clockwise ? -1 : 1), w = r * wobble(rng);
        loop.push_back({ClipperLib::cInt(std::llround(cx + w * std::cos(t))), ClipperLib::cInt(std::llround(cy + w * std::sin(t)))});
      }
      region.push_back(loop);
    }
    ClipperLib::cInt x0 = coordinate(rng), x1 = coordinate(rng), y0 = coordinate(rng), y1 = coordinate(rng);
    if (x0 > x1) std::swap(x0, x1);
    if (y0 > y1) std::swap(y0, y1);
    const ClipperLib::IntRect box{x0, y0, x1 + 1, y1 + 1};
    const Paths expected = clip_regions(
        region, {{{box.left, box.top}, {box.right, box.top}, {box.right, box.bottom}, {box.left, box.bottom}}},
        ClipperLib::ctIntersection);
    const Paths got = clip_to_box(region, box);
    // The same region but for Clipper's rounding of crossings to its grid (its scanbeams, which
    // clamp them, lie at the vertices' heights): a sliver two units wide at most along the edges.
    EXPECT_LE(std::abs(area(clip_regions(got, expected, ClipperLib::ctXor))), 2 * test::region_perimeter(expected));
    EXPECT_NEAR(area(got), area(expected), 2 * test::region_perimeter(expected));
    (expected.empty() ? empty : cut) += 1;
  }
  EXPECT_GT(cut, 100u);
  EXPECT_GT(empty, 10u);
}

}  // namespace
}  // namespace slicereuse
