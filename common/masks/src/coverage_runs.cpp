#include "coverage_runs.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "pixel_map.h"
#include "png_rows.h"

namespace slicereuse {
namespace {

// Positions inside a pixel in units of 1/kOne of its side; areas in units of 1/kFull of a
// pixel (the trapezoid rule's halving is left out, so every sum stays an integer).
constexpr int kFractionBits = 16;
constexpr int32_t kOne = int32_t(1) << kFractionBits;
constexpr int64_t kFull = int64_t(2) * kOne * kOne;

// A point of a contour in pixel coordinates, and the pixel it lies in: row in [-1, H] and
// column in [-1, W], clamped (-1 and H or W stand for everything beyond the display), with its
// fixed-point position inside that pixel (rounded to it, so a point may land on the next
// pixel's border). Both edges at a point use these same numbers, which makes the heights of the
// pieces along a contour add up exactly.
struct Point {
  double u, v;
  int32_t row, col;
  int32_t fy, fx;  // 0..kOne
};

// t in [0, 1] as 0..kOne, rounded (t just outside, from rounding, is clamped; NaN gives 0).
int32_t fraction(double t) { return int32_t(std::min(1.0, std::max(0.0, t)) * kOne + 0.5); }

// x clamped to [-1, n] (NaN to -1) in fixed point, kOne per pixel, rounded: its pixel is the
// value >> kFractionBits, its position inside the pixel the low bits. (One conversion, where
// std::floor would be a library call on baseline x86-64.)
int64_t fixed_within(double x, int n) {
  return int64_t((std::min(double(n), std::max(-1.0, x)) + 1) * kOne + 0.5) - kOne;
}

// A point that is not finite gets row -1, so its edges are either skipped or (an edge to a
// finite point) dropped by add_edge.
Point pixel_point(const PixelMap& m, const double* xyz, int W, int H) {
  Point p;
  p.u = m.u(xyz);
  p.v = m.v(xyz);
  const int64_t u = fixed_within(p.u, W), v = fixed_within(p.v, H);
  p.row = std::isfinite(p.u) ? int32_t(v >> kFractionBits) : -1;
  p.col = int32_t(u >> kFractionBits);
  p.fy = int32_t(v & (kOne - 1));
  p.fx = int32_t(u & (kOne - 1));
  return p;
}

// The sums of a strip of rows [r0, r1), per pixel and, in column -1, for everything left of the
// display: area, the sum of dv * (2 kOne - x_in - x_out) over the pieces of edges in the pixel
// (a piece's height times the part of the pixel right of it, doubled), and cover, the sum of
// their heights dv, which every pixel further right in the row gets in full; and which pixels
// have any. A strip is small enough to stay in cache: the pieces are added straight into it,
// in any order (the sums are of integers).
struct Strip {
  struct Sums {
    int64_t area, cover;
  };
  int32_t r0, r1;
  int W;
  size_t words;  // of the bit mask of touched pixels, per row
  Sums* sums;    // (r - r0) * (W + 1) + column + 1
  uint64_t* touched;

