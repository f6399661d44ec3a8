#pragma once
// Labels engraved into members' bases (#36): each member's own first layers lose the region of
// its label, placed on the base they share and mirrored to read from below (place_label.h), on
// the contours, before the masks are drawn, so that a reused member's labelled masks are direct
// slicing's.
//
// label_engraving: a member's first layers (from its own layer 0, as many as the depth reaches:
// engraved_layers) and its label -> the engraving: the layers it cuts and the label's region on
// the base, those layers' common region; not placed (0 layers) when it fits at no height.
// engrave_part: a part of the plate's layers (export_masks.h) whose layer 0 is its member's own
// layer own_first -> each layer below the engraving's depth as its region less the label's
// (layer_region.h), the others as they were, in one Slices as before (no encoding).
#include <clipper.hpp>
#include <string>

#include "slicereuse/plates/plate_job.h"
#include "slicereuse/regions/place_label.h"
#include "slicereuse/slicing/slices.h"

namespace slicereuse {

struct Engraving {
  size_t layers = 0;  // its own layers [0, layers) are cut
  LabelPlacement placement;
};

size_t engraved_layers(double depth_mm, double thickness_mm, size_t member_layers);
Engraving label_engraving(const Slices& first_layers, const std::string& text, const LabelOptions& o);
void engrave_part(SlicePart& part, size_t own_first, const Engraving& e);

}  // namespace slicereuse
