#include "coverage_runs.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "pixel_map.h"
#include "slicereuse/printer/grey_levels.h"
#include "slicereuse/png/png_rows.h"
#include "slicereuse/util/buffer.h"

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

// The sums of a pixel: area, the sum of dv * (2 kOne - x_in - x_out) over the pieces of edges
// in it (a piece's height times the part of the pixel right of it, doubled), and cover, the sum
// of their heights dv, which every pixel further right in the row gets in full.
struct PixelSums {
  int64_t area, cover;
};

// A strip of rows [r0, r1): the sums per pixel and, in column -1, for everything left of the
// display; which pixels have any, one bit each; and, with kSummary, which words of those bits
// are not zero, one bit each, so that a row's sweep visits only those. The summary is kept on
// displays whose rows have more than kScannedWords words of bits (most of a wide display's
// words are zero); a narrower row's sweep reads its every word, which costs less than keeping
// the summary (bench/RESULTS.md). Pixel (r, c) is number (r - r0) * stride + c + 1 in all;
// stride, a multiple of 64, is at least W + 1, so each row's bits are whole words. A strip is
// small enough to stay in cache: the pieces are added straight into it, in any order (the sums
// are of integers).
template <bool kSummary>
struct Strip {
  static constexpr bool summary = kSummary;
  int32_t r0, r1;
  int W;
  int32_t stride;
  PixelSums* sums;
  uint64_t* touched;
  uint64_t* touched_words;  // with kSummary

