#pragma once
// LevelRuns: the pixels of one layer image at or above a brightness, as runs per row: row r's
// runs are [lo[i], hi[i]) for i in [row_begin[r], row_begin[r+1]), increasing and disjoint.
// The checks work on these runs rather than on pixels: a plate's layer is mostly unlit.
//
// runs_at_levels: a mask's runs -> for each of levels (ascending), the runs of its pixels >= that
//   level, all in one pass over the mask's runs.
// complement_runs: the runs of the pixels in no run of runs (same width and height).
// subtract_runs: the pixels of a not in b; intersect_runs: the pixels in both.
// label_runs: runs -> the connected component of each run (0..count-1, in order of first run),
//   runs of neighbouring rows joining when they share a column (4-connectivity) or, with
//   diagonal, also when they touch at a corner (8-connectivity).
// for_each_overlap(a, b, row, f): f(i, j, lo, hi) for each pair of run i of a and run j of b in
//   that row sharing columns [lo, hi), in increasing column order.
#include <cstdint>
#include <vector>

#include "slicereuse/png/mask_png.h"

namespace slicereuse {

struct LevelRuns {
  int width = 0;
  int height = 0;
  std::vector<uint32_t> row_begin;  // height + 1
  std::vector<uint16_t> lo, hi;     // one per run

  uint32_t runs() const { return uint32_t(lo.size()); }
  uint64_t pixels() const;
};

std::vector<LevelRuns> runs_at_levels(const MaskRuns& mask, const std::vector<uint8_t>& levels);
LevelRuns complement_runs(const LevelRuns& runs);
LevelRuns subtract_runs(const LevelRuns& a, const LevelRuns& b);
LevelRuns intersect_runs(const LevelRuns& a, const LevelRuns& b);

struct RunLabels {
  std::vector<uint32_t> of_run;  // component of each run
  uint32_t count = 0;
};
RunLabels label_runs(const LevelRuns& runs, bool diagonal);

template <class F>
void for_each_overlap(const LevelRuns& a, const LevelRuns& b, int row, F f) {
  uint32_t i = a.row_begin[size_t(row)], j = b.row_begin[size_t(row)];
  const uint32_t ie = a.row_begin[size_t(row) + 1], je = b.row_begin[size_t(row) + 1];
  while (i < ie && j < je) {
    const uint16_t lo = a.lo[i] > b.lo[j] ? a.lo[i] : b.lo[j];
    const uint16_t hi = a.hi[i] < b.hi[j] ? a.hi[i] : b.hi[j];
    if (lo < hi) f(i, j, lo, hi);
    if (a.hi[i] < b.hi[j]) ++i; else ++j;
  }
}

}  // namespace slicereuse
