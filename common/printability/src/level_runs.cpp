#include "level_runs.h"

#include <algorithm>

#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

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
  // All levels in one pass over the mask's runs (each read once) into arrays sized for every run.
  // A run's level passes a set of the levels (a bit each); along a row only the levels whose
  // state changes from one run to the next open or close a run, so a run costs a few bit
  // operations however many levels there are.
  const size_t n = mask.levels.size(), count_of_levels = levels.size();
  if (count_of_levels > 32) throw Error(format("runs at %zu levels asked, more than the 32 one pass gives", count_of_levels));
  uint32_t passes[256];
  for (int v = 0; v < 256; ++v) {
    passes[v] = 0;
    for (size_t j = 0; j < count_of_levels; ++j)
      if (v >= levels[j]) passes[v] |= 1u << j;
  }
  // Written into the thread's arrays, room for every run of the mask at each level (only grown,
  // never cleared), then copied out at their size: most runs of the mask are grey pixels that
  // open no run.
  thread_local std::vector<std::vector<uint16_t>> room;
  if (room.size() < 2 * count_of_levels) room.resize(2 * count_of_levels);
  std::vector<LevelRuns> out(count_of_levels);
  std::vector<uint16_t*> lo(count_of_levels), hi(count_of_levels);
  std::vector<uint32_t> count(count_of_levels, 0);
  for (size_t j = 0; j < count_of_levels; ++j) {
    LevelRuns& r = out[j];
    r.width = mask.width;
    r.height = mask.height;
    r.row_begin.resize(size_t(mask.height) + 1);
    for (size_t side = 2 * j; side < 2 * j + 2; ++side)
      if (room[side].size() < n) room[side].resize(n);
    lo[j] = room[2 * j].data(), hi[j] = room[2 * j + 1].data();
  }
  const uint16_t* columns = mask.columns.data();
  const uint8_t* run_level = mask.levels.data();
  // Closes the runs of the levels in bits at column end.
  const auto close = [&](uint32_t bits, uint16_t end) {
    for (; bits; bits &= bits - 1) {
      const int j = __builtin_ctz(bits);
      hi[size_t(j)][count[size_t(j)] - 1] = end;
    }
  };
  // Each level's row_begin is written at the rows with runs, and filled in between (most rows of
  // a display are empty).
  int filled = 0;  // rows before it have their row_begin
  const auto fill_rows = [&](int end) {
    for (size_t j = 0; j < count_of_levels; ++j)
      std::fill(out[j].row_begin.begin() + filled, out[j].row_begin.begin() + end, count[j]);
    filled = end;
  };
  for (int y = 0; y < mask.height; ++y) {
    if (mask.row_begin[size_t(y)] == mask.row_begin[size_t(y) + 1]) continue;
    if (filled < y) fill_rows(y);
    for (size_t j = 0; j < count_of_levels; ++j) out[j].row_begin[size_t(y)] = count[j];
    filled = y + 1;
    uint32_t open = 0;  // the levels whose run is still open, up to open_end
    uint16_t open_end = 0;
    for (uint32_t i = mask.row_begin[size_t(y)]; i < mask.row_begin[size_t(y) + 1]; ++i) {
      const uint16_t a = columns[2 * size_t(i)], b = columns[2 * size_t(i) + 1];
      const uint32_t pass = passes[run_level[i]];
      if (a != open_end) close(open, open_end), open = 0;  // a gap closes every open run
      close(open & ~pass, a);
      for (uint32_t bits = pass & ~open; bits; bits &= bits - 1) {
        const size_t j = size_t(__builtin_ctz(bits));
        lo[j][count[j]++] = a;
      }
      open = pass, open_end = b;
    }
    close(open, open_end);
  }
  fill_rows(mask.height + 1);
  for (size_t j = 0; j < count_of_levels; ++j) {
    LevelRuns& r = out[j];
    r.lo.assign(lo[j], lo[j] + count[j]);
    r.hi.assign(hi[j], hi[j] + count[j]);
  }
  return out;
}

PixelBox box_of(const LevelRuns& runs) {
  PixelBox box;
  for (int y = 0; y < runs.height; ++y) {
    const uint32_t b = runs.row_begin[size_t(y)], e = runs.row_begin[size_t(y) + 1];
    if (b != e) box.add(runs.lo[b], runs.hi[e - 1], y);
  }
  return box;
}

LevelRuns subtract_runs(const LevelRuns& a, const LevelRuns& b) {
  LevelRuns r = empty_like(a.width, a.height);
  for (int y = 0; y < a.height; ++y) {
    for_each_difference(a, b, y, [&](int lo, int hi) { add_run(r, lo, hi); });
    r.row_begin.push_back(r.runs());
  }
  return r;
}

RunLabels label_runs(const LevelRuns& runs, bool diagonal) {
  ProvisionalLabels labels;
  labels.of_run.reserve(runs.runs());
  labels.add_rows(runs, 0, runs.height, diagonal ? 1 : 0, [](uint32_t, int, bool) {});
  return labels.numbered();
}

RunLabels ProvisionalLabels::numbered(std::vector<uint32_t>* root_of_label) {
  // Each provisional label's set found once (there are few), then each run's numbered through it.
  const uint32_t count = uint32_t(sets.parent.size());
  std::vector<uint32_t> root(count), of_root(count, UINT32_MAX);
  for (uint32_t p = 0; p < count; ++p) root[p] = sets.find(p);
  RunLabels labels;
  labels.of_run.resize(of_run.size());
  if (root_of_label) root_of_label->clear();
  for (size_t i = 0; i < of_run.size(); ++i) {
    uint32_t& label = of_root[root[of_run[i]]];
    if (label == UINT32_MAX) {
      label = labels.count++;
      if (root_of_label) root_of_label->push_back(root[of_run[i]]);
    }
    labels.of_run[i] = label;
  }
  return labels;
}

std::vector<uint64_t> pixels_inside(const LevelRuns& other, const LevelRuns& runs, const RunLabels& labels) {
  std::vector<uint64_t> n(labels.count, 0);
  for (int y = 0; y < runs.height; ++y)
    for_each_overlap(other, runs, y, [&](uint32_t, uint32_t j, int lo, int hi) { n[labels.of_run[j]] += uint64_t(hi - lo); });
  return n;
}

}  // namespace slicereuse
