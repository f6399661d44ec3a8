#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "coverage_runs.h"
#include "pixel_map.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/raster/rasterize_layer.h"
#include "slicereuse/util/error.h"

namespace slicereuse {
namespace {

// Binary masks sample each pixel at its centre: sample i of a row or column is at i + 1/2.
// An edge in pixel units, stored from its lower endpoint (smaller row coordinate) so both
// directions of the same segment give bit-identical crossings.
struct Edge {
  double ya, xa, dy, dx;   // lower endpoint, and upper endpoint minus lower
  int first_row, end_row;  // sample rows r with ya <= r + 1/2 < ya + dy
  int dir;                 // +1 when the contour runs towards larger rows, -1 otherwise
};

struct Scratch {
  std::vector<double> v;  // a contour's points' row coordinates
  std::vector<int> row;   // and first sample rows
  std::vector<Edge> edges;
  std::vector<uint32_t> row_begin;  // per sample row, where its crossings start
  std::vector<uint32_t> crossings;  // per row: 2 * first sample at or after the crossing + (dir > 0)
};

// NaN maps to lo, so a broken coordinate can never produce an out-of-range index.
double clamp(double x, double lo, double hi) { return !(x >= lo) ? lo : (x > hi ? hi : x); }

// Index of the first sample whose centre (i + 1/2) is at or after x, within [0, n].
// (Clamped to [0, n] after rounding: ceil of the clamped value alone could give -1 or n + 1,
// one pixel outside the row, for a part that leaves the display.)
// The ceiling by truncation and one comparison: std::ceil is a library call on baseline x86-64
// (no SSE4.1 round), and this runs for every contour point and every crossing.
int first_sample_at_or_after(double x, int n) {
  const double t = clamp(x - 0.5, -1.0, double(n) + 1.0);
  const int truncated = int(t);
  return std::clamp(truncated + int(double(truncated) < t), 0, n);
}

// Builds the oriented edges of the closed contours of layer k in pixel coordinates
// (pixel_map.h, flips applied). Rows first: most edges of a fine contour cross no sample row
// centre, and those are skipped by comparing their ends' first rows, computed once per point.
// Which edges do cross follows no pattern a branch predictor could learn (a test per point
// mispredicts about every other point), so the comparisons are gathered 64 at a time into a
// bit mask whose set bits are then visited. Edges come in contour order, the closing edge last.
size_t build_edges(const LayerView& layer, const PrinterProfile& p, Scratch& w) {
  // A local copy: the compiler cannot tell that the writes to w leave the layer and p alone.
  const MaskImageLayout image = mask_image_layout(p);
  const PixelMap map = pixel_map(image, true);
  const int rows = image.height;
  w.edges.clear();
  return for_each_closed_contour(layer, [&](const double* xyz, uint64_t n) {
    // Point n repeats point 0, so the closing edge needs no wrap-around.
    w.v.resize(n + 1);
    w.row.resize(n + 1);
    double* const v = w.v.data();
    int* const row = w.row.data();
    for (uint64_t i = 0; i < n; ++i) {
      v[i] = map.v(xyz + 3 * i);
      row[i] = first_sample_at_or_after(v[i], rows);
    }
    v[n] = v[0];
    row[n] = row[0];
    auto u = [&](uint64_t i) { return map.u(xyz + 3 * (i == n ? 0 : i)); };
    for (uint64_t base = 0; base < n; base += 64) {
      const uint64_t m = std::min<uint64_t>(64, n - base);
      uint64_t crossing = 0;
      for (uint64_t j = 0; j < m; ++j) crossing |= uint64_t(row[base + j] != row[base + j + 1]) << j;
      for (; crossing; crossing &= crossing - 1) {
        const uint64_t i = base + uint64_t(__builtin_ctzll(crossing));
        double y0 = v[i], x0 = u(i), y1 = v[i + 1], x1 = u(i + 1);
        int r0 = row[i], r1 = row[i + 1], dir = 1;
        if (y1 < y0) {
          std::swap(y0, y1);
          std::swap(x0, x1);
          std::swap(r0, r1);
          dir = -1;
        }
        // Horizontal edges cross no sample row; non-finite ones (only possible when the caller
        // skipped validate_slices) are dropped rather than swept.
        if (!(y0 < y1) || !std::isfinite(y1 - y0) || !std::isfinite(x1 - x0)) continue;
        if (r0 >= r1) continue;
        w.edges.push_back({y0, x0, y1 - y0, x1 - x0, r0, r1, dir});
      }
    }
  });
}

// Puts a and b in order without a branch (min and max compile to conditional moves).
void order(uint32_t& a, uint32_t& b) {
  const uint32_t lo = std::min(a, b), hi = std::max(a, b);
  a = lo;
  b = hi;
}

// Sorts a row's few crossings: most rows of a mask have 2 to 4, sorted by sorting networks,
// whose comparisons cannot be mispredicted as an insertion sort's are; more by insertion sort,
// which beats std::sort on a handful.
void sort_row(uint32_t* c, size_t n) {
  switch (n) {
    case 2:
      order(c[0], c[1]);
      return;
    case 3:
      order(c[0], c[1]);
      order(c[1], c[2]);
      order(c[0], c[1]);
      return;
    case 4:
      order(c[0], c[1]);
      order(c[2], c[3]);
      order(c[0], c[2]);
      order(c[1], c[3]);
      order(c[1], c[2]);
      return;
  }
  if (n > 32) {
    std::sort(c, c + n);
    return;
  }
  for (size_t i = 1; i < n; ++i) {
    const uint32_t x = c[i];
    size_t j = i;
    for (; j > 0 && x < c[j - 1]; --j) c[j] = c[j - 1];
    c[j] = x;
  }
}

// Visits sample rows top to bottom; for every run of samples whose centres have nonzero winding
// calls span(row, first, end). The crossings of every edge with the row centres it spans are
// bucketed by row (a counting sort: most edges of a fine contour cross one row, so an active edge
// list would cost more than the crossings themselves), then sorted along each row. A crossing at
// x counts for the samples whose centre is at or right of x, so a centre exactly on an edge is
// decided the same way whatever the order of edges.
// A crossing is kept as that first sample (and its direction) rather than as x, which gives the
// same spans: the lit samples depend on nothing else, x -> first sample is monotone, so sorting
// by first sample keeps the order sorting by x gives, and crossings with equal first samples,
// in whatever order, only have empty spans between them. Each crossing's first sample is then
// computed once, not once per span end.
template <class Span>
void sweep(Scratch& w, int rows, int cols, Span&& span) {
  // Per row, the edges starting there minus those ending there (mod 2^32); summed up, the
  // number of crossings of each row, and where they begin.
  std::vector<uint32_t>& begin = w.row_begin;
  begin.assign(size_t(rows) + 1, 0);
  for (const Edge& e : w.edges) {
    ++begin[size_t(e.first_row)];
    --begin[size_t(e.end_row)];
  }
  uint32_t total = 0, active = 0;
  for (size_t r = 0; r <= size_t(rows); ++r) {
    active += begin[r];
    begin[r] = total;
    total += active;
  }
  w.crossings.resize(total);
  uint32_t* const crossings = w.crossings.data();
  for (const Edge& e : w.edges) {
    const uint32_t up = e.dir > 0;
    for (int r = e.first_row; r < e.end_row; ++r) {
      const double yc = r + 0.5;
      const int first = first_sample_at_or_after(e.xa + (yc - e.ya) * e.dx / e.dy, cols);
      crossings[begin[size_t(r)]++] = uint32_t(first) << 1 | up;
    }
  }
  // The fill moved each row's begin to the next row's.
  for (int r = 0; r < rows; ++r) {
    const uint32_t from = r == 0 ? 0 : begin[size_t(r) - 1];
    uint32_t* const c = crossings + from;
    const size_t n = begin[size_t(r)] - from;
    if (n < 2) continue;
    sort_row(c, n);
    int winding = 0;
    for (size_t i = 0; i + 1 < n; ++i) {
      winding += c[i] & 1 ? 1 : -1;
      if (winding == 0) continue;
      const int a = int(c[i] >> 1), b = int(c[i + 1] >> 1);
      if (a < b) span(r, a, b);
    }
  }
}

void check_layer(const LayerView& layer, const PrinterProfile& profile) {
  validate_printer_profile(profile);
  for (const LayerPart& part : layer) {
    if (part.layer >= part.slices->layers())
      throw Error("layer " + std::to_string(part.layer) + " does not exist (" +
                  std::to_string(part.slices->layers()) + " layers)");
    if (!part.slices->has_points()) throw Error("the slices carry no contour points to rasterize");
  }
}

void check_antialiased_layer(const LayerView& layer, const PrinterProfile& profile) {
  check_layer(layer, profile);
  if (!profile.antialiasing) throw Error("an anti-aliased mask was asked for, but antialiasing is off");
}

// Anti-aliasing with gamma 0 is PrusaSlicer's threshold: the binary mask.
bool is_binary(const PrinterProfile& p) { return !p.antialiasing || p.gamma == 0; }

// The binary mask as runs (the layer checked).
size_t binary_runs(const LayerView& layer, const PrinterProfile& profile, MaskRuns& out) {
  thread_local Scratch w;
  const MaskImageLayout image = mask_image_layout(profile);
  const int H = image.height;
  out.width = image.width;
  out.height = H;
  out.row_begin.assign(size_t(H) + 1, 0);
  out.columns.clear();
  out.levels.clear();
  const size_t open = build_edges(layer, profile, w);
  // Rows come in order and runs left to right (see sweep): count per row, then sum up.
  sweep(w, H, image.width, [&](int r, int a, int b) {
    ++out.row_begin[size_t(r) + 1];
    out.columns.push_back(uint16_t(a));
    out.columns.push_back(uint16_t(b));
    out.levels.push_back(255);
  });
  for (int r = 0; r < H; ++r) out.row_begin[size_t(r) + 1] += out.row_begin[size_t(r)];
  return open;
}

}  // namespace

size_t rasterize_layer_runs(const LayerView& layer, const PrinterProfile& profile, MaskRuns& out) {
  check_layer(layer, profile);
  if (profile.antialiasing) throw Error("anti-aliased masks have grey levels and cannot be given as runs");
  return binary_runs(layer, profile, out);
}

size_t rasterize_layer_antialiased_runs(const LayerView& layer, const PrinterProfile& profile, MaskRuns& out) {
  check_antialiased_layer(layer, profile);
  return is_binary(profile) ? binary_runs(layer, profile, out) : coverage_runs(layer, profile, out);
}

size_t rasterize_layer_antialiased_png(const LayerView& layer, const PrinterProfile& profile,
                                       std::vector<uint8_t>& out, MaskRuns* runs) {
  check_antialiased_layer(layer, profile);
  if (!is_binary(profile)) return coverage_png(layer, profile, out, runs);
  thread_local MaskRuns own;
  MaskRuns& binary = runs ? *runs : own;
  const size_t open = binary_runs(layer, profile, binary);
  encode_mask_png(binary, out);
  return open;
}

size_t rasterize_layer(const LayerView& layer, const PrinterProfile& profile, uint8_t* out) {
  check_layer(layer, profile);
  const MaskImageLayout image = mask_image_layout(profile);
  const int W = image.width, H = image.height;
  std::memset(out, 0, size_t(W) * size_t(H));
  if (is_binary(profile)) {
    thread_local Scratch w;
    const size_t open = build_edges(layer, profile, w);
    sweep(w, H, W, [&](int r, int a, int b) { std::memset(out + size_t(r) * W + a, 255, b - a); });
    return open;
  }
  thread_local MaskRuns runs;
  const size_t open = coverage_runs(layer, profile, runs);
  draw_mask_runs(runs, out);
  return open;
}

}  // namespace slicereuse