  // A piece of height dv (signed: positive when the contour runs downwards) in pixel (row, col),
  // entering and leaving at x_in and x_out, x_sum = x_in + x_out. A piece without height adds
  // nothing, and its pixel comes out as if untouched.
  void add(int32_t row, int32_t col, int32_t dv, int32_t x_sum) const {
    const size_t i = size_t((row - r0) * stride + col + 1);
    PixelSums& s = sums[i];
    s.area += int64_t(dv) * (2 * kOne - x_sum);
    s.cover += dv;
    touched[i >> 6] |= uint64_t(1) << (i & 63);
    if constexpr (kSummary) touched_words[i >> 12] |= uint64_t(1) << ((i >> 6) & 63);
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

// std::clamp as libstdc++ computes it, min(max(v, lo), hi), also where lo > hi (a point rounded
// onto its pixel's border): written out, so that every path gives the same numbers whatever the
// library's std::clamp does there; in arithmetic, as the compiler's own min and max are
// sometimes branches, which the kinds of edges below would mispredict.
int32_t clamp_of(int32_t v, int32_t lo, int32_t hi) {
  const int32_t at_least = v ^ ((v ^ lo) & -int32_t(v < lo));
  return at_least ^ ((at_least ^ hi) & -int32_t(hi < at_least));
}

// Edge e[0] -> e[1] oriented from its lower endpoint a (smaller v) to b, and +1 when that is the
// contour's direction (downwards), else -1.
struct Oriented {
  const Point* a;
  const Point* b;
  int32_t sign;
};

Oriented oriented(const Point* e) {
  const bool down = e[0].v < e[1].v;
  return {e + !down, e + down, 2 * int32_t(down) - 1};
}

// The pieces of edge e[0] -> e[1] in the strip's rows. The edge is followed from pixel to pixel,
// at each step across whichever of the next row boundary and the next column boundary it meets
// first, from a, or where it enters the strip's first row, to b, or where it leaves the last.
// Every crossing is computed from the lower endpoint a (smaller v), so an edge and its reverse
// give the same pieces, and so does an edge that two strips share. Pixels beyond the display's
// right side are skipped; those left of it add their height to column -1.
template <class Strip>
void add_edge(const Point* e, const Strip& st) {
  const Point &p = e[0], &q = e[1];
  if (p.row == q.row && p.col == q.col) {  // one piece
    if (p.col < st.W) st.add(p.row, p.col, q.fy - p.fy, p.fx + q.fx);
    return;
  }
  const Oriented o = oriented(e);
  const Point &a = *o.a, &b = *o.b;
  // Horizontal edges have no height and cover nothing; non-finite ones (only possible when the
  // caller skipped validate_slices) are dropped.
  if (!(a.v < b.v) || !std::isfinite(b.v - a.v) || !std::isfinite(b.u - a.u)) return;
  const double du_dv = (b.u - a.u) / (b.v - a.v), dv_du = (b.v - a.v) / (b.u - a.u);
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
    const int32_t t_end = row_next ? kOne : clamp_of(fraction(v_x - r), fy, r == to.row ? to.fy : kOne);
    const int32_t x_end = row_next ? fraction(u_y - c) : side;
    if (c < st.W) st.add(r, c, o.sign * (t_end - fy), fx + x_end);
    fy = row_next ? 0 : t_end;
    fx = row_next ? x_end : kOne - side;
    r += row_next;
    c += row_next ? 0 : step;
    y += row_next;
    x += row_next ? 0 : step;
  }
  if (c < st.W) st.add(r, c, o.sign * (to.fy - fy), fx + to.fx);
}

// How add_edge's pieces of an edge are found without following it in a loop whose steps depend
// on the edge: a third of a fine contour's edges lie in one pixel, most others cross one or two
// pixel boundaries, and which of those an edge is follows no pattern a branch predictor could
// learn. So the edges of a strip are sorted by kind first, and each kind is added by code that
// does the same steps, add_edge's, for every edge of it: the kinds of up to two crossings of a
// row (R) and column (C) boundary, in the order met for RC. kOther is anything else (add_edge
// itself): more crossings, a horizontal edge, or one that leaves the strip or the display's rows.
enum EdgeKind : uint32_t { kOnePiece, kR, kC, kRR, kCC, kRC, kOther, kKinds };

template <class Strip>
void add_one_piece(const Point* e, const Strip& st) {
  if (e[0].col < st.W) st.add(e[0].row, e[0].col, e[1].fy - e[0].fy, e[0].fx + e[1].fx);
}

// Where an edge from a crosses row boundary y, as a position in column c, and column boundary x,
// as a position in row r: add_edge's numbers.
int32_t at_row(const Point& a, double du_dv, int32_t y, int32_t c) { return fraction(a.u + (y - a.v) * du_dv - c); }
int32_t at_column(const Point& a, double dv_du, double x, int32_t r) { return fraction(a.v + (x - a.u) * dv_du - r); }

template <class Strip>
void add_r(const Point* e, const Strip& st) {
  const Oriented o = oriented(e);
  const Point &a = *o.a, &b = *o.b;
  if (a.col >= st.W) return;
  const int32_t x = at_row(a, (b.u - a.u) / (b.v - a.v), a.row + 1, a.col);
  st.add(a.row, a.col, o.sign * (kOne - a.fy), a.fx + x);
  st.add(b.row, b.col, o.sign * b.fy, x + b.fx);
}

template <class Strip>
void add_rr(const Point* e, const Strip& st) {
  const Oriented o = oriented(e);
  const Point &a = *o.a, &b = *o.b;
  if (a.col >= st.W) return;
  const double du_dv = (b.u - a.u) / (b.v - a.v);
  const int32_t x1 = at_row(a, du_dv, a.row + 1, a.col), x2 = at_row(a, du_dv, a.row + 2, a.col);
  st.add(a.row, a.col, o.sign * (kOne - a.fy), a.fx + x1);
  st.add(a.row + 1, a.col, o.sign * kOne, x1 + x2);
  st.add(b.row, b.col, o.sign * b.fy, x2 + b.fx);
}

// The column crossings of kC and kCC: towards larger columns (right) they leave a pixel at its
// right side, x = kOne, and enter the next at 0.
template <class Strip>
void add_c(const Point* e, const Strip& st) {
  const Oriented o = oriented(e);
  const Point &a = *o.a, &b = *o.b;
  const bool right = b.col > a.col;
  const int32_t side = kOne * int32_t(right);
  const int32_t t = clamp_of(at_column(a, (b.v - a.v) / (b.u - a.u), a.col + right, a.row), a.fy, b.fy);
  if (a.col < st.W) st.add(a.row, a.col, o.sign * (t - a.fy), a.fx + side);
  if (b.col < st.W) st.add(b.row, b.col, o.sign * (b.fy - t), kOne - side + b.fx);
}

template <class Strip>
void add_cc(const Point* e, const Strip& st) {
  const Oriented o = oriented(e);
  const Point &a = *o.a, &b = *o.b;
  const bool right = b.col > a.col;
  const int32_t step = 2 * int32_t(right) - 1, side = kOne * int32_t(right);
  const double dv_du = (b.v - a.v) / (b.u - a.u), x1 = a.col + right;
  const int32_t t1 = clamp_of(at_column(a, dv_du, x1, a.row), a.fy, b.fy);
  const int32_t t2 = clamp_of(at_column(a, dv_du, x1 + step, a.row), t1, b.fy);
  if (a.col < st.W) st.add(a.row, a.col, o.sign * (t1 - a.fy), a.fx + side);
  if (a.col + step < st.W) st.add(a.row, a.col + step, o.sign * (t2 - t1), kOne);
  if (b.col < st.W) st.add(b.row, b.col, o.sign * (b.fy - t2), kOne - side + b.fx);
}

// One row and one column crossing, in the order the edge meets them: the middle piece is in the
// pixel below a's (row first) or beside it.
template <class Strip>
void add_rc(const Point* e, const Strip& st) {
  const Oriented o = oriented(e);
  const Point &a = *o.a, &b = *o.b;
  const bool right = b.col > a.col;
  const int32_t step = 2 * int32_t(right) - 1, side = kOne * int32_t(right);
  const double du_dv = (b.u - a.u) / (b.v - a.v), dv_du = (b.v - a.v) / (b.u - a.u);
  const double x = a.col + right;
  const bool row_first = a.row + 1 <= a.v + (x - a.u) * dv_du;
  int32_t dv0, x0, mid_row, mid_col, dv1, x1, dv2, x2;
  if (row_first) {
    const int32_t x_row = at_row(a, du_dv, a.row + 1, a.col);
    const int32_t t = clamp_of(at_column(a, dv_du, x, a.row + 1), 0, b.fy);
    dv0 = kOne - a.fy, x0 = a.fx + x_row;
    mid_row = a.row + 1, mid_col = a.col, dv1 = t, x1 = x_row + side;
    dv2 = b.fy - t, x2 = kOne - side + b.fx;
  } else {
    const int32_t t = clamp_of(at_column(a, dv_du, x, a.row), a.fy, kOne);
    const int32_t x_row = at_row(a, du_dv, a.row + 1, a.col + step);
    dv0 = t - a.fy, x0 = a.fx + side;
    mid_row = a.row, mid_col = a.col + step, dv1 = kOne - t, x1 = kOne - side + x_row;
    dv2 = b.fy, x2 = x_row + b.fx;
  }
  if (a.col < st.W) st.add(a.row, a.col, o.sign * dv0, x0);
  if (mid_col < st.W) st.add(mid_row, mid_col, o.sign * dv1, x1);
  if (b.col < st.W) st.add(b.row, b.col, o.sign * dv2, x2);
}

// Grey level round(255 * f^gamma) of coverage f = min(|x| / kFull, 1), by thresholds: level L
// starts at the least x with 255 * f^gamma >= L - 1/2, and a table over x's top bits gives the
// level to start counting from, instead of a pow per pixel. Then the nearest level the printer's
// file holds (grey_levels.h), by a table.
class CoverageLevels {
 public:
  void set(double gamma, int grey_levels) {
    if (gamma == gamma_ && grey_levels == grey_levels_) return;
    gamma_ = gamma;
    grey_levels_ = grey_levels;
    linear_ = gamma == 1;
    for (int level = 0; level < 256; ++level) held_[level] = representable_grey_level(uint8_t(level), grey_levels);
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
    if (linear_) return held_[(255 * uint64_t(a) + uint64_t(kFull / 2)) / uint64_t(kFull)];
    int level = first_[a >> kCoarseShift];
    // One step without a branch covers every coarse step up to gamma 16 and most for any gamma;
    // only very small coverages at gamma < 1 count further.
    level += int(threshold_[level + 1] <= a);
    while (threshold_[level + 1] <= a) ++level;
    return held_[level];
  }

