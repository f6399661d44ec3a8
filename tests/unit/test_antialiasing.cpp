// Anti-aliased masks against an independent computation of each pixel's covered area (every
// loop clipped to the pixel's square by Sutherland-Hodgman, signed areas summed), on holes,
// walls thinner than a pixel, edges on pixel borders, fine contours, long edges and parts that
// leave the display; gamma 0 against the binary mask; invariance to contour order, loop start
// and reversed duplicates; mirrors; portrait orientation; runs; gamma validation and the .sl1
// gamma_correction key.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "mask_layers.h"
#include "mask_stack.h"
#include "slicereuse/png/mask_png.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/printfiles/export_masks.h"
#include "slicereuse/raster/rasterize_layer.h"
#include "slicereuse/util/error.h"
#include "temp_folder.h"
#include "test_files.h"

using namespace slicereuse;
using test::Layer;
using test::Loop;
using test::raster;
using test::rect;
using test::small_display;
using test::star;

namespace {

using Pt = std::array<double, 2>;

// A circle of n points, counter-clockwise (clockwise for a hole).
Loop circle(double cx, double cy, double r, int n, bool clockwise = false) {
  Loop l;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * 3.141592653589793 * i / n + 0.0173;
    l.pts.push_back({cx + r * std::cos(a), cy + (clockwise ? -r : r) * std::sin(a)});
  }
  return l;
}

Loop reversed(Loop l) {
  std::reverse(l.pts.begin(), l.pts.end());
  return l;
}

// The layers every test here draws.
std::vector<Layer> shapes() {
  const Loop wall_hole = rect(-4.967, -4.967, 4.967, 4.967, true);             // walls of 0.33 px
  const Loop sliver{{{-6, -9}, {6, -7}, {6, -6.98}, {-6, -8.98}}};             // 0.2 px high, slanted
  const Loop diamond{{{0, 4}, {4, 0}, {0, -4}, {-4, 0}}};                      // through pixel corners
  const Loop triangle{{{-9.3, -8.1}, {8.7, -6.2}, {-2.1, 9.4}}};               // long edges
  const Loop needle{{{9.31, -9.5}, {9.35, -9.5}, {9.5, 9.5}, {9.46, 9.5}}};     // long, nearly vertical
  return {
      {rect(-5, -5, 5, 5), rect(-2, -2, 2, 2, true)},                          // edges on pixel borders
      {star(0.3, -0.2, 3, 7.5, 9), reversed(star(0.1, 0.2, 1, 2, 5))},         // a star with a star hole
      {rect(-5, -5, 5, 5), wall_hole, sliver},                                  // thinner than a pixel
      {diamond, rect(-4.95, 5.05, 5.05, 5.55), rect(2.5, -9.5, 3, -6)},        // centres, corners, borders
      {circle(0.37, -0.21, 6.3, 3000), circle(0.5, 0.1, 2.2, 1000, true)},     // 7.6 points per pixel
      {circle(-3.3, 2.2, 4.1, 250), circle(4.4, -3.9, 3.3, 90)},               // edges of 1 and 2.3 px
      {star(0.2, -0.3, 9, 16, 7), rect(-30, -0.73, 30, 0.71)},                 // beyond every side
      {triangle, needle},
      {rect(-5, -5, 5, 5), rect(0.034, 0.072, 9.034, 9.072)},                  // overlapping loops
  };
}

// The profiles they are drawn on: the small display, one where nothing lines up, and one more
// than 4096 pixels wide with narrow pixels (rows of 66 words of touched bits, so the words'
// summary bits of one row start and end inside a summary word, as on 8K to 16K displays).
std::vector<PrinterProfile> profiles() {
  PrinterProfile odd = small_display();
  odd.pixel_size_x_um = 73.1;
  odd.pixel_size_y_um = 81.7;
  odd.offset_x_mm = 0.0123;
  odd.offset_y_mm = -0.0456;
  PrinterProfile wide = small_display();
  wide.width_px = 4200;
  wide.height_px = 44;
  wide.pixel_size_x_um = 10.3;
  wide.pixel_size_y_um = 497;
  return {small_display(), odd, wide};
}

PrinterProfile antialiased(PrinterProfile p, double gamma) {
  p.antialiasing = true;
  p.gamma = gamma;
  return p;
}

