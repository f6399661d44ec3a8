#pragma once
// pillar_path: whether a support's way down is blocked by the part, by vertical rays.
//
// find_way_down looks below a support point at (x, y, z) for a pillar of pillar_radius: the
// axis ray from just under the point (the point's own face is not a hit), and rays at kRimRays
// points on the circle kPillarMarginMm outside the pillar and on the circle kRimClearanceMm
// outside it (the rim) from z_head_bottom (the head, narrower than the pillar, lies within those
// circles too; below the point a sloping surface of its own may lie within the rim above the
// head's bottom: the head zone covers that). A hit is a crossing of any face strictly between
// z_floor and the ray's start; a rim ray starting inside the part (within the clearance, beside
// the pillar) counts only the hits below where it leaves the part: what it starts in lies
// beside the pillar, not under it (where it reaches under it, the inner circle's rays meet it),
// and its underside would be taken for a floor. pillar_in_part: whether the pillar's section at
// z_head_bottom, with its margin, meets the part (a point of the inner circle, of the circle of
// half the pillar's radius, or the centre, inside it): then no pillar fits there (a groove
// narrower than it, a wall beside the head's back).

#include "part_columns.h"

namespace slicereuse {

// The rim rays run this far outside the pillar: 0.1 mm between pillar and part, plus a mask
// pixel (0.05 mm) so that the pillar's section never lights a pixel of the part's. Bridges keep
// the same clearance (bridge_path.h).
constexpr double kRimClearanceMm = 0.15;

// The inner rays run this far outside the pillar: a surface between two of them comes at most
// (pillar_radius + kPillarMarginMm) * (1 - cos(pi/8)) < kPillarMarginMm (for pillars up to
// 1.5 mm wide) into their circle before one sees it, so not into the pillar.
constexpr double kPillarMarginMm = 0.06;

// Rays on each circle, besides the axis: 8, so that a surface between two of them rises at most
// (pillar_radius + kRimClearanceMm) * (1 - cos(pi/8)) < 0.05 mm (a pixel) into the circle
// before one sees it.
constexpr int kRimRays = 8;

struct WayDown {
  // NaN when the way down to z_floor is clear; else the highest hit of any ray, at (blocked_x,
  // blocked_y): that ray's, the first of the axis and the circles' rays in order to reach it.
  double blocked_z;
  double blocked_x, blocked_y;
  // The axis ray's highest hit (NaN when it has none); when above z_head_bottom, the head
  // itself reaches the part below.
  double axis_z;
  // Whether the pillar's section at z_head_bottom meets the part.
  bool pillar_in_part;
};

WayDown find_way_down(const PartColumns& part, double x, double y, double z, double z_head_bottom, double z_floor,
                      double pillar_radius);

}  // namespace slicereuse
