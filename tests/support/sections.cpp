#include "sections.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

namespace slicereuse::test {
namespace {

// A contour as its points in canonical order: a loop rotated to start at its smallest point.
using Point = std::array<double, 3>;
std::vector<std::vector<Point>> canonical_layer(const Slices& s, size_t k) {
  std::vector<std::vector<Point>> loops;
  for (size_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c) {
    std::vector<Point> loop;
    for (size_t p = s.contour_begin[c]; p < s.contour_begin[c + 1]; ++p)
      loop.push_back({s.xyz[3 * p], s.xyz[3 * p + 1], s.xyz[3 * p + 2]});
    if (!s.contour_open[c]) std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
    loops.push_back(std::move(loop));
  }
  std::sort(loops.begin(), loops.end());
  return loops;
}

}  // namespace

void expect_same_sections(const Slices& a, const Slices& b) {
  ASSERT_EQ(a.layers(), b.layers());
  for (size_t k = 0; k < a.layers(); ++k) {
    ASSERT_EQ(a.layer_z[k], b.layer_z[k]);
    ASSERT_EQ(canonical_layer(a, k), canonical_layer(b, k)) << "layer " << k;
  }
}

}  // namespace slicereuse::test