 private:
  static constexpr int kCoarseShift = 21;  // 4096 coarse steps of coverage
  double gamma_ = 0;                       // 0: not set (gamma 0 is binary, never here)
  int grey_levels_ = 0;
  bool linear_ = false;
  int64_t threshold_[257];
  uint8_t first_[(kFull >> kCoarseShift) + 1];
  uint8_t held_[256];  // level -> the nearest level the file holds
};

struct Scratch {
  Buffer<Point> points;           // the layer's closed contours, each with its first point repeated
  Buffer<uint64_t> entries;        // per edge in one strip: strip and kind << 32 | edge
  std::vector<uint64_t> crossing;  // and so per strip of an edge in several (or beyond the rows)
  std::vector<uint32_t> begin;    // per strip and kind, where its edges begin in edges
  Buffer<uint32_t> edges;         // edge i joins points i and i + 1
  std::vector<PixelSums> sums;
  std::vector<uint64_t> touched;
  std::vector<uint64_t> touched_words;
  std::vector<std::pair<uint8_t, size_t>> spans;  // a row's, to be mirrored
  bool clear = false;                              // sums, touched and touched_words are all zero
  CoverageLevels levels;
};

// Rows per strip: a power of two, for about kStripPixels pixels' sums (16 bytes each), which
// stay in cache.
constexpr size_t kStripPixels = 32768;

// Rows of at most this many words of touched bits (displays up to 4095 pixels wide) are swept
// without the words' summary (Strip).
constexpr int32_t kScannedWords = 64;

int strip_shift(int32_t stride) {
  int shift = 0;
  while (shift < 16 && (size_t(2) << shift) * size_t(stride) <= kStripPixels) ++shift;
  return shift;
}

// The kind of edge p -> q, both in the display's rows and one strip: from the pixels alone, by
// a table. (A horizontal edge, kC or kCC, gets pieces of height 0: nothing, as in add_edge.)
uint32_t edge_kind(const Point& p, const Point& q) {
  static constexpr uint8_t by_crossings[4][4] = {{kOnePiece, kC, kCC, kOther},
                                                 {kR, kRC, kOther, kOther},
                                                 {kRR, kOther, kOther, kOther},
                                                 {kOther, kOther, kOther, kOther}};
  return by_crossings[std::min(std::abs(q.row - p.row), 3)][std::min(std::abs(q.col - p.col), 3)];
}

// The layer's points (w.points), and its edges sorted by strip of 2^shift rows and by kind within
// a strip (w.edges, strip i's edges of kind j from w.begin[i * kKinds + j]): an edge across
// strips, or reaching beyond the display's rows, is kOther in each strip it is in. Edges wholly
// above or below the display are left out. Returns the number of open contours.
size_t add_edges(const LayerView& layer, const PixelMap& map, int W, int H, int shift, size_t strips, Scratch& w) {
  w.points.clear();
  w.entries.clear();
  w.crossing.clear();
  w.begin.assign(strips * kKinds + 1, 0);
  uint32_t* const count = w.begin.data() + 1;  // per bucket, for now
  // The scalars by value: captured by reference, they could be any int the loop stores to.
  const size_t open = for_each_closed_contour(layer, [&w, count, map, W, H, shift](const double* xyz, uint64_t n) {
    const size_t base = w.points.size(), used = w.entries.size();
    w.points.resize(base + n + 1);
    w.entries.resize(used + n);
    Point* const pts = w.points.data() + base;
    uint64_t* entry = w.entries.data() + used;
    for (uint64_t i = 0; i < n; ++i) pts[i] = pixel_point(map, xyz + 3 * i, W, H);
    pts[n] = pts[0];
    for (uint64_t i = 0; i < n; ++i) {
      const Point &p = pts[i], &q = pts[i + 1];
      const int32_t top = std::min(p.row, q.row), bottom = std::max(p.row, q.row);
      if (bottom < 0 || top >= H) continue;
      if (top >= 0 && bottom < H && top >> shift == bottom >> shift) {
        const uint64_t key = uint64_t(top >> shift) * kKinds + edge_kind(p, q);
        ++count[key];
        *entry++ = key << 32 | (base + i);
        continue;
      }
      for (int32_t strip = std::max(top, 0) >> shift; strip <= std::min(bottom, H - 1) >> shift; ++strip) {
        const uint64_t key = uint64_t(strip) * kKinds + kOther;
        ++count[key];
        w.crossing.push_back(key << 32 | (base + i));
      }
    }
    w.entries.resize(size_t(entry - w.entries.data()));
  });
  // A counting sort by strip and kind: begin[i] becomes where bucket i - 1 begins, then, as the
  // edges are placed, where bucket i does.
  for (size_t i = 1; i < w.begin.size(); ++i) w.begin[i] += w.begin[i - 1];
  for (size_t i = w.begin.size() - 1; i > 0; --i) w.begin[i] = w.begin[i - 1];
  w.begin[0] = 0;
  w.edges.resize(w.entries.size() + w.crossing.size());
  uint32_t* const place = w.begin.data() + 1;
  for (const uint64_t entry : w.entries) w.edges[place[entry >> 32]++] = uint32_t(entry);
  for (const uint64_t entry : w.crossing) w.edges[place[entry >> 32]++] = uint32_t(entry);
  return open;
}

// The pieces of strip i's edges, kind by kind.
template <class Strip>
void add_strip_edges(const Scratch& w, size_t i, const Strip& st) {
  const Point* const pts = w.points.data();
  const uint32_t* const edges = w.edges.data();
  auto each = [&](uint32_t kind, auto add) {
    for (uint32_t j = w.begin[i * kKinds + kind]; j < w.begin[i * kKinds + kind + 1]; ++j) add(pts + edges[j], st);
  };
  each(kOnePiece, [](const Point* e, const auto& s) { add_one_piece(e, s); });
  each(kR, [](const Point* e, const auto& s) { add_r(e, s); });
  each(kC, [](const Point* e, const auto& s) { add_c(e, s); });
  each(kRR, [](const Point* e, const auto& s) { add_rr(e, s); });
  each(kCC, [](const Point* e, const auto& s) { add_cc(e, s); });
  each(kRC, [](const Point* e, const auto& s) { add_rc(e, s); });
  each(kOther, [](const Point* e, const auto& s) { add_edge(e, s); });
}

// Strip row r as spans of one level, left to right, covering the row: emit(level, n), n >= 0.
// A running sum of the covers left of each column gives the pixels between touched ones (full
// or empty, exactly, unless an edge passes them without height), and each touched pixel adds
// its area. Touched pixels are visited without a branch on their kind: a span, maybe empty, of
// the pixels before one (levels of the cover alone, which levels() maps to 0 or 255 when the
// cover is 0 or a whole winding) and the pixel itself. Leaves the row's sums and bits zero.
template <class Strip, class Emit>
void sweep_row(const Strip& st, int32_t r, const CoverageLevels& levels, Emit&& emit) {
  PixelSums* const sums = st.sums + size_t(r - st.r0) * size_t(st.stride);
  const size_t w0 = size_t(r - st.r0) * size_t(st.stride / 64), w1 = w0 + size_t(st.stride / 64);
  // Column -1, everything left of the display, only carries its cover into the row (its sums
  // are zero when untouched).
  int64_t carry = std::exchange(sums[0], PixelSums{0, 0}).cover;  // in units of kOne
  st.touched[w0] &= ~uint64_t(1);
  int at = 0;  // columns before it are emitted
  // The touched pixels of word `word` of the row, bits, left to right. (Inlined by force: called
  // from two loops, GCC 12 otherwise keeps carry and at in memory.)
  auto visit = [&](size_t word, uint64_t bits) __attribute__((always_inline)) {
    while (bits) {
      const int64_t j = int64_t(word - w0) * 64 + __builtin_ctzll(bits);
      bits &= bits - 1;
      const PixelSums here = std::exchange(sums[j], PixelSums{0, 0});
      const int col = int(j) - 1;
      emit(levels(carry * (2 * kOne)), size_t(col - at));
      emit(levels(carry * (2 * kOne) + here.area), size_t(1));
      at = col + 1;
      carry += here.cover;
    }
  };
  if constexpr (!Strip::summary) {
    for (size_t word = w0; word < w1; ++word) {
      const uint64_t bits = st.touched[word];
      if (!bits) continue;
      st.touched[word] = 0;
      visit(word, bits);
    }
  } else {
    // The row's words are w0 .. w1 - 1; those in the same summary word as a neighbouring row's
    // keep that row's bits.
    for (size_t sw = w0 >> 6; sw <= (w1 - 1) >> 6; ++sw) {
      const uint64_t from = sw << 6 < w0 ? ~uint64_t(0) << (w0 & 63) : ~uint64_t(0);
      const uint64_t to = (sw + 1) << 6 > w1 ? ~uint64_t(0) >> (64 - (w1 & 63)) : ~uint64_t(0);
      uint64_t words = st.touched_words[sw] & from & to;
      st.touched_words[sw] &= ~words;
      while (words) {
        const size_t word = (sw << 6) + size_t(__builtin_ctzll(words));
        words &= words - 1;
        visit(word, std::exchange(st.touched[word], 0));
      }
    }
  }
  emit(levels(carry * (2 * kOne)), size_t(st.W - at));
}

// The pixels a sink gets, row by row, top to bottom: row(fill), fill calling pixels(level, n)
// for the row left to right, or empty_rows(n) for n rows of black (PngRows): a strip without
// edges is black (nothing covers it, nothing left of it carries a cover into it), and most of a
// large display's strips are. The sink's rows are the image's, flips applied
// (mask_image_layout): the rows of the unflipped image in reverse when rows ascend, each row's
// spans in reverse when columns descend.
template <class Sink>
size_t rasterize_coverage(const LayerView& layer, const PrinterProfile& p, Sink& sink) {
  thread_local Scratch scratch;
  Scratch& w = scratch;
  const MaskImageLayout image = mask_image_layout(p);
  const int W = image.width, H = image.height;
  const int32_t stride = (W + 64) / 64 * 64;
  const int shift = strip_shift(stride), rows = 1 << shift;
  const size_t strips = size_t((H + rows - 1) >> shift);
  w.levels.set(p.gamma, p.grey_levels);
  const size_t open = add_edges(layer, pixel_map(image, false), W, H, shift, strips, w);
  // The sweep leaves every sum and bit zero again, so they are cleared only when their size
  // changes or a former call stopped half-way (an exception).
  const size_t pixels = size_t(rows) * size_t(stride);
  const size_t summary_words = stride / 64 > kScannedWords ? (pixels / 64 + 63) / 64 : 0;
  if (!w.clear || w.sums.size() != pixels || w.touched_words.size() != summary_words) {
    w.sums.assign(pixels, PixelSums{0, 0});
    w.touched.assign(pixels / 64, 0);
    w.touched_words.assign(summary_words, 0);
  }
  w.clear = false;
  auto sweep_strips = [&](auto summary) {
    for (size_t n = 0; n < strips; ++n) {
      const size_t i = image.rows_ascend ? strips - 1 - n : n;
      const int32_t r0 = int32_t(i) * rows;
      const Strip<decltype(summary)::value> st{
          r0, std::min(r0 + rows, H), W, stride, w.sums.data(), w.touched.data(), w.touched_words.data()};
      if (w.begin[i * kKinds] == w.begin[(i + 1) * kKinds]) {
        sink.empty_rows(size_t(st.r1 - st.r0));
        continue;
      }
      add_strip_edges(w, i, st);
      for (int32_t m = 0; m < st.r1 - st.r0; ++m) {
        const int32_t r = image.rows_ascend ? st.r1 - 1 - m : st.r0 + m;
        if (!image.columns_descend) {
          sink.row([&](auto&& pixels) { sweep_row(st, r, w.levels, pixels); });
          continue;
        }
        w.spans.clear();
        sweep_row(st, r, w.levels, [&](uint8_t level, size_t count) { w.spans.push_back({level, count}); });
        sink.row([&](auto&& pixels) {
          for (size_t q = w.spans.size(); q-- > 0;) pixels(w.spans[q].first, w.spans[q].second);
        });
      }
    }
  };
  if (summary_words > 0)
    sweep_strips(std::true_type());
  else
    sweep_strips(std::false_type());
  w.clear = true;
  return open;
}

// Runs of non-zero pixels, adjacent ones of one level joined. The arrays are kept at least a row
// of runs (W) longer than those written, which are counted apart, so that a span is written with
// no check of the room left; finish() cuts them to the runs written.
class RunsSink {
 public:
  RunsSink(int W, int H, MaskRuns& out) : out_(out) {
    out.width = W;
    out.height = H;
    out.row_begin.assign(1, 0);
    out.row_begin.reserve(size_t(H) + 1);
  }
  // The next row: fill(pixels) calls pixels(level, n), n >= 0, left to right (as PngRows).
  template <class Fill>
  void row(Fill&& fill) {
    const size_t room = written_ + size_t(out_.width);
    if (out_.levels.size() < room) {
      out_.levels.resize(std::max(room, 2 * out_.levels.size()));
      out_.columns.resize(2 * out_.levels.size());
    }
    uint16_t* const columns = out_.columns.data();
    uint8_t* const levels = out_.levels.data();
    const size_t first = written_;
    size_t n_runs = written_;
    int at = 0;  // the row's next column
    fill([&](uint8_t level, size_t n) {
      const int end = at + int(n);
      if (n > 0 && level != 0) {
        if (n_runs > first && columns[2 * n_runs - 1] == at && levels[n_runs - 1] == level) {
          columns[2 * n_runs - 1] = uint16_t(end);
        } else {
          columns[2 * n_runs] = uint16_t(at);
          columns[2 * n_runs + 1] = uint16_t(end);
          levels[n_runs++] = level;
        }
      }
      at = end;
    });
    written_ = n_runs;
    out_.row_begin.push_back(uint32_t(written_));
  }
  void empty_rows(size_t n) { out_.row_begin.insert(out_.row_begin.end(), n, uint32_t(written_)); }
  void finish() {
    out_.levels.resize(written_);
    out_.columns.resize(2 * written_);
  }

