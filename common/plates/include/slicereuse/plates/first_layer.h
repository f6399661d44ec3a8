#pragma once
// compensate_first_layer: a stack's layer 0 shrunk against elephant foot (elephant_foot.h), for
// every print file: the parts (export_masks.h) that hold layer 0 (first 0), all together,
// replaced by one part of the compensated contours at plane z0 (its slab from bottom0, of
// thickness), followed by the rest of their layers copied out (first 1); parts starting later are
// kept as they are. Nothing changes when profile.elephant_foot_mm is 0.
#include <vector>

#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/printfiles/export_masks.h"

namespace slicereuse {

void compensate_first_layer(std::vector<SlicePart>& parts, const PrinterProfile& profile, double z0, double bottom0,
                            double thickness);

}  // namespace slicereuse