// The part of polygon `in` where coordinate `axis` is >= bound (keep_above) or <= bound.
std::vector<Pt> clip(const std::vector<Pt>& in, int axis, double bound, bool keep_above) {
  std::vector<Pt> out;
  auto inside = [&](const Pt& p) { return keep_above ? p[axis] >= bound : p[axis] <= bound; };
  for (size_t i = 0; i < in.size(); ++i) {
    const Pt& prev = in[(i + in.size() - 1) % in.size()];
    const Pt& cur = in[i];
    if (inside(cur) != inside(prev)) {
      const double t = (bound - prev[axis]) / (cur[axis] - prev[axis]);
      Pt x{prev[0] + t * (cur[0] - prev[0]), prev[1] + t * (cur[1] - prev[1])};
      x[axis] = bound;
      out.push_back(x);
    }
    if (inside(cur)) out.push_back(cur);
  }
  return out;
}

double signed_area(const std::vector<Pt>& poly) {
  double twice = 0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Pt &p = poly[i], &q = poly[(i + 1) % poly.size()];
    twice += p[0] * q[1] - q[0] * p[1];
  }
  return twice / 2;
}

// Each pixel's covered area: the integral of the winding number over its square, as an absolute
// value clamped to 1 (rasterize_layer.h), from the loops in pixel coordinates (the placement of
// docs/formats.md, without mirrors). Every loop is clipped to a pixel row's strip, then each
// strip polygon to each pixel of that row. Portrait, as PrusaSlicer writes it: the image is
// height_px wide, column 0 at the largest y, row 0 at the largest x.
std::vector<double> reference_coverage(const Layer& layer, const PrinterProfile& p) {
  const int W = p.portrait ? p.height_px : p.width_px, H = p.portrait ? p.width_px : p.height_px;
  std::vector<std::vector<Pt>> loops;
  for (const Loop& l : layer) {
    if (l.open) continue;
    std::vector<Pt> q;
    for (const auto& pt : l.pts) {
      const double x = (pt[0] + p.offset_x_mm) * 1000 / p.pixel_size_x_um,
                   y = (pt[1] + p.offset_y_mm) * 1000 / p.pixel_size_y_um;
      q.push_back(p.portrait ? Pt{W / 2.0 - y, H / 2.0 - x} : Pt{W / 2.0 + x, H / 2.0 - y});
    }
    loops.push_back(q);
  }
  std::vector<double> integral(size_t(W) * H, 0);
  for (int r = 0; r < H; ++r)
    for (const auto& loop : loops) {
      const std::vector<Pt> strip = clip(clip(loop, 1, r, true), 1, r + 1, false);
      if (strip.empty()) continue;
      double lo = strip[0][0], hi = lo;
      for (const Pt& q : strip) lo = std::min(lo, q[0]), hi = std::max(hi, q[0]);
      for (int c = std::max(0, int(std::floor(lo))); c < std::min(W, int(std::floor(hi)) + 1); ++c)
        integral[size_t(r) * W + c] += signed_area(clip(clip(strip, 0, c, true), 0, c + 1, false));
    }
  for (double& f : integral) f = std::min(1.0, std::abs(f));
  return integral;
}

uint8_t level_of(double f, double gamma) { return uint8_t(std::floor(255 * std::pow(f, gamma) + 0.5)); }

std::vector<uint8_t> flipped(const std::vector<uint8_t>& img, int W, int H, bool x, bool y) {
  std::vector<uint8_t> out(img.size());
  for (int r = 0; r < H; ++r)
    for (int c = 0; c < W; ++c) out[size_t(r) * W + c] = img[size_t(y ? H - 1 - r : r) * W + (x ? W - 1 - c : c)];
  return out;
}

}  // namespace

TEST(Antialiasing, EveryPixelWithinOneLevelOfItsExactCoveredArea) {
  const std::vector<Layer> layers = shapes();
  const Slices s = test::make_slices(layers);
  size_t grey_pixels = 0;
  for (const PrinterProfile& display : profiles()) {
    const PrinterProfile p = antialiased(display, 1);
    for (size_t k = 0; k < layers.size(); ++k) {
      const std::vector<double> f = reference_coverage(layers[k], p);
      const std::vector<uint8_t> img = raster(s, k, p);
      size_t off_by_one = 0, grey = 0, worst = 0;
      for (size_t i = 0; i < img.size(); ++i) {
        const int want = level_of(f[i], 1), diff = std::abs(int(img[i]) - want);
        worst = std::max<size_t>(worst, size_t(diff));
        off_by_one += diff == 1;
        grey += want != 0 && want != 255;
      }
      EXPECT_LE(worst, 1u) << "layer " << k << ", pixel " << p.pixel_size_x_um << " um";
      // Off by one only where the exact level is within the fixed point's error of a rounding
      // boundary: rare.
      EXPECT_LE(off_by_one, grey / 100) << "layer " << k << ", pixel " << p.pixel_size_x_um << " um";
      grey_pixels += grey;
    }
  }
  EXPECT_GT(grey_pixels, 10000u);
}