  // A piece of height dv (signed: positive when the contour runs downwards) in pixel (row, col),
  // entering and leaving at x_in and x_out, x_sum = x_in + x_out. A piece without height adds
  // nothing, and its pixel comes out as if untouched.
  void add(int32_t row, int32_t col, int32_t dv, int32_t x_sum) const {
    const size_t j = size_t(col + 1);
    Sums& s = sums[size_t(row - r0) * size_t(W + 1) + j];
    s.area += int64_t(dv) * (2 * kOne - x_sum);
    s.cover += dv;
    touched[size_t(row - r0) * words + (j >> 6)] |= uint64_t(1) << (j & 63);
  }
};

// Where edge (a, b) crosses row boundary y: the row below it (v = y is its top), column and
// position in it.
Point at_row_boundary(const Point& a, double du_dv, int32_t y, int W) {
  Point p;
  p.u = a.u + (y - a.v) * du_dv;
  p.v = y;
  const int64_t u = fixed_within(p.u, W);
  p.row = y;
  p.col = int32_t(u >> kFractionBits);
  p.fy = 0;
  p.fx = int32_t(u & (kOne - 1));
  return p;
}

// The pieces of edge (p, q), contour order p -> q, in the strip's rows. The edge is followed
// from pixel to pixel, at each step across whichever of the next row boundary and the next
// column boundary it meets first. Every crossing is computed from its lower endpoint (smaller
// v), so an edge and its reverse give the same pieces, and so does an edge that two strips
// share. Pixels beyond the display's right side are skipped; those left of it add their height
// to column -1.
void add_edge(const Point& p, const Point& q, const Strip& st) {
  if (p.row == q.row && p.col == q.col) {  // a third of a fine contour's edges: one piece
    if (p.col < st.W) st.add(p.row, p.col, q.fy - p.fy, p.fx + q.fx);
    return;
  }
  const bool down = p.v < q.v;
  const Point& a = down ? p : q;
  const Point& b = down ? q : p;
  const int32_t sign = down ? 1 : -1;
  // Horizontal edges have no height and cover nothing; non-finite ones (only possible when the
  // caller skipped validate_slices) are dropped.
  if (!(a.v < b.v) || !std::isfinite(b.v - a.v) || !std::isfinite(b.u - a.u)) return;
  const double du_dv = (b.u - a.u) / (b.v - a.v), dv_du = (b.v - a.v) / (b.u - a.u);
  // From a, or where the edge enters the strip's first row, to b, or where it leaves the last.
  const Point from = a.row < st.r0 ? at_row_boundary(a, du_dv, st.r0, st.W) : a;
  Point to = b;
  if (b.row >= st.r1) {
    to = at_row_boundary(a, du_dv, st.r1, st.W);
    to.row = st.r1 - 1;
    to.fy = kOne;
  }
  const int32_t step = to.col < from.col ? -1 : 1, side = to.col < from.col ? 0 : kOne;  // where to lies
  int32_t n = to.row - from.row + (to.col - from.col) * step;  // boundaries crossed
  int32_t r = from.row, c = from.col, fy = from.fy, fx = from.fx;  // the piece so far
  double y = r + 1, x = c + (step > 0);                         // the next row and column boundaries
  for (; n > 0; --n) {
    const double u_y = a.u + (y - a.v) * du_dv, v_x = a.v + (x - a.u) * dv_du;
    const bool row_next = r < to.row && (c == to.col || y <= v_x);
    const int32_t t_end = row_next ? kOne : std::clamp(fraction(v_x - r), fy, r == to.row ? to.fy : kOne);
    const int32_t x_end = row_next ? fraction(u_y - c) : side;
    if (c < st.W) st.add(r, c, sign * (t_end - fy), fx + x_end);
    fy = row_next ? 0 : t_end;
    fx = row_next ? x_end : kOne - side;
    r += row_next;
    c += row_next ? 0 : step;
    y += row_next;
    x += row_next ? 0 : step;
  }
  if (c < st.W) st.add(r, c, sign * (to.fy - fy), fx + to.fx);
}

// Grey level round(255 * f^gamma) of coverage f = min(|x| / kFull, 1), by thresholds: level L
// starts at the least x with 255 * f^gamma >= L - 1/2, and a table over x's top bits gives the
// level to start counting from, instead of a pow per pixel.
class CoverageLevels {
 public:
  void set_gamma(double gamma) {
    if (gamma == gamma_) return;
    gamma_ = gamma;
    linear_ = gamma == 1;
    threshold_[0] = 0;
    for (int level = 1; level < 256; ++level) {
      const double f = std::pow((level - 0.5) / 255, 1 / gamma);
      threshold_[level] = std::clamp<int64_t>(int64_t(std::ceil(f * double(kFull))), 1, kFull);
    }
    threshold_[256] = std::numeric_limits<int64_t>::max();
    int level = 0;
    for (int64_t i = 0; i <= kFull >> kCoarseShift; ++i) {
      while (threshold_[level + 1] <= i << kCoarseShift) ++level;
      first_[i] = uint8_t(level);
    }
  }

  uint8_t operator()(int64_t x) const {
    const int64_t a = int64_t(std::min(x < 0 ? 0 - uint64_t(x) : uint64_t(x), uint64_t(kFull)));
    // The thresholds' own values at gamma 1, without looking them up.
    if (linear_) return uint8_t((255 * a + kFull / 2) / kFull);
    int level = first_[a >> kCoarseShift];
    // One step without a branch covers every coarse step up to gamma 16 and most for any gamma;
    // only very small coverages at gamma < 1 count further.
    level += int(threshold_[level + 1] <= a);
    while (threshold_[level + 1] <= a) ++level;
    return uint8_t(level);
  }

