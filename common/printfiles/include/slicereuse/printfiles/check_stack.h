#pragma once
// check_stack: UVtools' printability checks (check_layers.h) of the masks a stack of layers would
// print with, without writing them: a stack in parts (export_masks.h's SlicePart: layer k's
// contours are those of every part that has it), each layer rasterized for profile (binary or
// anti-aliased, as rasterize_layer.h draws it, with the profile's pixel size) on all cores a batch
// at a time, and checked in order, the stack's layer thickness giving heights and volumes.
// What Check Printability does with a mesh or a contour layer. Throws Error for an invalid
// profile, a part whose points are not finite, or no layers; Cancelled when progress says so.
#include <cstddef>
#include <vector>

#include "slicereuse/printability/printability_report.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/printfiles/export_masks.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

PrintabilityReport check_stack(const std::vector<SlicePart>& parts, size_t layers, double thickness,
                               const PrinterProfile& profile, const Progress& progress = {});

}  // namespace slicereuse