TEST(Antialiasing, FullAndEmptyPixelsAreExact) {
  // An aligned square with an aligned hole: every pixel is fully in, fully out or, on the
  // diamond's diagonals through pixel corners, exactly half covered (127.5 rounds up).
  const Slices s = test::make_slices({{rect(-5, -5, 5, 5), rect(-2, -2, 2, 2, true)},
                                      {{{{0, 4}, {4, 0}, {0, -4}, {-4, 0}}}}});
  const PrinterProfile p = antialiased(small_display(), 1);
  std::vector<uint8_t> img = raster(s, 0, p);
  for (int r = 0; r < 200; ++r)
    for (int c = 0; c < 200; ++c) {
      const bool in_square = r >= 50 && r < 150 && c >= 50 && c < 150, in_hole = r >= 80 && r < 120 && c >= 80 && c < 120;
      ASSERT_EQ(img[size_t(r) * 200 + c], in_square && !in_hole ? 255 : 0) << r << ", " << c;
    }
  img = raster(s, 1, p);
  EXPECT_EQ(img[size_t(60) * 200 + 100], 128);  // (0, 4) - (4, 0) crosses pixel (100, 60) corner to corner
  EXPECT_EQ(img[size_t(60) * 200 + 99], 128);
  EXPECT_EQ(img[size_t(61) * 200 + 100], 255);
  EXPECT_EQ(std::count(img.begin(), img.end(), 128), 4 * 40);
  EXPECT_EQ(std::count(img.begin(), img.end(), 255), 2 * 40 * 39);
}

TEST(Antialiasing, GammaFollowsTheCoverage) {
  // round(255 * f^gamma) of the exact f, allowing for f's fixed-point error (1e-4 is far more).
  const std::vector<Layer> layers = shapes();
  const Slices s = test::make_slices(layers);
  for (double gamma : {0.45, 2.2, 7.0}) {
    const PrinterProfile p = antialiased(profiles()[1], gamma);
    for (size_t k = 0; k < layers.size(); ++k) {
      const std::vector<double> f = reference_coverage(layers[k], p);
      const std::vector<uint8_t> img = raster(s, k, p);
      size_t wrong = 0;
      for (size_t i = 0; i < img.size(); ++i)
        wrong += img[i] < level_of(std::max(0.0, f[i] - 1e-4), gamma) || img[i] > level_of(std::min(1.0, f[i] + 1e-4), gamma);
      EXPECT_EQ(wrong, 0u) << "gamma " << gamma << ", layer " << k;
    }
  }
}

TEST(Antialiasing, GammaZeroIsTheBinaryMask) {
  const std::vector<Layer> layers = shapes();
  const Slices s = test::make_slices(layers);
  for (PrinterProfile binary : profiles())
    for (int mirror = 0; mirror < 4; ++mirror) {
      binary.mirror_x = mirror & 1;
      binary.mirror_y = mirror & 2;
      const PrinterProfile p = antialiased(binary, 0);
      for (size_t k = 0; k < layers.size(); ++k) {
        EXPECT_EQ(raster(s, k, p), raster(s, k, binary)) << "layer " << k << ", mirror " << mirror;
        MaskRuns a, b;
        rasterize_layer_antialiased_runs(s, k, p, a);
        rasterize_layer_runs(s, k, binary, b);
        EXPECT_EQ(a.row_begin, b.row_begin);
        EXPECT_EQ(a.columns, b.columns);
        EXPECT_EQ(a.levels, b.levels);
      }
    }
}

