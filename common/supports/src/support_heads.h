#pragma once
// support_heads: the support structure's first stage, its heads (PrusaSlicer's pinheads).
//
// place_heads: for each support point whose surface does not face up (faces_up), in the
// points' order, a vertical head (support_structure.h): its tip (head_front_diameter_mm) above
// the point by head_penetration_mm, or by half the part's wall above the point where that is
// thinner than twice the penetration (the tip must not come out of its other side); its back
// (pillar_diameter_mm) head_width_mm below the point, but not below floor (the pad's top, or the
// ground without a pad), where it is as wide as the cone is there; its rest not yet decided (the
// routes stage does). And, in ways, each head's way down from head_width_mm below its point to
// floor (find_way_down, for a pillar of pillar_diameter_mm). A point gets no head when the part
// lies right under it (kBelowPointMm under it is inside the part: a wall facing sideways, not an
// overhang; a vertical head would go down through the part and end under it), or when no
// pillar fits under it (find_way_down's pillar_in_part: a groove narrower than the pillar, a
// wall beside), the head does not reach the part below, and its back's section meets no part
// beside it either: the head would hang (PrusaSlicer drops the heads it cannot route).
#include <vector>

#include "pillar_path.h"
#include "slicereuse/supports/support_points.h"
#include "slicereuse/supports/support_tree.h"

namespace slicereuse {

std::vector<SupportHead> place_heads(const PartColumns& columns, const SupportPoints& points, double floor,
                                     const SupportTreeOptions& options, std::vector<WayDown>& ways);

// How deep a head goes into a wall of the given thickness (NaN: no other side met): the
// penetration, or half the wall where that is thinner than twice it, so that it does not come
// out of the other side.
double depth_in_wall(double wall_mm, const SupportTreeOptions& options);

// The wall above or below a point: surfaces nearer than this are its own face.
constexpr double kWallEpsilonMm = 1e-6;
// Where place_heads looks whether the part lies under a point: far enough under its face that
// the face's own rounding does not count.
constexpr double kBelowPointMm = 1e-6;

// Head h's radius at height z, between its full width's bottom (head_width_mm below its point,
// the pillar's radius) and its tip.
double head_radius_at(const SupportHead& head, double z, const SupportPoints& points,
                      const SupportTreeOptions& options);

}  // namespace slicereuse