 private:
  MaskRuns& out_;
  size_t written_ = 0;
};

// The PNG and the runs from one sweep: each span goes to both.
class PngAndRunsSink {
 public:
  PngAndRunsSink(PngRows& png, RunsSink& runs) : png_(png), runs_(runs) {}
  template <class Fill>
  void row(Fill&& fill) {
    png_.row([&](auto&& png_pixels) {
      runs_.row([&](auto&& run_pixels) {
        fill([&](uint8_t level, size_t n) {
          png_pixels(level, n);
          run_pixels(level, n);
        });
      });
    });
  }
  void empty_rows(size_t n) {
    png_.empty_rows(n);
    runs_.empty_rows(n);
  }

 private:
  PngRows& png_;
  RunsSink& runs_;
};

}  // namespace

size_t coverage_runs(const LayerView& layer, const PrinterProfile& p, MaskRuns& out) {
  const MaskImageLayout image = mask_image_layout(p);
  RunsSink sink(image.width, image.height, out);
  const size_t open = rasterize_coverage(layer, p, sink);
  sink.finish();
  return open;
}

size_t coverage_png(const LayerView& layer, const PrinterProfile& p, std::vector<uint8_t>& png, MaskRuns* runs) {
  const MaskImageLayout image = mask_image_layout(p);
  PngRows sink(image.width, image.height, png);
  size_t open;
  if (runs) {
    RunsSink runs_sink(image.width, image.height, *runs);
    PngAndRunsSink both(sink, runs_sink);
    open = rasterize_coverage(layer, p, both);
    runs_sink.finish();
  } else {
    open = rasterize_coverage(layer, p, sink);
  }
  sink.finish();
  return open;
}

}  // namespace slicereuse