TEST(Antialiasing, LoopStartContourOrderAndReversedDuplicatesChangeNoByte) {
  // Each loop started elsewhere, the loops in reverse order, and a copy of a loop plus the
  // same loop reversed (their edges cancel exactly) added in between.
  const std::vector<Layer> layers = shapes();
  std::vector<Layer> moved;
  for (const Layer& layer : layers) {
    Layer m;
    for (size_t i = layer.size(); i-- > 0;) {
      Loop l = layer[i];
      std::rotate(l.pts.begin(), l.pts.begin() + long((i * 7 + 1) % l.pts.size()), l.pts.end());
      m.push_back(l);
      if (i == 0) {
        const Loop extra = star(-1.3, 2.1, 0.7, 3.3, 6);
        m.insert(m.begin(), extra);
        m.push_back(reversed(extra));
      }
    }
    moved.push_back(m);
  }
  const Slices a = test::make_slices(layers), b = test::make_slices(moved);
  for (double gamma : {1.0, 0.45})
    for (const PrinterProfile& display : profiles())
      for (size_t k = 0; k < layers.size(); ++k)
        EXPECT_EQ(raster(a, k, antialiased(display, gamma)), raster(b, k, antialiased(display, gamma)))
            << "gamma " << gamma << ", layer " << k;
}

TEST(Antialiasing, MirrorsFlipExactly) {
  const std::vector<Layer> layers = shapes();
  const Slices s = test::make_slices(layers);
  for (const PrinterProfile& display : profiles()) {
    PrinterProfile p = antialiased(display, 1);
    for (size_t k = 0; k < layers.size(); ++k) {
      p.mirror_x = p.mirror_y = false;
      const std::vector<uint8_t> plain = raster(s, k, p);
      for (int mirror = 1; mirror < 4; ++mirror) {
        p.mirror_x = mirror & 1;
        p.mirror_y = mirror & 2;
        EXPECT_EQ(raster(s, k, p), flipped(plain, p.width_px, p.height_px, p.mirror_x, p.mirror_y))
            << "layer " << k << ", mirror " << mirror;
      }
    }
  }
}

namespace {

// The runs checked for order and levels, and encoded; the direct PNG (what .sl1 export writes)
// must be the same bytes, mirrored or not, at gamma 0 (binary runs) too.
void expect_runs_encode_the_pixels_as_the_direct_png_does(const Slices& s, size_t k, const PrinterProfile& p) {
  MaskRuns runs;
  rasterize_layer_antialiased_runs(s, k, p, runs);
  const MaskImageLayout image = mask_image_layout(p);
  ASSERT_EQ(runs.row_begin.size(), size_t(image.height) + 1);
  ASSERT_EQ(runs.levels.size(), runs.row_begin.back());
  for (int r = 0; r < image.height; ++r)
    for (uint32_t i = runs.row_begin[size_t(r)]; i < runs.row_begin[size_t(r) + 1]; ++i) {
      EXPECT_LT(runs.columns[2 * i], runs.columns[2 * i + 1]);
      EXPECT_NE(runs.levels[i], 0);
      if (i > runs.row_begin[size_t(r)]) EXPECT_LE(runs.columns[2 * i - 1], runs.columns[2 * i]);
    }
  if (!runs.columns.empty()) EXPECT_LE(runs.columns.back(), image.width);
  std::vector<uint8_t> png, direct;
  encode_mask_png(runs, png);
  MaskImage back;
  decode_mask_png(png.data(), png.size(), "runs", back);
  EXPECT_EQ(back.pixels, raster(s, k, p));
  rasterize_layer_antialiased_png(s, k, p, direct);
  EXPECT_EQ(direct, png);
  // Both from one pass, into outputs holding a former layer's: the same PNG and the same runs.
  std::vector<uint8_t> both_png = png;
  MaskRuns both_runs;
  rasterize_layer_antialiased_runs(s, (k + 1) % s.layers(), p, both_runs);
  rasterize_layer_antialiased_png(s, k, p, both_png, &both_runs);
  EXPECT_EQ(both_png, png);
  EXPECT_EQ(both_runs.width, runs.width);
  EXPECT_EQ(both_runs.height, runs.height);
  EXPECT_EQ(both_runs.row_begin, runs.row_begin);
  EXPECT_EQ(both_runs.columns, runs.columns);
  EXPECT_EQ(both_runs.levels, runs.levels);
}

}  // namespace

