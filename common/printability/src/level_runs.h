#pragma once
// LevelRuns: the pixels of one layer image at or above a brightness, as runs per row: row r's
// runs are [lo[i], hi[i]) for i in [row_begin[r], row_begin[r+1]), increasing and disjoint.
// The checks work on these runs rather than on pixels: a plate's layer is mostly unlit.
//
// PixelBox: the box [x0, x1) x [y0, y1) of the pixels added to it (runs of a row, other boxes);
//   empty until the first.
// runs_at_levels: a mask's runs -> for each of levels (at most 32, in any order), the runs of its
//   pixels >= that level (runs of different levels side by side join), all levels in one pass
//   over the mask's runs.
// box_of: the box of the runs' pixels.
// subtract_runs: the pixels of a not in b.
// label_runs: runs -> the connected component of each run (0..count-1, in order of first run),
//   runs of neighbouring rows joining when they share a column (4-connectivity) or, with
//   diagonal, also when they touch at a corner (8-connectivity).
// pixels_inside(other, runs, labels): per component of runs (labels, from label_runs), the
//   pixels of other inside it.
// for_each_overlap(a, b, row, f): f(i, j, lo, hi) for each pair of run i of a and run j of b in
//   that row sharing columns [lo, hi), in increasing column order.
// for_each_difference(a, b, row, f): f(lo, hi) for each run [lo, hi) of that row's pixels of a
//   not in b, in increasing column order (subtract_runs' runs, without keeping them).
#include <cstdint>
#include <vector>

#include "slicereuse/png/mask_png.h"
#include "slicereuse/util/union_find.h"

namespace slicereuse {

struct PixelBox {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
  void add(int lo, int hi, int y) {
    x0 = x0 < lo ? x0 : lo;
    x1 = x1 > hi ? x1 : hi;
    y0 = y0 < y ? y0 : y;
    y1 = y1 > y + 1 ? y1 : y + 1;
  }
  void add(const PixelBox& b) {
    x0 = x0 < b.x0 ? x0 : b.x0;
    x1 = x1 > b.x1 ? x1 : b.x1;
    y0 = y0 < b.y0 ? y0 : b.y0;
    y1 = y1 > b.y1 ? y1 : b.y1;
  }
  bool empty() const { return x1 < 0; }
  bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

struct LevelRuns {
  int width = 0;
  int height = 0;
  std::vector<uint32_t> row_begin;  // height + 1
  std::vector<uint16_t> lo, hi;     // one per run

  uint32_t runs() const { return uint32_t(lo.size()); }
  uint64_t pixels() const;
};

std::vector<LevelRuns> runs_at_levels(const MaskRuns& mask, const std::vector<uint8_t>& levels);
PixelBox box_of(const LevelRuns& runs);
LevelRuns subtract_runs(const LevelRuns& a, const LevelRuns& b);

struct RunLabels {
  std::vector<uint32_t> of_run;  // component of each run
  uint32_t count = 0;
};
RunLabels label_runs(const LevelRuns& runs, bool diagonal);

// ProvisionalLabels: label_runs' labelling of runs as they are made, row after row (air_layer_of
// makes and labels the air's runs in one pass). add(lo_of, hi_of, j, je, lo, hi, reach) labels the
// next run, [lo, hi), of a row whose row above holds runs [j, je) of lo_of and hi_of (j advances
// as the row's runs come, left to right; reach 1 joins runs touching at a corner): it takes the
// label of the first run above it touches, or a new one (returns true), and the labels of other
// runs above it touches are joined to it. Most runs touch one run above, so the sets hold few
// labels and most finds end at once. numbered(root_of_label) numbers the sets in order of their
// first run; root_of_label, when not null, gets each one's root among the provisional labels;
// summed turns sums kept per provisional label into sums per label. add_rows adds the runs of rows
// that exist already.
struct ProvisionalLabels {
  std::vector<uint32_t> of_run;
  UnionFind sets;

  bool add(const uint16_t* lo_of, const uint16_t* hi_of, uint32_t& j, uint32_t je, int lo, int hi, int reach) {
    while (j < je && hi_of[j] + reach <= lo) ++j;
    if (j == je || lo_of[j] >= hi + reach) {
      of_run.push_back(sets.add());
      return true;
    }
    const uint32_t label = of_run[j];
    for (uint32_t k = j + 1; k < je && lo_of[k] < hi + reach; ++k)
      if (of_run[k] != label) sets.join(of_run[k], label);
    of_run.push_back(label);
    return false;
  }
  // Adds rows [y0, y1) of runs (the row before y0 holds none), calling visit(i, y, fresh) after
  // labelling each run i of row y, fresh when it started a label.
  template <class Visit>
  void add_rows(const LevelRuns& runs, int y0, int y1, int reach, Visit visit) {
    for (int y = y0; y < y1; ++y) {
      uint32_t j = y > 0 ? runs.row_begin[size_t(y) - 1] : 0;
      const uint32_t je = runs.row_begin[size_t(y)];
      for (uint32_t i = runs.row_begin[size_t(y)]; i < runs.row_begin[size_t(y) + 1]; ++i)
        visit(i, y, add(runs.lo.data(), runs.hi.data(), j, je, runs.lo[i], runs.hi[i], reach));
    }
  }
  RunLabels numbered(std::vector<uint32_t>* root_of_label = nullptr);
  // Sums kept per provisional label (sums[p]) -> per label, as numbered gave their roots: each
  // set's sums added at its root by add(to, from).
  template <class Sums, class Add>
  std::vector<Sums> summed(std::vector<Sums>& sums, const std::vector<uint32_t>& root_of_label, Add add) {
    for (uint32_t p = 0; p < sums.size(); ++p) {
      const uint32_t root = sets.find(p);
      if (root != p) add(sums[root], sums[p]);
    }
    std::vector<Sums> out;
    out.reserve(root_of_label.size());
    for (const uint32_t root : root_of_label) out.push_back(sums[root]);
    return out;
  }
};
std::vector<uint64_t> pixels_inside(const LevelRuns& other, const LevelRuns& runs, const RunLabels& labels);

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

template <class F>
void for_each_difference(const LevelRuns& a, const LevelRuns& b, int row, F f) {
  uint32_t j = b.row_begin[size_t(row)];
  const uint32_t je = b.row_begin[size_t(row) + 1];
  for (uint32_t i = a.row_begin[size_t(row)]; i < a.row_begin[size_t(row) + 1]; ++i) {
    int x = a.lo[i];
    while (j < je && b.hi[j] <= x) ++j;
    // Each run of b inside a's run cuts it; the last one may reach into a's next run.
    for (uint32_t k = j; k < je && b.lo[k] < a.hi[i]; ++k) {
      if (b.lo[k] > x) f(x, int(b.lo[k]));
      if (b.hi[k] > x) x = b.hi[k];
    }
    if (x < a.hi[i]) f(x, int(a.hi[i]));
  }
}

}  // namespace slicereuse
