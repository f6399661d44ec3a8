#pragma once
// pillar_path: whether a support's way down is blocked by the part, by vertical rays.
//
// find_way_down looks below a support point at (x, y, z): the axis ray from just under the
// point (the point's own face is not a hit), and rays at kRimRays points on the circle of
// rim_radius around the axis from z_head_bottom (the head, narrower than the pillar, lies
// within that circle too; below the point a sloping surface of its own may lie within the rim
// above the head's bottom: the head zone covers that). A hit is a crossing of any face strictly
// between z_floor and the ray's start.

#include "part_columns.h"

namespace slicereuse {

// The rim rays run this far outside the pillar: 0.1 mm between pillar and part, plus a mask
// pixel (0.05 mm) so that the pillar's section never lights a pixel of the part's. Bridges keep
// the same clearance (bridge_path.h).
constexpr double kRimClearanceMm = 0.15;

// Rays on the rim, besides the axis: 8, so that a surface between two of them rises at most
// rim_radius * (1 - cos(pi/8)) < 0.05 mm (a pixel) into the circle before one sees it.
constexpr int kRimRays = 8;

struct WayDown {
  // NaN when the way down to z_floor is clear; else the highest hit of any ray, at (blocked_x,
  // blocked_y): that ray's, the first of the axis and the rim rays in order to reach it.
  double blocked_z;
  double blocked_x, blocked_y;
  // The axis ray's highest hit (NaN when it has none); when above z_head_bottom, the head
  // itself reaches the part below.
  double axis_z;
};

WayDown find_way_down(const PartColumns& part, double x, double y, double z, double z_head_bottom, double z_floor,
                      double rim_radius);

}  // namespace slicereuse