TEST(Antialiasing, RunsAreOrderedAndEncodeThePixelsAsTheDirectPngDoes) {
  const std::vector<Layer> layers = shapes();
  const Slices s = test::make_slices(layers);
  for (int mirror = 0; mirror < 4; ++mirror)
    for (double gamma : {1.0, 0.45, 0.0}) {
      PrinterProfile p = antialiased(profiles()[1], gamma);
      p.mirror_x = mirror & 1;
      p.mirror_y = mirror & 2;
      for (size_t k = 0; k < layers.size(); ++k) {
        SCOPED_TRACE("layer " + std::to_string(k) + ", gamma " + std::to_string(gamma) + ", mirror " +
                     std::to_string(mirror));
        expect_runs_encode_the_pixels_as_the_direct_png_does(s, k, p);
      }
    }
  MaskRuns runs;
  EXPECT_THROW(rasterize_layer_antialiased_runs(s, 0, small_display(), runs), Error);  // antialiasing off
  std::vector<uint8_t> png;
  EXPECT_THROW(rasterize_layer_antialiased_png(s, 0, small_display(), png), Error);
}

TEST(Antialiasing, GammaMustBeAFiniteNumberNotBelowZero) {
  PrinterProfile p = small_display();
  validate_printer_profile(p);
  for (double bad : {-0.5, std::nan(""), double(INFINITY)}) {
    p.gamma = bad;
    EXPECT_ERROR(validate_printer_profile(p), "gamma");
  }
  p.gamma = 0;
  validate_printer_profile(p);
  p.gamma = 3.5;
  validate_printer_profile(p);
}

class AntialiasedExport : public test::TempFolderTest {};

TEST_F(AntialiasedExport, Sl1CarriesTheGammaAndIsTheSameOnAnyNumberOfThreads) {
  const Slices s = test::make_slices(shapes());
  const PrinterProfile p = antialiased(profiles()[1], 2.2);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  export_masks(s, p, path("one.sl1"));
  omp_set_num_threads(4);
  export_masks(s, p, path("four.sl1"));
  omp_set_num_threads(threads);
  MaskStack one(path("one.sl1")), four(path("four.sl1"));
  ASSERT_EQ(one.layers(), s.layers());
  std::vector<uint8_t> a, b;
  for (size_t k = 0; k < s.layers(); ++k) {
    one.read(k, a);
    four.read(k, b);
    EXPECT_EQ(a, b) << "layer " << k;
  }
  EXPECT_NE(test::zip_entry(path("one.sl1"), "prusaslicer.ini").find("\ngamma_correction = 2.2\n"), std::string::npos);
  PrinterProfile binary = p;
  binary.antialiasing = false;
  export_masks(s, binary, path("binary.sl1"));
  EXPECT_NE(test::zip_entry(path("binary.sl1"), "prusaslicer.ini").find("\ngamma_correction = 0\n"), std::string::npos);
}

TEST(Antialiasing, PortraitIsTheDisplayTurnedCounterClockwiseThenMirrored) {
  // A display 200 px along x and 160 along y, portrait: images 160 wide and 200 tall, against
  // the independent coverage in PrusaSlicer's portrait placement; mirrors flip the image's
  // columns (mirror_x) and rows (mirror_y), and gamma 0 is still the binary mask.
  const std::vector<Layer> layers = shapes();
  const Slices s = test::make_slices(layers);
  PrinterProfile p = antialiased(profiles()[1], 1);
  p.height_px = 160;
  p.portrait = true;
  for (int mirror = 0; mirror < 4; ++mirror) {
    p.mirror_x = mirror & 1;
    p.mirror_y = mirror & 2;
    const MaskImageLayout image = mask_image_layout(p);
    ASSERT_EQ(image.width, 160);
    ASSERT_EQ(image.height, 200);
    for (size_t k = 0; k < layers.size(); ++k) {
      const std::vector<double> f = reference_coverage(layers[k], p);
      std::vector<uint8_t> want(f.size());
      for (size_t i = 0; i < f.size(); ++i) want[i] = level_of(f[i], 1);
      want = flipped(want, 160, 200, p.mirror_x, p.mirror_y);
      const std::vector<uint8_t> img = raster(s, k, p);
      ASSERT_EQ(img.size(), want.size());
      int worst = 0;
      for (size_t i = 0; i < img.size(); ++i) worst = std::max(worst, std::abs(int(img[i]) - int(want[i])));
      EXPECT_LE(worst, 1) << "layer " << k << ", mirror " << mirror;
      PrinterProfile binary = p;
      binary.antialiasing = false;
      EXPECT_EQ(raster(s, k, antialiased(p, 0)), raster(s, k, binary)) << "layer " << k << ", mirror " << mirror;
      expect_runs_encode_the_pixels_as_the_direct_png_does(s, k, p);
    }
  }
}
