#include "slicereuse/printability/seal_support_pockets.h"

#include <algorithm>
#include <vector>

#include "air_regions.h"
#include "level_runs.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "uvtools_settings.h"

namespace slicereuse {
namespace {

// Whether a lit run of row y of lit comes within one pixel of columns [lo, hi).
bool lit_near(const LevelRuns& lit, int y, int lo, int hi) {
  if (y < 0 || y >= lit.height) return false;
  const uint32_t b = lit.row_begin[size_t(y)], e = lit.row_begin[size_t(y) + 1];
  // The first run whose last pixel (hi - 1) is at or after column lo - 1.
  const uint16_t* first =
      std::upper_bound(lit.hi.data() + b, lit.hi.data() + e, lo - 1, [](int v, uint16_t h) { return v < int(h); });
  const uint32_t i = uint32_t(first - lit.hi.data());
  return i < e && int(lit.lo[i]) <= hi;
}

// Row y of mask with the sealed columns [s_lo[k], s_hi[k]) at 255, appended to out.
void seal_row(const MaskRuns& mask, int y, const std::vector<uint16_t>& s_lo, const std::vector<uint16_t>& s_hi,
              MaskRuns& out) {
  auto add = [&](int a, int b, uint8_t level) {
    if (a >= b) return;
    const size_t n = out.levels.size();
    if (n > out.row_begin[size_t(y)] && out.levels[n - 1] == level && out.columns[2 * n - 1] == a) {
      out.columns[2 * n - 1] = uint16_t(b);
      return;
    }
    out.columns.push_back(uint16_t(a));
    out.columns.push_back(uint16_t(b));
    out.levels.push_back(level);
  };
  // A mask run is either air (below the solid level) inside one air run, sealed or not, or solid
  // and apart from every air run: so it is dropped when a sealed run holds it, else kept.
  size_t k = 0;
  int sealed_to = 0;
  for (uint32_t i = mask.row_begin[size_t(y)]; i < mask.row_begin[size_t(y) + 1]; ++i) {
    const int a = mask.columns[2 * size_t(i)], b = mask.columns[2 * size_t(i) + 1];
    for (; k < s_lo.size() && s_lo[k] <= a; ++k) {
      add(s_lo[k], s_hi[k], 255);
      sealed_to = s_hi[k];
    }
    if (b > sealed_to) add(a, b, mask.levels[i]);
  }
  for (; k < s_lo.size(); ++k) add(s_lo[k], s_hi[k], 255);
}

}  // namespace

size_t seal_support_pockets(MaskRuns& mask, const MaskRuns& support_runs, uint64_t max_pixels) {
  if (support_runs.width != mask.width || support_runs.height != mask.height)
    throw Error(format("internal error: a %d x %d mask sealed with supports of %d x %d pixels", mask.width,
                       mask.height, support_runs.width, support_runs.height));
  if (support_runs.levels.empty()) return 0;
  const LevelRuns air = complement_runs(runs_at_levels(mask, {kTrapSolid})[0]);
  const AirLayer layer = air_layer_of(air);
  std::vector<uint8_t> sealed(layer.labels.count, 0);
  bool candidates = false;
  for (uint32_t c = 0; c < layer.labels.count; ++c)
    candidates |= sealed[c] = !layer.regions[c].border && layer.regions[c].pixels < max_pixels;
  if (!candidates) return 0;
  const LevelRuns supports = runs_at_levels(support_runs, {1})[0];
  std::vector<uint8_t> touches(layer.labels.count, 0);
  const LevelRuns& runs = layer.runs;
  for (int y = 0; y < runs.height; ++y)
    for (uint32_t i = runs.row_begin[size_t(y)]; i < runs.row_begin[size_t(y) + 1]; ++i) {
      const uint32_t c = layer.labels.of_run[i];
      if (!sealed[c] || touches[c] || layer.regions[c].pixels < kRequiredBlackPixelsToDrain) continue;
      for (int dy = -1; dy <= 1 && !touches[c]; ++dy) touches[c] = lit_near(supports, y + dy, runs.lo[i], runs.hi[i]);
    }
  size_t count = 0;
  for (uint32_t c = 0; c < layer.labels.count; ++c)
    count += sealed[c] = sealed[c] && (touches[c] || layer.regions[c].pixels < kRequiredBlackPixelsToDrain);
  if (count == 0) return 0;
  MaskRuns out;
  out.width = mask.width;
  out.height = mask.height;
  out.row_begin.assign(size_t(mask.height) + 1, 0);
  out.columns.reserve(mask.columns.size() + 2 * count);
  out.levels.reserve(mask.levels.size() + count);
  std::vector<uint16_t> s_lo, s_hi;
  for (int y = 0; y < mask.height; ++y) {
    out.row_begin[size_t(y)] = uint32_t(out.levels.size());
    s_lo.clear();
    s_hi.clear();
    for (uint32_t i = runs.row_begin[size_t(y)]; i < runs.row_begin[size_t(y) + 1]; ++i)
      if (sealed[layer.labels.of_run[i]]) {
        s_lo.push_back(runs.lo[i]);
        s_hi.push_back(runs.hi[i]);
      }
    if (s_lo.empty()) {  // the row as it was
      const uint32_t b = mask.row_begin[size_t(y)], e = mask.row_begin[size_t(y) + 1];
      out.columns.insert(out.columns.end(), mask.columns.begin() + 2 * long(b), mask.columns.begin() + 2 * long(e));
      out.levels.insert(out.levels.end(), mask.levels.begin() + long(b), mask.levels.begin() + long(e));
    } else {
      seal_row(mask, y, s_lo, s_hi, out);
    }
  }
  out.row_begin[size_t(mask.height)] = uint32_t(out.levels.size());
  mask = std::move(out);
  return count;
}

}  // namespace slicereuse
