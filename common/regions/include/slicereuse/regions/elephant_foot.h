#pragma once
// elephant_foot: a layer shrunk against elephant-foot spread (PrusaSlicer's
// elefant_foot_compensation and elefant_foot_min_width; faded_layers.h gives each of an object's
// first layers its compensation): the layer's region (layer_region.h)
// offset inwards by compensation_mm (miter joins), except where that would make a feature
// narrower than min_width_mm: such features (those an opening by min_width_mm / 2 +
// compensation_mm removes, at least 10 um wide: thinner slivers are the opening's rounding along
// the boundary) keep their own width, unshrunk, with a collar of compensation_mm
// into the rest of the region, so that they stay joined to it. The result replaces the layer's
// contours, so binary and anti-aliased masks agree.
// Output: out replaced by one layer at height z (region_into_layer). compensation_mm 0 copies
// the region unchanged. Throws Error for a negative or non-finite compensation or width.
#include "slicereuse/slicing/layer_view.h"
#include "slicereuse/slicing/slices.h"

namespace slicereuse {

void compensate_elephant_foot(const LayerView& layer, double z, double compensation_mm, double min_width_mm,
                              Slices& out);

}  // namespace slicereuse
