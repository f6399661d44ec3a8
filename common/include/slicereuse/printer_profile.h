#pragma once
// validate_printer_profile: throws Error naming the bad field when a PrinterProfile (masks.h)
// cannot be rasterized: display size outside 1..kMaxDisplayPixels px per side, a pixel size
// that is not a positive finite number, or a non-finite offset. Exporters call it before
// creating any output.
#include "slicereuse/masks.h"

namespace slicereuse {

// Largest display side, in pixels, accepted by the core and by the mask filters' parameters.
constexpr int kMaxDisplayPixels = 65535;

void validate_printer_profile(const PrinterProfile& profile);

}  // namespace slicereuse
