// squared_distances (util/squared_distances.h): the exact Euclidean distance transform, against
// the brute-force nearest set cell of every cell.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "slicereuse/util/squared_distances.h"

namespace slicereuse {
namespace {

TEST(SquaredDistances, EqualTheNearestSetCellsByBruteForce) {
  std::mt19937 random(7);
  for (const double share : {0.002, 0.05, 0.5}) {
    const int w = 37, h = 23;
    std::vector<uint8_t> set(size_t(w) * h);
    for (uint8_t& c : set) c = std::uniform_real_distribution<double>(0, 1)(random) < share;
    set[5] = 1;  // at least one
    const std::vector<double> d = squared_distances(set, w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        double best = kNoCellSet;
        for (int v = 0; v < h; ++v)
          for (int u = 0; u < w; ++u)
            if (set[size_t(v) * w + u]) best = std::min(best, double((u - x) * (u - x) + (v - y) * (v - y)));
        ASSERT_EQ(d[size_t(y) * w + x], best) << "cell " << x << ", " << y << ", share " << share;
      }
  }
  EXPECT_EQ(squared_distances(std::vector<uint8_t>(12, 0), 4, 3), std::vector<double>(12, kNoCellSet));
}

}  // namespace
}  // namespace slicereuse
