#pragma once
// PngRows: an 8-bit greyscale mask PNG (mask_png.h) written into out (replaced) from runs of
// equal pixels as a rasterizer makes them, without keeping the pixels or the runs: row()
// starts the next row (its filter byte, type 0), pixels(level, n) adds the row's next n pixels,
// finish() ends the file. Equal neighbours are merged before they reach the thread's
// RunDeflater (a row's trailing black, the next filter byte and that row's leading black are
// one run), and runs of up to 3 pixels (an anti-aliased mask's grey pixels) go to it as
// literals: the same stream. One PngRows per thread at a time; encode_mask_png of MaskRuns is
// one.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "slicereuse/masks/deflate_runs.h"

namespace slicereuse {

class PngRows {
 public:
  // Throws Error for a size encode_mask_png refuses.
  PngRows(int width, int height, std::vector<uint8_t>& out);
  void row() { pixels(0, 1); }
  void pixels(uint8_t level, size_t n) {
    if (n == 0) return;
    if (level != byte_) {
      flush();
      byte_ = level;
      count_ = 0;
    }
    count_ += n;
  }
  void finish();

 private:
  // Up to 3 equal bytes are literals whichever way they are sent, and cheaper as literals.
  void flush() {
    if (count_ > 3)
      deflater_.add_run(byte_, count_);
    else
      for (size_t i = 0; i < count_; ++i) deflater_.add_literal(byte_);
  }

  RunDeflater& deflater_;
  std::vector<uint8_t>& out_;
  size_t data_begin_ = 0;
  uint8_t byte_ = 0;
  size_t count_ = 0;
};

}  // namespace slicereuse
