#pragma once
// measure_walls: the thinnest wall of a hollowed part, measured on its masks in 3-D.
//
// Input: the part's mask stack (PNG folder or print file, MaskStack), pixel_mm wide pixels,
// layer_mm apart, and limit_mm, the farthest distance worth measuring. Output: the least distance
// from a cavity pixel's centre (unlit, enclosed in its layer) to an outside pixel's (unlit,
// joined to the image's border in its layer) of any layer, or to the empty layers beyond the
// stack (limit_mm when nothing is nearer); a wall between them is that less a pixel. Also the
// cavity's volume. The nearest pair always has its cavity pixel on the cavity's boundary, so only
// those are measured, against exact distance transforms (squared_distances.h) of the layers
// within limit_mm; memory: those layers' transforms.
#include <cmath>

#include "mask_stack.h"

namespace slicereuse::test {

struct WallMeasure {
  double thinnest_mm = INFINITY;
  double cavity_mm3 = 0;
};

WallMeasure measure_walls(MaskStack& stack, double pixel_mm, double layer_mm, double limit_mm);

}  // namespace slicereuse::test