 private:
  static constexpr int kCoarseShift = 21;  // 4096 coarse steps of coverage
  double gamma_ = 0;                       // 0: not set (gamma 0 is binary, never here)
  bool linear_ = false;
  int64_t threshold_[257];
  uint8_t first_[(kFull >> kCoarseShift) + 1];
};

// Edges [first, end) (edge i joins points i and i + 1), all in one strip's rows.
struct EdgeRange {
  uint32_t strip, first, end;
};

struct Scratch {
  std::vector<Point> points;  // the layer's closed contours, each with its first point repeated
  std::vector<EdgeRange> ranges, by_strip;
  std::vector<uint32_t> strip_begin;
  std::vector<Strip::Sums> sums;
  std::vector<uint64_t> touched;
  std::vector<std::pair<uint8_t, size_t>> spans;  // a row's, to be mirrored
  CoverageLevels levels;
};

// Rows per strip: a power of two, for about kStripPixels pixels' sums (16 bytes each), which
// stay in cache.
constexpr size_t kStripPixels = 32768;

int strip_shift(int W) {
  int shift = 0;
  while (shift < 16 && (size_t(2) << shift) * size_t(W + 1) <= kStripPixels) ++shift;
  return shift;
}

// Layer k's points, and its edges in ranges by strip of 2^shift rows: consecutive edges of a
// contour in the same strip make one range, an edge across strips a range in each. Edges
// wholly above or below the display are left out. Returns the number of open contours.
size_t add_edges(const Slices& s, size_t k, const PixelMap& map, int W, int H, int shift, Scratch& w) {
  w.points.clear();
  w.ranges.clear();
  return for_each_closed_contour(s, k, [&](const double* xyz, uint64_t n) {
    const size_t base = w.points.size();
    w.points.resize(base + n + 1);
    Point* const pts = w.points.data() + base;
    for (uint64_t i = 0; i < n; ++i) pts[i] = pixel_point(map, xyz + 3 * i, W, H);
    pts[n] = pts[0];
    EdgeRange range{UINT32_MAX, 0, 0};
    for (uint64_t i = 0; i < n; ++i) {
      const int32_t lo = std::max(std::min(pts[i].row, pts[i + 1].row), 0);
      const int32_t hi = std::min(std::max(pts[i].row, pts[i + 1].row), H - 1);
      if (lo > hi) continue;
      const uint32_t first = uint32_t(lo) >> shift, last = uint32_t(hi) >> shift, e = uint32_t(base + i);
      if (first == last && first == range.strip && range.end == e) {
        ++range.end;
        continue;
      }
      if (range.first < range.end) w.ranges.push_back(range);
      range = {first, e, e + 1};
      for (uint32_t strip = first + 1; strip <= last; ++strip) w.ranges.push_back({strip, e, e + 1});
    }
    if (range.first < range.end) w.ranges.push_back(range);
  });
}

// Strip row r as spans of one level, left to right, covering the row: emit(level, n). A running
// sum of the covers left of each column gives the pixels between touched ones (full or empty,
// exactly, unless an edge passes them without height), and each touched pixel adds its area.
// Leaves the row's sums and bits zero.
template <class Emit>
void sweep_row(const Strip& st, int32_t r, const CoverageLevels& levels, Emit&& emit) {
  Strip::Sums* const sums = st.sums + size_t(r - st.r0) * size_t(st.W + 1);
  uint64_t* const touched = st.touched + size_t(r - st.r0) * st.words;
  // Between touched pixels: nothing, full (a whole number of windings), or rarely anything else.
  auto level_of = [&](int64_t carry) {
    return carry == 0 ? 0 : carry >= kOne || carry <= -kOne ? 255 : levels(carry * (2 * kOne));
  };
  int64_t carry = 0;  // covers left of the next column, in units of kOne
  int at = 0;         // columns before it are emitted
  for (size_t word = 0; word < st.words; ++word) {
    for (uint64_t bits = std::exchange(touched[word], 0); bits; bits &= bits - 1) {
      const size_t j = word * 64 + size_t(__builtin_ctzll(bits));
      const Strip::Sums here = std::exchange(sums[j], Strip::Sums{0, 0});
      if (j > 0) {
        const int col = int(j) - 1;
        if (at < col) emit(level_of(carry), size_t(col - at));
        emit(levels(carry * (2 * kOne) + here.area), size_t(1));
        at = col + 1;
      }
      carry += here.cover;
    }
  }
  if (at < st.W) emit(level_of(carry), size_t(st.W - at));
}

// The pixels a sink gets, row by row, top to bottom: row(), then pixels(level, n) covering it.
// The sink's rows are the image's, flips applied (mask_image_layout): the rows of the unflipped
// image in reverse when rows ascend, each row's spans in reverse when columns descend.
template <class Sink>
size_t rasterize_coverage(const Slices& s, size_t k, const PrinterProfile& p, Sink& sink) {
  thread_local Scratch scratch;
  Scratch& w = scratch;
  const MaskImageLayout image = mask_image_layout(p);
  const int W = image.width, H = image.height;
  const int shift = strip_shift(W), rows = 1 << shift;
  const size_t strips = size_t((H + rows - 1) >> shift);
  w.levels.set_gamma(p.gamma);
  const size_t open = add_edges(s, k, pixel_map(image, false), W, H, shift, w);

  // Ranges by strip: counted, then placed (a counting sort); afterwards strip_begin[i] is where
  // strip i + 1 begins.
  std::vector<uint32_t>& begin = w.strip_begin;
  begin.assign(strips + 1, 0);
  for (const EdgeRange& r : w.ranges) ++begin[r.strip + 1];
  for (size_t i = 1; i <= strips; ++i) begin[i] += begin[i - 1];
  w.by_strip.resize(w.ranges.size());
  for (const EdgeRange& r : w.ranges) w.by_strip[begin[r.strip]++] = r;

  const size_t words = size_t(W) / 64 + 1;
  w.sums.assign(size_t(rows) * size_t(W + 1), Strip::Sums{0, 0});
  w.touched.assign(size_t(rows) * words, 0);
  const Point* const pts = w.points.data();
  for (size_t n = 0; n < strips; ++n) {
    const size_t i = image.rows_ascend ? strips - 1 - n : n;
    const int32_t r0 = int32_t(i) * rows;
    const Strip st{r0, std::min(r0 + rows, H), W, words, w.sums.data(), w.touched.data()};
    for (uint32_t e = i == 0 ? 0 : begin[i - 1]; e < begin[i]; ++e)
      for (uint32_t j = w.by_strip[e].first; j < w.by_strip[e].end; ++j) add_edge(pts[j], pts[j + 1], st);
    for (int32_t m = 0; m < st.r1 - st.r0; ++m) {
      const int32_t r = image.rows_ascend ? st.r1 - 1 - m : st.r0 + m;
      sink.row();
      if (!image.columns_descend) {
        sweep_row(st, r, w.levels, [&](int level, size_t count) { sink.pixels(uint8_t(level), count); });
        continue;
      }
      w.spans.clear();
      sweep_row(st, r, w.levels, [&](int level, size_t count) { w.spans.push_back({uint8_t(level), count}); });
      for (size_t q = w.spans.size(); q-- > 0;) sink.pixels(w.spans[q].first, w.spans[q].second);
    }
  }
  return open;
}

// Runs of non-zero pixels, adjacent ones of one level joined.
class RunsSink {
 public:
  RunsSink(int W, int H, MaskRuns& out) : out_(out) {
    out.width = W;
    out.height = H;
    out.row_begin.assign(1, 0);
    out.row_begin.reserve(size_t(H) + 1);
    out.columns.clear();
    out.levels.clear();
  }
  void row() {
    if (at_ >= 0) out_.row_begin.push_back(uint32_t(out_.levels.size()));
    at_ = 0;
    row_first_ = out_.levels.size();
  }
  void pixels(uint8_t level, size_t n) {
    const int end = at_ + int(n);
    if (level != 0) {
      if (out_.levels.size() > row_first_ && out_.columns.back() == at_ && out_.levels.back() == level) {
        out_.columns.back() = uint16_t(end);
      } else {
        out_.columns.push_back(uint16_t(at_));
        out_.columns.push_back(uint16_t(end));
        out_.levels.push_back(level);
      }
    }
    at_ = end;
  }
  void finish() { out_.row_begin.push_back(uint32_t(out_.levels.size())); }

 private:
  MaskRuns& out_;
  int at_ = -1;  // the row's next column; -1 before the first row
  size_t row_first_ = 0;
};

}  // namespace

size_t coverage_runs(const Slices& s, size_t k, const PrinterProfile& p, MaskRuns& out) {
  const MaskImageLayout image = mask_image_layout(p);
  RunsSink sink(image.width, image.height, out);
  const size_t open = rasterize_coverage(s, k, p, sink);
  sink.finish();
  return open;
}

size_t coverage_png(const Slices& s, size_t k, const PrinterProfile& p, std::vector<uint8_t>& png) {
  const MaskImageLayout image = mask_image_layout(p);
  PngRows sink(image.width, image.height, png);
  const size_t open = rasterize_coverage(s, k, p, sink);
  sink.finish();
  return open;
}

}  // namespace slicereuse
