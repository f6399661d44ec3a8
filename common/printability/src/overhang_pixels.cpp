#include "overhang_pixels.h"

#include <algorithm>
#include <vector>

#include "uvtools_settings.h"

namespace slicereuse {
namespace {

// The level of row y's pixel x in mask, walking the row's runs forwards from i (kept between
// calls with increasing x), and the first column past x where it may change.
struct RowLevels {
  const MaskRuns& mask;
  uint32_t i, end;
  RowLevels(const MaskRuns& m, int y) : mask(m), i(m.row_begin[size_t(y)]), end(m.row_begin[size_t(y) + 1]) {}
  uint8_t at(int x, int& next) {
    while (i < end && mask.columns[2 * size_t(i) + 1] <= x) ++i;
    if (i == end) return 0;  // next unchanged: nothing lit further on
    const int lo = mask.columns[2 * size_t(i)];
    if (x < lo) {
      next = std::min(next, lo);
      return 0;
    }
    next = std::min(next, int(mask.columns[2 * size_t(i) + 1]));
    return mask.levels[i];
  }
};

}  // namespace

LevelRuns overhang_pixels(const LayerRuns& layer, const LayerRuns& below) {
  const MaskRuns& mask = *layer.mask;
  PixelBox crop = *layer.nonzero_box;
  crop.add(*below.nonzero_box);
  // Only a pixel whose row has 40 brighter pixels on either side (or the crop's border, which
  // does not erode) can survive. The brighter pixels lie within the candidates, so where no
  // candidate run is that long (most layers: thin rims), none survives.
  const auto core_of = [&](int lo, int hi, int& core_lo, int& core_hi) {
    core_lo = lo == crop.x0 ? lo : lo + kErodeIterations;
    core_hi = hi == crop.x1 ? hi : hi - kErodeIterations;
    return core_lo < core_hi;
  };
  LevelRuns kept;
  kept.width = mask.width;
  kept.height = mask.height;
  kept.row_begin.assign(size_t(mask.height) + 1, 0);
  // Whether a run of the pixels of a not in b holds a core, in the rows with pixels here.
  const auto any_core_in = [&](const LevelRuns& a, const LevelRuns& b) {
    bool any = false;
    for (int y = layer.nonzero_box->y0; y < layer.nonzero_box->y1 && !any; ++y)
      for_each_difference(a, b, y, [&](int lo, int hi) {
        int core_lo, core_hi;
        any |= core_of(lo, hi, core_lo, core_hi);
      });
    return any;
  };
  // Brighter by more than 127 needs >= 128 here and < 128 below (the candidates); the levels
  // decide the rest. The candidates lie within the pixels >= 101 here and < 150 below, whose
  // runs the layers have: most layers have no run of those with a core, and are not kept; the
  // others have their candidates found.
  if (!any_core_in(*layer.solid, *below.support)) return kept;
  const LevelRuns here_128 = runs_at_levels(mask, {128})[0];
  const LevelRuns below_128 = runs_at_levels(*below.mask, {128})[0];
  if (!any_core_in(here_128, below_128)) return kept;
  const LevelRuns candidates = subtract_runs(here_128, below_128);
  LevelRuns brighter;
  brighter.width = mask.width;
  brighter.height = mask.height;
  brighter.row_begin.push_back(0);
  for (int y = 0; y < mask.height; ++y) {
    RowLevels here(mask, y), under(*below.mask, y);
    const uint32_t row = brighter.runs();
    for (uint32_t i = candidates.row_begin[size_t(y)]; i < candidates.row_begin[size_t(y) + 1]; ++i) {
      for (int x = candidates.lo[i]; x < candidates.hi[i];) {
        int next = candidates.hi[i];
        const bool is_brighter = here.at(x, next) - under.at(x, next) > kDifferenceThreshold;
        if (is_brighter) {
          if (brighter.runs() > row && brighter.hi.back() == x) {
            brighter.hi.back() = uint16_t(next);
          } else {
            brighter.lo.push_back(uint16_t(x));
            brighter.hi.push_back(uint16_t(next));
          }
        }
        x = next;
      }
    }
    brighter.row_begin.push_back(brighter.runs());
  }
  LevelRuns core;
  core.width = mask.width;
  core.height = mask.height;
  core.row_begin.push_back(0);
  for (int y = 0; y < mask.height; ++y) {
    for (uint32_t i = brighter.row_begin[size_t(y)]; i < brighter.row_begin[size_t(y) + 1]; ++i) {
      int lo, hi;
      if (!core_of(brighter.lo[i], brighter.hi[i], lo, hi)) continue;
      core.lo.push_back(uint16_t(lo));
      core.hi.push_back(uint16_t(hi));
    }
    core.row_begin.push_back(core.runs());
  }
  const PixelBox found = box_of(core);
  if (found.empty()) return kept;

  // L1 distance to the nearest pixel of the crop that is not brighter, over the core's box and
  // the 41 pixels around it (where every such pixel within 40 of the core lies); two chamfer
  // passes give it exactly in a rectangle.
  const int reach = kErodeIterations + 1;
  const int x0 = std::max(found.x0 - reach, 0), y0 = std::max(found.y0 - reach, 0);
  const int x1 = std::min(found.x1 + reach, mask.width), y1 = std::min(found.y1 + reach, mask.height);
  const int w = x1 - x0, h = y1 - y0;
  constexpr int kFar = 1 << 29;
  std::vector<int> dist(size_t(w) * size_t(h));
  for (int y = y0; y < y1; ++y) {
    int* d = dist.data() + size_t(y - y0) * size_t(w);
    for (int x = x0; x < x1; ++x) d[x - x0] = crop.contains(x, y) ? 0 : kFar;
    for (uint32_t i = brighter.row_begin[size_t(y)]; i < brighter.row_begin[size_t(y) + 1]; ++i) {
      const int lo = std::max<int>(brighter.lo[i], x0), hi = std::min<int>(brighter.hi[i], x1);
      if (lo < hi) std::fill(d + (lo - x0), d + (hi - x0), kFar);
    }
  }
  for (int y = 0; y < h; ++y) {
    int* d = dist.data() + size_t(y) * size_t(w);
    for (int x = 0; x < w; ++x) {
      if (x > 0) d[x] = std::min(d[x], d[x - 1] + 1);
      if (y > 0) d[x] = std::min(d[x], d[x - w] + 1);
    }
  }
  for (int y = h - 1; y >= 0; --y) {
    int* d = dist.data() + size_t(y) * size_t(w);
    for (int x = w - 1; x >= 0; --x) {
      if (x < w - 1) d[x] = std::min(d[x], d[x + 1] + 1);
      if (y < h - 1) d[x] = std::min(d[x], d[x + w] + 1);
    }
  }
  // Distances inside the window are exact within 40 of the core only: survivors come from it.
  kept.row_begin.assign(1, 0);
  for (int y = 0; y < mask.height; ++y) {
    if (y >= y0 && y < y1) {
      const int* d = dist.data() + size_t(y - y0) * size_t(w);
      for (uint32_t i = core.row_begin[size_t(y)]; i < core.row_begin[size_t(y) + 1]; ++i) {
        for (int x = core.lo[i]; x < core.hi[i];) {
          if (d[x - x0] <= kErodeIterations) {
            ++x;
            continue;
          }
          const int lo = x;
          while (x < core.hi[i] && d[x - x0] > kErodeIterations) ++x;
          kept.lo.push_back(uint16_t(lo));
          kept.hi.push_back(uint16_t(x));
        }
      }
    }
    kept.row_begin.push_back(kept.runs());
  }
  return kept;
}

}  // namespace slicereuse
