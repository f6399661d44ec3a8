#include "goo_preview.h"

#include <algorithm>
#include <cmath>

namespace slicereuse {

GooFootprint::GooFootprint(const PrinterProfile& profile)
    : layout_(mask_image_layout(profile)), cells_(size_t(kGrid) * kWords) {
  const double w_mm = layout_.width * layout_.column_um / 1000, h_mm = layout_.height * layout_.row_um / 1000;
  const double cells_per_mm = kGrid / std::max(w_mm, h_mm);
  cell_per_column_ = layout_.column_um / 1000 * cells_per_mm;
  cell_per_row_ = layout_.row_um / 1000 * cells_per_mm;
  left_ = (kGrid - w_mm * cells_per_mm) / 2;
  top_ = (kGrid - h_mm * cells_per_mm) / 2;
}

// The cells [first, last] that the interval [a, b) of cell coordinates overlaps, within the grid;
// ends within 1e-9 of a cell edge (pixel edges on cell edges, up to rounding) are on it.
std::pair<int, int> GooFootprint::span(double a, double b) {
  const int first = std::clamp(int(std::floor(a + 1e-9)), 0, kGrid - 1);
  return {first, std::clamp(int(std::ceil(b - 1e-9)) - 1, first, kGrid - 1)};
}

void GooFootprint::add(const MaskRuns& runs) {
  // The layer's cells on this thread first, then ORed into the shared grid: one atomic per
  // word that gains a cell, and none once the footprint is complete there.
  thread_local std::vector<uint64_t> local(size_t(kGrid) * kWords, 0);
  int lo = kGrid, hi = -1;
  for (int r = 0; r < runs.height; ++r) {
    const uint32_t b = runs.row_begin[size_t(r)], e = runs.row_begin[size_t(r) + 1];
    if (b == e) continue;
    // Top view: row 0 at the largest y. The cells the pixel row overlaps, usually one.
    const int top_row = layout_.rows_ascend ? runs.height - 1 - r : r;
    const auto [y0, y1] = span(top_ + top_row * cell_per_row_, top_ + (top_row + 1) * cell_per_row_);
    lo = std::min(lo, y0);
    hi = std::max(hi, y1);
    for (uint32_t i = b; i < e; ++i) {
      int c0 = runs.columns[2 * size_t(i)], c1 = runs.columns[2 * size_t(i) + 1];
      if (layout_.columns_descend) {  // x to the right
        const int t = runs.width - c1;
        c1 = runs.width - c0;
        c0 = t;
      }
      const auto [x0, x1] = span(left_ + c0 * cell_per_column_, left_ + c1 * cell_per_column_);
      for (int y = y0; y <= y1; ++y) {
        uint64_t* row = local.data() + size_t(y) * kWords;
        for (int w = x0 / 64; w <= x1 / 64; ++w) {
          const int from = std::max(x0, 64 * w) - 64 * w, to = std::min(x1, 64 * w + 63) - 64 * w;
          row[w] |= (~uint64_t(0) >> (63 - to)) & (~uint64_t(0) << from);
        }
      }
    }
  }
  for (int cy = lo; cy <= hi; ++cy)
    for (int w = 0; w < kWords; ++w) {
      uint64_t& bits = local[size_t(cy) * kWords + size_t(w)];
      std::atomic<uint64_t>& shared = cells_[size_t(cy) * kWords + size_t(w)];
      if ((shared.load(std::memory_order_relaxed) & bits) != bits) shared.fetch_or(bits, std::memory_order_relaxed);
      bits = 0;
    }
}

std::vector<uint16_t> GooFootprint::preview(int n) const {
  const int f = kGrid / n;
  std::vector<uint16_t> out(size_t(n) * size_t(n));
  for (int py = 0; py < n; ++py)
    for (int px = 0; px < n; ++px) {
      int lit = 0;
      for (int cy = py * f; cy < (py + 1) * f; ++cy)
        for (int cx = px * f; cx < (px + 1) * f; ++cx)
          lit += int(cells_[size_t(cy) * kWords + size_t(cx / 64)].load(std::memory_order_relaxed) >> (cx % 64) & 1);
      const unsigned v = unsigned(std::lround(255.0 * lit / (f * f)));
      out[size_t(py) * size_t(n) + size_t(px)] = uint16_t((v >> 3) << 11 | (v >> 2) << 5 | (v >> 3));
    }
  return out;
}

}  // namespace slicereuse
