#pragma once
// support_pad: the support structure's last stage, the pad under the pillars on the ground
// (PrusaSlicer's pad, raised: no part sunk into it).
//
// place_pad (when options.pad_enable and a pillar stands on the ground): a slab from ground_z
// to pad_wall_thickness_mm above it whose outline is the convex hull of the circles around the
// pillars' axes (x-y) of radius base + pad_brim_mm at the top and smaller by the walls' inset,
// thickness / tan(pad_wall_slope_deg), at the bottom. Both outlines are the Minkowski sum of the
// axes' convex hull and a kSupportSides-gon of that radius: they have the same corners, pair by
// pair (each corner is an axis of the hull plus a corner of the polygon), so the walls are quads.
#include "slicereuse/supports/support_tree.h"

namespace slicereuse {

void place_pad(const SupportTreeOptions& options, double ground_z, SupportStructure& s);

}  // namespace slicereuse
