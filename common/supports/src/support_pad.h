#pragma once
// support_pad: the pad under the pillars that reach the ground, as one closed shell: a slab from
// z_bottom to z_top whose outline is the convex hull of the circles of radius r_bottom around
// the pillars' axes (x-y) at the bottom and of radius r_top at the top (r_top < r_bottom slopes
// its walls inwards). Both outlines are the Minkowski sum of the axes' convex hull and a
// kSupportSides-gon of that radius: they have the same corners, pair by pair (each corner is an
// axis of the hull plus a corner of the polygon), so the walls are quads.
#include <array>
#include <vector>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

// axes: at least one (x, y); r_bottom and r_top > 0.
void append_pad(Mesh& mesh, const std::vector<std::array<double, 2>>& axes, double r_bottom, double r_top,
                double z_bottom, double z_top);

}  // namespace slicereuse
