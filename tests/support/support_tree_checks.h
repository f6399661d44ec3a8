#pragma once
// support_tree_checks: whether a support structure (support_tree.h) meets its part only where it
// may, checked on its public result, whatever builds it.
//
// check_tree_sections: part and tree sliced on the same planes (layer_mm apart from the tree's
// ground_z to the part's top), layer by layer: the part's and the supports' sections overlap
// only within the head zones (their circles around the 16-gons, grown by 1e-3 mm); every piece
// of the union of the supports' sections above layer 0 overlaps the layer below (supports or
// part: a foot rests on the part).
// check_feet_on_part: every foot of the structure ends on the part: the point its penetration
// (more than 0, at most head_penetration_mm) above its tip lies on the part's surface (within
// 1e-6 mm); a foot failing either counts in in_air.
#include <cstddef>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/supports/support_tree.h"

namespace slicereuse::test {

struct TreeSections {
  size_t layers = 0;
  size_t open_contours = 0;          // of the supports' slicing
  double ground_area_mm2 = 0;        // the supports' section on layer 0
  size_t overlapping_layers = 0;     // where part and supports overlap
  double outside_zones_mm2 = 0;      // the largest overlap outside the head zones in one layer
  size_t outside_zones_layer = 0;    // its layer (when outside_zones_mm2 > 0)
  double outside_zones_z = 0;
  double outside_zones_xy[2] = {0, 0};  // the centre of its largest piece's bounding box
  size_t support_islands = 0;        // pieces of the supports' sections resting on nothing
  size_t first_support_island_layer = 0;
  double first_support_island_xy[2] = {0, 0};  // the centre of its bounding box
};

TreeSections check_tree_sections(const Mesh& part, const SupportTree& tree, double layer_mm);

struct FeetOnPart {
  size_t feet = 0;
  size_t in_air = 0;          // feet off the part, or going deeper than a head
  double farthest_mm = 0;     // the largest distance of a tip from the part
  double farthest_xy[2] = {0, 0};
};

FeetOnPart check_feet_on_part(const Mesh& part, const SupportTree& tree, const SupportTreeOptions& options);

}  // namespace slicereuse::test
