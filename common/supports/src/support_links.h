#pragma once
// support_links: the support structure's third stage, links between tall pillars (PrusaSlicer's
// interconnect_pillars, its zig-zag mode, the SL1S profile's).
//
// link_tall_pillars: each pillar on the ground (in order) taller than kMaxSoloPillarMm needs one
// link to another pillar on the ground, taller than kMaxDualPillarMm two; it takes its nearest
// (then the first) not yet linked to it, between 2 pillar radii and max_pillar_link_distance_mm
// away, until it has them. A link is bridges zig-zagging down between the two pillars at
// critical_angle_deg: the first from the lower of their tops, each ending on the other pillar,
// the last above both bases; only those clear of the part (bridge_is_clear) are built, and the
// link counts when one is. The pillars linked to count their links too.
#include "part_columns.h"
#include "slicereuse/supports/support_tree.h"

namespace slicereuse {

// PrusaSlicer's max_solo_pillar_height_mm and max_dual_pillar_height_mm.
constexpr double kMaxSoloPillarMm = 15;
constexpr double kMaxDualPillarMm = 35;

void link_tall_pillars(const PartColumns& columns, const SupportTreeOptions& options, SupportStructure& s);

}  // namespace slicereuse
