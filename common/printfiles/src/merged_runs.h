#pragma once
// for_each_merged_run(runs, code, emit): a mask given as runs (mask_png.h's MaskRuns: each row's
// lit runs, rows one after the other making the row-major pixel stream) as the maximal runs of
// equal code that the run-length print files (.goo, .ctb, Anycubic pw0Img) store: code(level)
// is what the file stores for a pixel of that level (code(0) for unlit pixels), and
// emit(code, count) is called once per maximal run, in order (equal neighbours, across runs and
// rows, merged: the unlit end of a row and the unlit start of the next are one run). In time
// proportional to the runs, never the pixels.
#include <cstdint>

#include "slicereuse/png/mask_png.h"

namespace slicereuse {

template <class Code, class Emit>
void for_each_merged_run(const MaskRuns& runs, Code code, Emit emit) {
  auto value = code(uint8_t(0));
  uint64_t pending = 0;
  const auto pixels = [&](decltype(value) v, uint64_t n) {
    if (n == 0) return;
    if (pending > 0 && v == value) {
      pending += n;
      return;
    }
    if (pending > 0) emit(value, pending);
    value = v;
    pending = n;
  };
  const auto unlit = code(uint8_t(0));
  for (int r = 0; r < runs.height; ++r) {
    uint32_t c = 0;
    for (uint32_t i = runs.row_begin[size_t(r)]; i < runs.row_begin[size_t(r) + 1]; ++i) {
      const uint32_t c0 = runs.columns[2 * size_t(i)], c1 = runs.columns[2 * size_t(i) + 1];
      pixels(unlit, c0 - c);
      pixels(code(runs.levels[size_t(i)]), c1 - c0);
      c = c1;
    }
    pixels(unlit, uint64_t(uint32_t(runs.width) - c));
  }
  if (pending > 0) emit(value, pending);
}

}  // namespace slicereuse
