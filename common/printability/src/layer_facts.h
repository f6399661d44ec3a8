#pragma once
// LayerFacts: what the printability checks (check_layers.h) need of one layer that depends on
// that layer alone, so that a job computes it on the thread that made the mask, in parallel, and
// the checker's work in order is only what joins a layer to the one below.
//
// layer_facts_of: a layer's mask as runs of levels (mask_png.h) -> its facts:
//   - the runs of its pixels at the checks' levels (UVtools' thresholds, check_layers.h);
//   - the box of its pixels > 0 (overhangs erode inside the two layers' boxes);
//   - its pixels >= 127 within 5 pixels of the image's edges (touching bounds), box and count;
//   - its islands' candidates: the 4-connected regions of pixels > 1, each with its pixels, box
//     and pixels >= 10, and the region of each run of those;
//   - its air (pixels <= 100) as regions (air_regions.h).
// Thread-safe. Time: proportional to the mask's runs.
#include <cstdint>
#include <vector>

#include "air_regions.h"
#include "level_runs.h"
#include "slicereuse/png/mask_png.h"

namespace slicereuse {

// A 4-connected region of lit pixels of one layer.
struct LitRegion {
  uint64_t pixels = 0;
  uint64_t point_pixels = 0;  // >= 10: those islands count and need held
  PixelBox box;
};

struct LayerFacts {
  MaskRuns mask;
  PixelBox nonzero_box;                       // of its pixels > 0
  LevelRuns lit, points, solid, support;  // > 1, >= 10, >= 101, >= 150
  RunLabels lit_labels;                       // region of each run of lit
  std::vector<LitRegion> lit_regions;
  std::vector<uint32_t> point_region;  // region of each run of points (the lit run holding it)
  PixelBox touching_box;  // pixels >= 127 within the margin
  uint64_t touching_pixels = 0;
  AirLayer air;
};

LayerFacts layer_facts_of(MaskRuns mask);

}  // namespace slicereuse
