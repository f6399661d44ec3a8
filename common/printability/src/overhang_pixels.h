#pragma once
// overhang_pixels: a layer and the layer below -> the layer's overhanging pixels as UVtools finds
// them: the pixels brighter than below by more than 127 (the layer minus the one below,
// thresholded), eroded ErodeIterations (40) times by a 3x3 cross, i.e. kept when every pixel
// within L1 distance 40 is one too. Erosion works inside the union of the two layers' bounding
// boxes (UVtools crops both to it and reflects at its border, which never erodes: a pixel
// mirrored across the border is farther than the pixel it mirrors).
// In: both masks as runs of levels (same size) with the box of their pixels > 0 and their runs
// of pixels >= 101 and >= 150 (the checks' levels, which bound the pixels >= 128 the overhangs
// start from); out: runs (level_runs.h).
// Time: the lit runs, plus a distance transform over the box of the pixels with 40 brighter
// pixels on either side in their row (and 41 pixels around it): none where the layer only
// shrinks, repeats or widens by thin rims the layer below.
#include "level_runs.h"
#include "slicereuse/png/mask_png.h"

namespace slicereuse {

struct LayerRuns {
  const MaskRuns* mask = nullptr;
  const PixelBox* nonzero_box = nullptr;
  const LevelRuns* solid = nullptr;    // pixels >= 101
  const LevelRuns* support = nullptr;  // pixels >= 150
};

LevelRuns overhang_pixels(const LayerRuns& layer, const LayerRuns& below);

}  // namespace slicereuse
