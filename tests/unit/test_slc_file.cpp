// SLC export: the layout checked by an independent reader written from the 3D Systems
// specification (tests/support/spec_readers.cpp), boundary orientation on a sliced torus,
// open contours left out and counted, refusal of what SLC cannot hold.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include "shapes.h"
#include "slicereuse/formats/slc_file.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/util/error.h"
#include "spec_readers.h"
#include "test_files.h"

using namespace slicereuse;
using namespace slicereuse::test;

namespace {

class SlcFiles : public FileTest {};

double area(const std::vector<std::array<float, 2>>& b) {
  double a = 0;
  for (size_t i = 0; i + 1 < b.size(); ++i) a += 0.5 * (double(b[i][0]) * b[i + 1][1] - double(b[i + 1][0]) * b[i][1]);
  return a;
}

}  // namespace

TEST_F(SlcFiles, LayoutMatchesTheSpecification) {
  Slices s = make_slices({5, 3, 4, -1, -1, 7, 2, 1, -1, 30, 3, 3, 9}, 42);
  for (double& v : s.xyz) v = std::fmod(v, 1000.0);  // within float32
  const SlcExportStats stats = write_slc_file(path("s.slc"), s);
  EXPECT_EQ(stats.skipped_open_contours, s.open_contours());
  EXPECT_EQ(stats.boundaries, s.contours() - s.open_contours());

  const SpecSlc f = read_slc_per_spec(slurp(path("s.slc")));
  EXPECT_EQ(f.header.rfind("-SLCVER 2.0 -UNIT MM -TYPE PART ", 0), 0u) << f.header;
  // -EXTENTS minx,maxx miny,maxy minz,maxz over what is written.
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (size_t c = 0; c < s.contours(); ++c)
    if (!s.contour_open[c])
      for (uint64_t p = s.contour_begin[c]; p < s.contour_begin[c + 1]; ++p)
        for (int a = 0; a < 2; ++a) {
          lo[a] = std::min(lo[a], s.xyz[3 * p + a]);
          hi[a] = std::max(hi[a], s.xyz[3 * p + a]);
        }
  const size_t at = f.header.find("-EXTENTS ");
  ASSERT_NE(at, std::string::npos);
  double e[6];
  ASSERT_EQ(std::sscanf(f.header.c_str() + at, "-EXTENTS %lf,%lf %lf,%lf %lf,%lf", &e[0], &e[1], &e[2], &e[3], &e[4], &e[5]), 6);
  EXPECT_EQ(e[0], lo[0]);
  EXPECT_EQ(e[1], hi[0]);
  EXPECT_EQ(e[2], lo[1]);
  EXPECT_EQ(e[3], hi[1]);
  EXPECT_DOUBLE_EQ(e[4], s.layer_z.front() - s.thickness / 2);
  EXPECT_DOUBLE_EQ(e[5], s.layer_z.back() + s.thickness / 2);

  ASSERT_EQ(f.samples.size(), 1u);
  EXPECT_EQ(f.samples[0][0], float(s.layer_z.front() - s.thickness / 2));
  EXPECT_EQ(f.samples[0][1], float(s.thickness));
  EXPECT_EQ(f.samples[0][2], 0.0f);
  ASSERT_EQ(f.layers.size(), s.layers());
  for (size_t k = 0; k < s.layers(); ++k) {
    EXPECT_EQ(f.layers[k].z, float(s.layer_z[k] - s.thickness / 2));
    size_t i = 0;
    for (uint64_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c) {
      if (s.contour_open[c]) continue;
      ASSERT_LT(i, f.layers[k].boundaries.size());
      const auto& b = f.layers[k].boundaries[i];
      EXPECT_EQ(f.layers[k].gaps[i], 0u);
      const uint64_t p0 = s.contour_begin[c], n = s.contour_begin[c + 1] - p0;
      ASSERT_EQ(b.size(), n + 1);
      for (uint64_t j = 0; j <= n; ++j) {
        EXPECT_EQ(b[j][0], float(s.xyz[3 * (p0 + j % n)]));
        EXPECT_EQ(b[j][1], float(s.xyz[3 * (p0 + j % n) + 1]));
      }
      ++i;
    }
    EXPECT_EQ(i, f.layers[k].boundaries.size());
  }
  EXPECT_EQ(f.end_z, float(s.layer_z.back() + s.thickness / 2));
}

TEST_F(SlcFiles, TorusBoundariesRunOuterCounterClockwiseInnerClockwise) {
  SliceOptions o;
  o.thickness = 0.05;
  const Slices s = slice_layers(make_torus(3, 1, 48, 24), o);
  write_slc_file(path("t.slc"), s);
  const SpecSlc f = read_slc_per_spec(slurp(path("t.slc")));
  ASSERT_EQ(f.layers.size(), s.layers());
  size_t outer = 0, inner = 0;
  for (const auto& l : f.layers) {
    // A torus layer through the hole: two nested loops, the larger one outside.
    if (l.boundaries.size() != 2) continue;
    const double a0 = area(l.boundaries[0]), a1 = area(l.boundaries[1]);
    const double big = std::abs(a0) > std::abs(a1) ? a0 : a1, small = std::abs(a0) > std::abs(a1) ? a1 : a0;
    EXPECT_GT(big, 0);
    EXPECT_LT(small, 0);
    ++outer, ++inner;
    for (const auto& b : l.boundaries) EXPECT_EQ(b.front(), b.back());
  }
  EXPECT_GT(outer, s.layers() / 2);
}

TEST_F(SlcFiles, EmptySlicesGiveAValidFile) {
  Slices s;
  s.thickness = 0.1;
  s.z_start = 2;
  s.layer_begin = {0};
  s.contour_begin = {0};
  write_slc_file(path("e.slc"), s);
  const SpecSlc f = read_slc_per_spec(slurp(path("e.slc")));
  EXPECT_TRUE(f.layers.empty());
  EXPECT_EQ(f.end_z, 2.0f);
}

TEST_F(SlcFiles, WhatSlcCannotHoldIsRefused) {
  Slices s = make_slices({5, 3}, 1);
  for (double& v : s.xyz) v = 1;
  s.xyz[0] = 1e300;
  EXPECT_ERROR(write_slc_file(path("w.slc"), s), "does not fit in a float32");
  EXPECT_TRUE(leftovers().empty());
  EXPECT_FALSE(std::filesystem::exists(path("w.slc")));
  s.xyz.clear();
  EXPECT_ERROR(write_slc_file(path("w.slc"), s), "no contour points");
}
