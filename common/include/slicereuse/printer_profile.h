#pragma once
// validate_printer_profile: throws Error naming the bad field when a PrinterProfile (masks.h)
// cannot be rasterized: display size outside 1..65535 px per side, a pixel size that is not a
// positive finite number, or a non-finite offset. Exporters call it before creating any output.
#include "slicereuse/masks.h"

namespace slicereuse {

void validate_printer_profile(const PrinterProfile& profile);

}  // namespace slicereuse
