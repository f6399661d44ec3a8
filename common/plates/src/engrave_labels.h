#pragma once
// engrave_part: a part of the plate's layers (export_masks.h) whose layer 0 is its member's own
// layer own_first, and the member's label (base_label.h) -> each layer the label cuts as its
// region less the label's (layer_region.h), the others as they were, in one Slices as before
// (no encoding). On the contours, before the masks are drawn, so that a reused member's
// labelled masks are direct slicing's.
#include "slicereuse/plates/base_label.h"
#include "slicereuse/printfiles/export_masks.h"

namespace slicereuse {

void engrave_part(SlicePart& part, size_t own_first, const BaseLabel& label);

}  // namespace slicereuse
