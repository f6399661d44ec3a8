#include "coverage_runs.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "pixel_map.h"

namespace slicereuse {
namespace {

// Positions inside a pixel in units of 1/kOne of its side; areas in units of 1/kFull of a
// pixel (the trapezoid rule's halving is left out, so every sum stays an integer).
constexpr int kFractionBits = 16;
constexpr int32_t kOne = int32_t(1) << kFractionBits;
constexpr int64_t kFull = int64_t(2) * kOne * kOne;

// A point of a contour in pixel coordinates, and the pixel it lies in: row in [-1, H] and
// column in [-1, W], clamped (-1 and H or W stand for everything beyond the display), with its
// fixed-point position inside that pixel. Both edges at a point use these same numbers, which
// makes the heights of the pieces along a contour add up exactly.
struct Point {
  double u, v;
  int32_t row, col;
  int32_t fy, fx;  // 0..kOne
};

// What the pieces of edges in one pixel add to it: area, the sum of dv * (2 kOne - x_in -
// x_out) over the pieces (height times the part of the pixel right of the piece, doubled), and
// cover, the sum of their heights dv, which every pixel further right in the row gets in full.
// key = row << 16 | (column + 1), column -1 collecting what lies left of the display.
struct Cell {
  int64_t area;
  int32_t cover;
  uint32_t key;
};

// floor(x) of x in [-1, n], clamped there first. By truncation and one comparison: std::floor
// is a library call on baseline x86-64, and this runs twice per contour point.
int32_t floor_within(double x, int n) {
  const double t = clamp_coordinate(x, -1.0, double(n));
  const int32_t truncated = int32_t(t);
  return truncated - int32_t(double(truncated) > t);
}

// t in [0, 1] as 0..kOne, rounded (t just outside, from rounding, is clamped).
int32_t fraction(double t) { return int32_t(clamp_coordinate(t, 0.0, 1.0) * kOne + 0.5); }

Point pixel_point(const PixelMap& m, double x, double y, int W, int H) {
  Point p;
  p.u = m.u(x);
  p.v = m.v(y);
  p.row = floor_within(p.v, H);
  p.col = floor_within(p.u, W);
  p.fy = fraction(p.v - p.row);
  p.fx = fraction(p.u - p.col);
  return p;
}

// A piece of height dv (signed: positive when the contour runs downwards) in pixel (row, col),
// entering and leaving at x_in and x_out, x_sum = x_in + x_out. Consecutive pieces in the same
// pixel (a fine contour has several edges per pixel) are summed into one cell.
void add_piece(std::vector<Cell>& cells, int32_t row, int32_t col, int32_t dv, int32_t x_sum) {
  if (dv == 0) return;
  const uint32_t key = uint32_t(row) << 16 | uint32_t(col + 1);
  const int64_t area = int64_t(dv) * (2 * kOne - x_sum);
  if (!cells.empty() && cells.back().key == key) {
    cells.back().area += area;
    cells.back().cover += dv;
  } else {
    cells.push_back({area, dv, key});
  }
}

// Where edge (a, b) crosses row boundary y: the row below it (v = y is its top), column and
// position in it.
Point at_row_boundary(const Point& a, double du_dv, int32_t y, int W) {
  Point p;
  p.u = a.u + (y - a.v) * du_dv;
  p.v = y;
  p.row = y;
  p.col = floor_within(p.u, W);
  p.fy = 0;
  p.fx = fraction(p.u - p.col);
  return p;
}

// The pieces inside row r of edge (a, b), a its lower endpoint, from in to out (in that row or on
// its top and bottom, in.fy <= out.fy). Column crossings are computed from a.
void add_row_pieces(const Point& in, const Point& out, const Point& a, const Point& b, int32_t r, int32_t sign,
                    int W, std::vector<Cell>& cells) {
  if (in.fy == out.fy) return;  // no height in this row
  if (in.col == out.col) {
    if (in.col < W) add_piece(cells, r, in.col, sign * (out.fy - in.fy), in.fx + out.fx);
    return;
  }
  // Heights where the edge crosses column boundary x: monotone in x (rounding is), and kept
  // within the row's piece.
  const double dv_du = (b.v - a.v) / (b.u - a.u);
  auto height_at = [&](int32_t x) { return std::clamp(fraction((a.v - r) + (x - a.u) * dv_du), in.fy, out.fy); };
  int32_t c = in.col, fy = in.fy, fx = in.fx;
  if (in.col < out.col) {  // rightwards: each pixel left through its right side
    for (; c < out.col && c < W; ++c) {
      const int32_t next = height_at(c + 1);
      add_piece(cells, r, c, sign * (next - fy), fx + kOne);
      fy = next;
      fx = 0;
    }
    if (c < W) add_piece(cells, r, c, sign * (out.fy - fy), fx + out.fx);
  } else {  // leftwards, from column W at most: what lies beyond the display is skipped
    for (; c > out.col; --c) {
      const int32_t next = height_at(c);
      if (c < W) add_piece(cells, r, c, sign * (next - fy), fx);
      fy = next;
      fx = kOne;
    }
    add_piece(cells, r, c, sign * (out.fy - fy), fx + out.fx);
  }
}

// An edge that crosses at most one row boundary and one column boundary, inside the display
// (nearly every edge of a fine contour that leaves its pixel): its two or three pieces, without
// add_edge's loops. a is the lower endpoint, b is in a's row or the next, and in a's column or
// a neighbouring one.
void add_short_edge(const Point& a, const Point& b, int32_t sign, std::vector<Cell>& cells) {
  const int32_t x = std::max(a.col, b.col);       // the column boundary, if crossed
  const int32_t side = b.col > a.col ? kOne : 0;  // where the edge leaves a's column
  if (a.row == b.row) {
    const double dv_du = (b.v - a.v) / (b.u - a.u);
    const int32_t t = std::clamp(fraction((a.v - a.row) + (x - a.u) * dv_du), a.fy, b.fy);
    add_piece(cells, a.row, a.col, sign * (t - a.fy), a.fx + side);
    add_piece(cells, a.row, b.col, sign * (b.fy - t), kOne - side + b.fx);
    return;
  }
  const double u_y = a.u + (b.row - a.v) * ((b.u - a.u) / (b.v - a.v));  // where it enters b's row
  if (a.col == b.col) {
    const int32_t fx = fraction(u_y - a.col);
    add_piece(cells, a.row, a.col, sign * (kOne - a.fy), a.fx + fx);
    add_piece(cells, b.row, b.col, sign * b.fy, fx + b.fx);
    return;
  }
  const double dv_du = (b.v - a.v) / (b.u - a.u);
  if (side ? u_y < x : u_y > x) {  // the row boundary first, through pixel (b.row, a.col)
    const int32_t fx = fraction(u_y - a.col);
    const int32_t t = std::clamp(fraction((a.v - b.row) + (x - a.u) * dv_du), 0, b.fy);
    add_piece(cells, a.row, a.col, sign * (kOne - a.fy), a.fx + fx);
    add_piece(cells, b.row, a.col, sign * t, fx + side);
    add_piece(cells, b.row, b.col, sign * (b.fy - t), kOne - side + b.fx);
  } else {  // the column boundary first, through pixel (a.row, b.col)
    const int32_t t = std::clamp(fraction((a.v - a.row) + (x - a.u) * dv_du), a.fy, kOne);
    const int32_t fx = fraction(u_y - b.col);
    add_piece(cells, a.row, a.col, sign * (t - a.fy), a.fx + side);
    add_piece(cells, a.row, b.col, sign * (kOne - t), kOne - side + fx);
    add_piece(cells, b.row, b.col, sign * b.fy, fx + b.fx);
  }
}

// The pieces of an edge that leaves its first point's pixel, contour order a -> b. Every
// crossing with a row or column boundary is computed from the lower endpoint (smaller v), so an
// edge and its reverse give the same pieces.
void add_edge(Point a, Point b, int W, int H, std::vector<Cell>& cells) {
  int32_t sign = 1;
  if (b.v < a.v) {
    std::swap(a, b);
    sign = -1;
  }
  // Horizontal edges have no height and cover nothing; non-finite ones (only possible when the
  // caller skipped validate_slices) are dropped.
  if (!(a.v < b.v) || !std::isfinite(b.v - a.v) || !std::isfinite(b.u - a.u)) return;
  if (b.row - a.row <= 1 && a.row >= 0 && b.row < H && std::abs(b.col - a.col) <= 1 && std::min(a.col, b.col) >= 0 &&
      std::max(a.col, b.col) < W) {
    add_short_edge(a, b, sign, cells);
    return;
  }
  if (a.row == b.row) {
    if (a.row >= 0 && a.row < H) add_row_pieces(a, b, a, b, a.row, sign, W, cells);
    return;
  }
  // Row by row: where the edge leaves a row is where it enters the next.
  const double du_dv = (b.u - a.u) / (b.v - a.v);
  int32_t r = a.row;
  Point in = a;
  if (r < 0) {
    r = 0;
    in = at_row_boundary(a, du_dv, 0, W);
  }
  for (const int32_t last = std::min(b.row, H - 1); r <= last; ++r) {
    Point out = b;
    if (r != b.row) {
      out = at_row_boundary(a, du_dv, r + 1, W);
      out.fy = kOne;
    }
    add_row_pieces(in, out, a, b, r, sign, W, cells);
    in = out;
    in.fy = 0;
  }
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
    // One step without a branch covers every coarse step for gamma 1 (and most for any gamma);
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

struct Scratch {
  std::vector<Point> points;
  std::vector<Cell> cells, by_row;
  std::vector<uint32_t> row_begin;
  // One row's sums per column + 1 (0: left of the display), and which columns have any.
  std::vector<int64_t> area, cover;
  std::vector<uint64_t> touched;
  CoverageLevels levels;
};

// Layer k's cells, in contour order. Returns the number of open contours.
size_t add_cells(const Slices& s, size_t k, const PixelMap& map, int W, int H, Scratch& w) {
  w.cells.clear();
  size_t open = 0;
  for (uint64_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c) {
    if (s.contour_open[c]) {
      ++open;
      continue;
    }
    const uint64_t b = s.contour_begin[c], n = s.contour_begin[c + 1] - b;
    if (n == 0) continue;
    const double* const xyz = s.xyz.data() + 3 * b;
    // Point n repeats point 0, so the closing edge needs no wrap-around.
    w.points.resize(n + 1);
    Point* const pts = w.points.data();
    for (uint64_t i = 0; i < n; ++i) pts[i] = pixel_point(map, xyz[3 * i], xyz[3 * i + 1], W, H);
    pts[n] = pts[0];
    for (uint64_t i = 0; i < n; ++i) {
      const Point &a = pts[i], &b = pts[i + 1];
      if (a.row != b.row || a.col != b.col) {
        add_edge(a, b, W, H, w.cells);
      } else if (a.row >= 0 && a.row < H && a.col < W) {  // most edges of a fine contour: one piece
        add_piece(w.cells, a.row, a.col, b.fy - a.fy, a.fx + b.fx);
      }
    }
  }
  return open;
}

// Appends the runs of one row's cells [first, end) to out: a running sum of the covers left of
// each column gives the pixels between cells (full or empty, exactly, unless an edge passes
// them without height), and each cell's own pixel adds its area. Adjacent runs of one level
// are joined.
void sweep_row(const Cell* first, const Cell* end, int W, Scratch& w, MaskRuns& out) {
  int64_t* const area = w.area.data();
  int64_t* const cover = w.cover.data();
  uint64_t* const touched = w.touched.data();
  const CoverageLevels& levels = w.levels;
  uint32_t lo = UINT32_MAX, hi = 0;
  for (const Cell* c = first; c < end; ++c) {
    const uint32_t j = c->key & 0xffff;
    area[j] += c->area;
    cover[j] += c->cover;
    touched[j >> 6] |= uint64_t(1) << (j & 63);
    lo = std::min(lo, j);
    hi = std::max(hi, j);
  }
  int last_end = -1, last_level = 0;  // the row's last run
  auto run = [&](int a, int b, int level) {
    if (a == last_end && level == last_level) {
      out.columns.back() = uint16_t(b);
    } else {
      out.columns.push_back(uint16_t(a));
      out.columns.push_back(uint16_t(b));
      out.levels.push_back(uint8_t(level));
      last_level = level;
    }
    last_end = b;
  };
  // Between cells: nothing, full (a whole number of windings), or rarely anything else.
  auto between = [&](int a, int b, int64_t carry) {
    if (a < b && carry != 0) run(a, b, carry >= kOne || carry <= -kOne ? 255 : levels(carry * (2 * kOne)));
  };
  int64_t carry = 0;  // covers left of the next column, in units of kOne
  int at = 0;         // columns before it have their runs
  for (uint32_t word = lo >> 6; word <= hi >> 6; ++word) {
    for (uint64_t bits = std::exchange(touched[word], 0); bits; bits &= bits - 1) {
      const uint32_t j = word * 64 + uint32_t(__builtin_ctzll(bits));
      if (j > 0) {
        const int col = int(j) - 1;
        between(at, col, carry);
        const int level = levels(carry * (2 * kOne) + area[j]);
        if (level != 0) run(col, col + 1, level);
        at = col + 1;
      }
      carry += cover[j];
      area[j] = 0;
      cover[j] = 0;
    }
  }
  between(at, W, carry);
}

// Mirrors the runs out holds from run `first` on (one row) left to right.
void mirror_runs(size_t first, int W, MaskRuns& out) {
  std::reverse(out.columns.begin() + std::ptrdiff_t(2 * first), out.columns.end());
  for (size_t i = 2 * first; i < out.columns.size(); ++i) out.columns[i] = uint16_t(W - out.columns[i]);
  std::reverse(out.levels.begin() + std::ptrdiff_t(first), out.levels.end());
}

}  // namespace

size_t coverage_runs(const Slices& s, size_t k, const PrinterProfile& p, MaskRuns& out) {
  thread_local Scratch scratch;
  Scratch& w = scratch;
  const int W = p.width_px, H = p.height_px;
  w.levels.set_gamma(p.gamma);
  const size_t open = add_cells(s, k, pixel_map(p, false), W, H, w);

  // Cells by row: counted, then placed (a counting sort); afterwards row_begin[r] is where
  // row r + 1 begins.
  std::vector<uint32_t>& begin = w.row_begin;
  begin.assign(size_t(H) + 1, 0);
  for (const Cell& c : w.cells) ++begin[(c.key >> 16) + 1];
  for (size_t r = 1; r <= size_t(H); ++r) begin[r] += begin[r - 1];
  w.by_row.resize(w.cells.size());
  for (const Cell& c : w.cells) w.by_row[begin[c.key >> 16]++] = c;

  w.area.assign(size_t(W) + 1, 0);
  w.cover.assign(size_t(W) + 1, 0);
  w.touched.assign(size_t(W) / 64 + 1, 0);
  out.width = W;
  out.height = H;
  out.row_begin.assign(size_t(H) + 1, 0);
  out.columns.clear();
  out.levels.clear();
  for (int o = 0; o < H; ++o) {
    const int r = p.mirror_y ? H - 1 - o : o;
    const Cell* const cells = w.by_row.data();
    const uint32_t first = r == 0 ? 0 : begin[size_t(r) - 1], end = begin[size_t(r)];
    if (first < end) {
      const size_t row_first = out.levels.size();
      sweep_row(cells + first, cells + end, W, w, out);
      if (p.mirror_x) mirror_runs(row_first, W, out);
    }
    out.row_begin[size_t(o) + 1] = uint32_t(out.levels.size());
  }
  return open;
}

}  // namespace slicereuse
