#pragma once
// support_routes: the support structure's second stage, each head's way to what holds it
// (PrusaSlicer's classify, routing to ground and routing to the model).
//
// route_heads: takes the heads in order (not by height: points a rounding apart keep their
// order, and so their structure) and gives each its rest:
//   - the part, when the part below is nearer than the head's width (ways[h].axis_z above its
//     full width's bottom): the head's back moves down into the part, head_penetration_mm deep
//     or halfway through a thinner wall (depth_in_wall), not below floor nor its full width;
//     or, when no pillar fits under it (ways[h].pillar_in_part: its back's section already meets
//     the part beside it, a groove narrower than the pillar), its back where it is;
//   - a bridge to a pillar on the ground of an earlier head (PrusaSlicer's connect_to_nearpillar): from
//     the head's back, or from a pillar of its own down to where the bridge starts, to the
//     pillar's axis, descending at critical_angle_deg, at most max_bridge_length_mm long, ending
//     on the pillar above its base, on a pillar with fewer than max_bridges_on_pillar such
//     bridges, clear of the part (bridge_is_clear), and taking less resin than a pillar of its own
//     with its base, or its way down blocked; of those, the one taking least resin;
//   - else a pillar to floor on a base cone (base_diameter_mm, base_height_mm at most up to the
//     head); where the way down is blocked, a pillar ending on the part in a foot: a small head
//     upside down from 1 mm above the highest hit (but not above the head's back) into the part
//     at that hit, as deep as a head goes into the part there (depth_in_wall; not below floor).
// Fills the pillars, feet, junctions and bridges in the heads' order.
#include <vector>

#include "pillar_path.h"
#include "slicereuse/supports/support_points.h"
#include "slicereuse/supports/support_tree.h"

namespace slicereuse {

void route_heads(const PartColumns& columns, const SupportPoints& points, const std::vector<WayDown>& ways,
                 double floor, const SupportTreeOptions& options, SupportStructure& s);

}  // namespace slicereuse
