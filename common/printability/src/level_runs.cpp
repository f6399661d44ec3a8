#include "level_runs.h"

#include <cstring>

#include "slicereuse/util/union_find.h"

namespace slicereuse {
namespace {

LevelRuns empty_like(int width, int height) {
  LevelRuns r;
  r.width = width;
  r.height = height;
  r.row_begin.reserve(size_t(height) + 1);
  r.row_begin.push_back(0);
  return r;
}

void add_run(LevelRuns& r, int lo, int hi) {
  r.lo.push_back(uint16_t(lo));
  r.hi.push_back(uint16_t(hi));
}

}  // namespace

uint64_t LevelRuns::pixels() const {
  uint64_t n = 0;
  for (size_t i = 0; i < lo.size(); ++i) n += hi[i] - lo[i];
  return n;
}

std::vector<LevelRuns> runs_at_levels(const MaskRuns& mask, const std::vector<uint8_t>& levels) {
  std::vector<LevelRuns> out;
  for (size_t j = 0; j < levels.size(); ++j) {
    out.push_back(empty_like(mask.width, mask.height));
    out.back().lo.reserve(mask.levels.size());
    out.back().hi.reserve(mask.levels.size());
  }
  const size_t n = levels.size();
  std::vector<uint32_t> row_start(n);
  for (int y = 0; y < mask.height; ++y) {
    for (size_t j = 0; j < n; ++j) row_start[j] = out[j].runs();
    for (uint32_t i = mask.row_begin[size_t(y)]; i < mask.row_begin[size_t(y) + 1]; ++i) {
      const uint8_t level = mask.levels[i];
      const uint16_t lo = mask.columns[2 * size_t(i)], hi = mask.columns[2 * size_t(i) + 1];
      // Ascending levels: those this run reaches come first.
      for (size_t j = 0; j < n && levels[j] <= level; ++j) {
        LevelRuns& r = out[j];
        if (r.runs() > row_start[j] && r.hi.back() == lo)
          r.hi.back() = hi;  // runs of different levels side by side: one run here
        else
          add_run(r, lo, hi);
      }
    }
    for (size_t j = 0; j < n; ++j) out[j].row_begin.push_back(out[j].runs());
  }
  return out;
}

LevelRuns complement_runs(const LevelRuns& runs) {
  LevelRuns r = empty_like(runs.width, runs.height);
  for (int y = 0; y < runs.height; ++y) {
    int x = 0;
    for (uint32_t i = runs.row_begin[size_t(y)]; i < runs.row_begin[size_t(y) + 1]; ++i) {
      if (runs.lo[i] > x) add_run(r, x, runs.lo[i]);
      x = runs.hi[i];
    }
    if (x < runs.width) add_run(r, x, runs.width);
    r.row_begin.push_back(r.runs());
  }
  return r;
}

LevelRuns subtract_runs(const LevelRuns& a, const LevelRuns& b) {
  LevelRuns r = empty_like(a.width, a.height);
  for (int y = 0; y < a.height; ++y) {
    uint32_t j = b.row_begin[size_t(y)];
    const uint32_t je = b.row_begin[size_t(y) + 1];
    for (uint32_t i = a.row_begin[size_t(y)]; i < a.row_begin[size_t(y) + 1]; ++i) {
      int x = a.lo[i];
      while (j < je && b.hi[j] <= x) ++j;
      // Each run of b inside a's run cuts it; the last one may reach into a's next run.
      for (uint32_t k = j; k < je && b.lo[k] < a.hi[i]; ++k) {
        if (b.lo[k] > x) add_run(r, x, b.lo[k]);
        if (b.hi[k] > x) x = b.hi[k];
      }
      if (x < a.hi[i]) add_run(r, x, a.hi[i]);
    }
    r.row_begin.push_back(r.runs());
  }
  return r;
}

LevelRuns intersect_runs(const LevelRuns& a, const LevelRuns& b) {
  LevelRuns r = empty_like(a.width, a.height);
  for (int y = 0; y < a.height; ++y) {
    for_each_overlap(a, b, y, [&](uint32_t, uint32_t, int lo, int hi) { add_run(r, lo, hi); });
    r.row_begin.push_back(r.runs());
  }
  return r;
}

RunLabels label_runs(const LevelRuns& runs, bool diagonal) {
  UnionFind sets(runs.runs());
  const int reach = diagonal ? 1 : 0;  // a corner contact is one column apart
  for (int y = 1; y < runs.height; ++y) {
    uint32_t j = runs.row_begin[size_t(y) - 1];
    const uint32_t je = runs.row_begin[size_t(y)];
    for (uint32_t i = runs.row_begin[size_t(y)]; i < runs.row_begin[size_t(y) + 1]; ++i) {
      while (j < je && runs.hi[j] + reach <= runs.lo[i]) ++j;
      for (uint32_t k = j; k < je && runs.lo[k] < runs.hi[i] + reach; ++k) sets.join(i, k);
    }
  }
  RunLabels labels;
  labels.of_run.resize(runs.runs());
  std::vector<uint32_t> of_root(runs.runs(), UINT32_MAX);
  for (uint32_t i = 0; i < runs.runs(); ++i) {
    uint32_t& label = of_root[sets.find(i)];
    if (label == UINT32_MAX) label = labels.count++;
    labels.of_run[i] = label;
  }
  return labels;
}

}  // namespace slicereuse
