#include "layer_facts.h"

#include <algorithm>

#include "uvtools_settings.h"

namespace slicereuse {
namespace {

PixelBox nonzero_box_of(const MaskRuns& mask) {
  PixelBox box;
  for (int y = 0; y < mask.height; ++y) {
    const uint32_t b = mask.row_begin[size_t(y)], e = mask.row_begin[size_t(y) + 1];
    if (b != e) box.add(mask.columns[2 * size_t(b)], mask.columns[2 * size_t(e) - 1], y);
  }
  return box;
}

// Pixels >= kTouchLevel within kTouchMargin of the edges: whole rows near the top and bottom,
// elsewhere only the runs reaching into the left or right margin (the first and last of a row).
void find_touching(const MaskRuns& mask, PixelBox& box, uint64_t& pixels) {
  const auto touch = [&](int lo, int hi, int y) {
    if (lo >= hi) return;
    box.add(lo, hi, y);
    pixels += uint64_t(hi - lo);
  };
  const int right = mask.width - kTouchMargin;
  for (int y = 0; y < mask.height; ++y) {
    const uint32_t b = mask.row_begin[size_t(y)], e = mask.row_begin[size_t(y) + 1];
    const bool edge_row = y < kTouchMargin || y >= mask.height - kTouchMargin;
    for (uint32_t i = b; i < e; ++i) {
      const int lo = mask.columns[2 * size_t(i)], hi = mask.columns[2 * size_t(i) + 1];
      if (!edge_row && lo >= kTouchMargin) break;
      if (mask.levels[i] >= kTouchLevel) touch(lo, edge_row ? hi : std::min(hi, kTouchMargin), y);
    }
    if (edge_row) continue;
    // From the right, their parts in the right margin (a run across the row counts in both).
    for (uint32_t i = e; i > b; --i) {
      const int lo = mask.columns[2 * size_t(i - 1)], hi = mask.columns[2 * size_t(i - 1) + 1];
      if (hi <= right) break;
      if (mask.levels[i - 1] >= kTouchLevel) touch(std::max(lo, right), hi, y);
    }
  }
}

}  // namespace

LayerFacts layer_facts_of(MaskRuns mask) {
  LayerFacts f;
  std::vector<LevelRuns> at = runs_at_levels(mask, {kIslandLit, kIslandPointLevel, kTrapSolid, kSupportLevel});
  f.lit = std::move(at[0]);
  f.points = std::move(at[1]);
  f.solid = std::move(at[2]);
  f.support = std::move(at[3]);
  f.nonzero_box = nonzero_box_of(mask);
  find_touching(mask, f.touching_box, f.touching_pixels);

  // The lit regions (UVtools: AllowDiagonalBonds false) labelled and summed in one pass over the
  // rows with pixels, as air_layer_of does the air's.
  ProvisionalLabels labels;
  labels.of_run.reserve(f.lit.runs());
  std::vector<LitRegion> sums;  // per provisional label
  labels.add_rows(f.lit, f.nonzero_box.y0, f.nonzero_box.y1, 0, [&](uint32_t i, int y, bool fresh) {
    if (fresh) sums.emplace_back();
    LitRegion& r = sums[labels.of_run.back()];
    r.pixels += f.lit.hi[i] - f.lit.lo[i];
    r.box.add(f.lit.lo[i], f.lit.hi[i], y);
  });
  std::vector<uint32_t> root_of_label;
  f.lit_labels = labels.numbered(&root_of_label);
  f.lit_regions = labels.summed(sums, root_of_label, [](LitRegion& to, const LitRegion& from) {
    to.pixels += from.pixels;
    to.box.add(from.box);
  });
  // Pixels >= 10 are lit: each run of them lies in one lit run.
  f.point_region.resize(f.points.runs());
  for (int y = f.nonzero_box.y0; y < f.nonzero_box.y1; ++y) {
    uint32_t j = f.lit.row_begin[size_t(y)];
    for (uint32_t i = f.points.row_begin[size_t(y)]; i < f.points.row_begin[size_t(y) + 1]; ++i) {
      while (f.lit.hi[j] <= f.points.lo[i]) ++j;
      const uint32_t c = f.lit_labels.of_run[j];
      f.point_region[i] = c;
      f.lit_regions[c].point_pixels += f.points.hi[i] - f.points.lo[i];
    }
  }
  f.air = air_layer_of(f.solid);
  f.mask = std::move(mask);
  return f;
}

}  // namespace slicereuse
