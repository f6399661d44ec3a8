#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "slicereuse/error.h"
#include "slicereuse/masks.h"
#include "slicereuse/printer_profile.h"

namespace slicereuse {
namespace {

// Anti-aliased masks sample every pixel on a SUPERSAMPLE x SUPERSAMPLE grid of sample centres
// with the same nonzero rule as binary masks (64 samples -> 65 grey levels).
constexpr int SUPERSAMPLE = 8;

// An edge in sample units, stored from its lower endpoint (smaller row coordinate) so both
// directions of the same segment give bit-identical crossings.
struct Edge {
  double ya, xa, yb, xb;
  int first_row, end_row;  // sample rows r with ya <= r + 1/2 < yb
  int dir;                 // +1 when the contour runs towards larger rows, -1 otherwise
};

struct Crossing {
  double x;
  int dir;
  bool operator<(const Crossing& o) const { return x < o.x; }
};

struct Scratch {
  std::vector<double> v;
  std::vector<int> row;
  std::vector<Edge> edges;
  std::vector<uint32_t> row_count, order, active;
  std::vector<Crossing> crossings;
  std::vector<uint16_t> coverage;
};

// NaN maps to lo, so a broken coordinate can never produce an out-of-range index.
double clamp(double x, double lo, double hi) { return !(x >= lo) ? lo : (x > hi ? hi : x); }

// Index of the first sample whose centre (i + 1/2) is at or after x, within [0, n].
// (Clamped to [0, n] after rounding: ceil of the clamped value alone could give -1 or n + 1,
// one pixel outside the row, for a part that leaves the display.)
int first_sample_at_or_after(double x, int n) {
  return std::clamp(int(std::ceil(clamp(x - 0.5, -1.0, double(n) + 1.0))), 0, n);
}

// Builds the oriented edges of the closed contours of layer k in sample coordinates
// (columns u to the right, rows v downwards, scale samples per pixel).
size_t build_edges(const Slices& s, size_t k, const PrinterProfile& p, int scale, Scratch& w,
                   int rows) {
  const double sx = scale * 1000.0 / p.pixel_size_x_um, sy = scale * 1000.0 / p.pixel_size_y_um;
  const double cu = 0.5 * scale * p.width_px, cv = 0.5 * scale * p.height_px;
  const double su = p.mirror_x ? -sx : sx, sv = p.mirror_y ? sy : -sy;
  w.edges.clear();
  size_t open = 0;
  for (uint64_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c) {
    if (s.contour_open[c]) {
      ++open;
      continue;
    }
    const uint64_t b = s.contour_begin[c], n = s.contour_begin[c + 1] - b;
    // Rows first: most edges of a fine contour cross no sample row centre, and those are
    // skipped by comparing their ends' first rows, computed once per point.
    w.v.resize(n);
    w.row.resize(n);
    for (uint64_t i = 0; i < n; ++i) {
      w.v[i] = cv + sv * (s.xyz[3 * (b + i) + 1] + p.offset_y_mm);
      w.row[i] = first_sample_at_or_after(w.v[i], rows);
    }
    auto u = [&](uint64_t i) { return cu + su * (s.xyz[3 * (b + i)] + p.offset_x_mm); };
    for (uint64_t i = 0; i < n; ++i) {
      const uint64_t j = i + 1 == n ? 0 : i + 1;
      if (w.row[i] == w.row[j]) continue;
      double y0 = w.v[i], x0 = u(i), y1 = w.v[j], x1 = u(j);
      int r0 = w.row[i], r1 = w.row[j], dir = 1;
      if (y1 < y0) {
        std::swap(y0, y1);
        std::swap(x0, x1);
        std::swap(r0, r1);
        dir = -1;
      }
      // Horizontal edges cross no sample row; non-finite ones (only possible when the caller
      // skipped validate_slices) are dropped rather than fed to the sort.
      if (!(y0 < y1) || !std::isfinite(y1 - y0) || !std::isfinite(x1 - x0)) continue;
      if (r0 >= r1) continue;
      w.edges.push_back({y0, x0, y1, x1, r0, r1, dir});
    }
  }
  return open;
}

// Sweeps sample rows top to bottom with an active edge list; for every run of samples whose
// centres have nonzero winding calls span(row, first, end). A crossing at x counts for the
// samples whose centre is at or right of x, so a centre exactly on an edge is decided the same
// way whatever the order of edges.
template <class Span>
void sweep(Scratch& w, int rows, int cols, Span&& span) {
  w.row_count.assign(size_t(rows) + 1, 0);
  for (const Edge& e : w.edges) ++w.row_count[size_t(e.first_row) + 1];
  for (int r = 0; r < rows; ++r) w.row_count[size_t(r) + 1] += w.row_count[size_t(r)];
  w.order.resize(w.edges.size());
  {
    std::vector<uint32_t>& next = w.active;  // reused as fill cursors
    next.assign(w.row_count.begin(), w.row_count.end() - 1);
    for (uint32_t e = 0; e < w.edges.size(); ++e) w.order[next[size_t(w.edges[e].first_row)]++] = e;
  }
  w.active.clear();
  for (int r = 0; r < rows; ++r) {
    for (uint32_t i = w.row_count[size_t(r)]; i < w.row_count[size_t(r) + 1]; ++i)
      w.active.push_back(w.order[i]);
    if (w.active.empty()) continue;
    const double yc = r + 0.5;
    w.crossings.clear();
    size_t kept = 0;
    for (uint32_t e : w.active) {
      const Edge& g = w.edges[e];
      if (g.end_row <= r) continue;
      w.active[kept++] = e;
      w.crossings.push_back({g.xa + (yc - g.ya) * (g.xb - g.xa) / (g.yb - g.ya), g.dir});
    }
    w.active.resize(kept);
    std::sort(w.crossings.begin(), w.crossings.end());
    int winding = 0;
    for (size_t i = 0; i + 1 < w.crossings.size(); ++i) {
      winding += w.crossings[i].dir;
      if (winding == 0) continue;
      const int a = first_sample_at_or_after(w.crossings[i].x, cols);
      const int b = first_sample_at_or_after(w.crossings[i + 1].x, cols);
      if (a < b) span(r, a, b);
    }
  }
}

void check_layer(const Slices& s, size_t k, const PrinterProfile& profile) {
  validate_printer_profile(profile);
  if (k >= s.layers())
    throw Error("layer " + std::to_string(k) + " does not exist (" + std::to_string(s.layers()) +
                " layers)");
  if (!s.has_points()) throw Error("the slices carry no contour points to rasterize");
}

}  // namespace

size_t rasterize_layer_runs(const Slices& s, size_t k, const PrinterProfile& profile, MaskRuns& out) {
  check_layer(s, k, profile);
  if (profile.antialiasing) throw Error("anti-aliased masks have grey levels and cannot be given as runs");
  thread_local Scratch w;
  const int H = profile.height_px;
  out.width = profile.width_px;
  out.height = H;
  out.row_begin.assign(size_t(H) + 1, 0);
  out.columns.clear();
  const size_t open = build_edges(s, k, profile, 1, w, H);
  // Rows come in order and runs left to right (see sweep): count per row, then sum up.
  sweep(w, H, profile.width_px, [&](int r, int a, int b) {
    ++out.row_begin[size_t(r) + 1];
    out.columns.push_back(uint16_t(a));
    out.columns.push_back(uint16_t(b));
  });
  for (int r = 0; r < H; ++r) out.row_begin[size_t(r) + 1] += out.row_begin[size_t(r)];
  return open;
}

size_t rasterize_layer(const Slices& s, size_t k, const PrinterProfile& profile, uint8_t* out) {
  check_layer(s, k, profile);
  thread_local Scratch w;
  const int W = profile.width_px, H = profile.height_px;
  std::memset(out, 0, size_t(W) * size_t(H));
  if (!profile.antialiasing) {
    const size_t open = build_edges(s, k, profile, 1, w, H);
    sweep(w, H, W, [&](int r, int a, int b) { std::memset(out + size_t(r) * W + a, 255, b - a); });
    return open;
  }
  constexpr int S = SUPERSAMPLE;
  const size_t open = build_edges(s, k, profile, S, w, H * S);
  w.coverage.assign(size_t(W) * H, 0);
  uint16_t* cov = w.coverage.data();
  sweep(w, H * S, W * S, [&](int r, int a, int b) {
    uint16_t* row = cov + size_t(r / S) * W;
    const int ca = a / S, cb = (b - 1) / S;
    if (ca == cb) {
      row[ca] += uint16_t(b - a);
      return;
    }
    row[ca] += uint16_t(S * (ca + 1) - a);
    for (int c = ca + 1; c < cb; ++c) row[c] += S;
    row[cb] += uint16_t(b - S * cb);
  });
  for (size_t i = 0, n = size_t(W) * H; i < n; ++i)
    out[i] = uint8_t((cov[i] * 255u + S * S / 2) / (S * S));
  return open;
}

}  // namespace slicereuse
