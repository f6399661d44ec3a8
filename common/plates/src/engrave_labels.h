#pragma once
// engrave_part: a part of the plate's layers (export_masks.h) whose layer 0 is its member's own
// layer own_first, and what the member's label cuts (a LabelCut) -> each layer the label cuts as
// its region less the cut (layer_region.h), the others as they were, in one Slices as before
// (no encoding). On the contours, before the masks are drawn, so that a reused member's
// labelled masks are direct slicing's.
// LabelCut: the member's own layers [first, first + layers) lose regions[0] each when it holds
// one region (a base label's letters, base_label.h), else layer j regions[j - first] (a side
// label's bands, side_label.h; an empty one cuts nothing); with skin_mm > 0, only what of it
// lies within skin_mm of the layer's outside (its outer loops: a cavity is not outside).
#include <clipper.hpp>
#include <vector>

#include "slicereuse/printfiles/export_masks.h"

namespace slicereuse {

struct LabelCut {
  size_t first = 0, layers = 0;
  std::vector<ClipperLib::Paths> regions;
  double skin_mm = 0;
};

void engrave_part(SlicePart& part, size_t own_first, const LabelCut& label);

}  // namespace slicereuse
