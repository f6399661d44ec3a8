#pragma once
// PngRows: an 8-bit greyscale mask PNG (mask_png.h) written into out (replaced) from runs of
// equal pixels as a rasterizer makes them, without keeping the pixels or the runs. Each
// row(fill) adds the next row: its filter byte (type 0), then fill(pixels) calls pixels(level,
// n) for the row's pixels left to right, n of them at a time (n may be 0); empty_rows(n) adds
// n rows of black at once. finish() ends the file. The runs go straight to the thread's
// RunDeflater, which merges equal neighbours (a row's trailing black, the next filter byte and
// that row's leading black are one run). One PngRows per thread at a time; encode_mask_png of
// MaskRuns is one.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "slicereuse/png/deflate_runs.h"

namespace slicereuse {

class PngRows {
 public:
  // Throws Error for a size encode_mask_png refuses.
  PngRows(int width, int height, std::vector<uint8_t>& out);
  template <class Fill>
  void row(Fill&& fill) {
    // A local copy of the deflater's runs for the row: its state stays in registers.
    RunDeflater::Runs runs = runs_;
    runs.add(0, 1);
    fill([&runs](uint8_t level, size_t n) { runs.add(level, n); });
    runs_ = runs;
  }
  void empty_rows(size_t n) {
    RunDeflater::Runs runs = runs_;
    runs.add(0, n * (size_t(width_) + 1));  // each row's filter byte 0 and its pixels
    runs_ = runs;
  }
  void finish();

 private:
  int width_;
  RunDeflater& deflater_;
  RunDeflater::Runs runs_;
  std::vector<uint8_t>& out_;
  size_t data_begin_ = 0;
};

}  // namespace slicereuse
