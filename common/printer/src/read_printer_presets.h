#pragma once
// read_printer_presets(text, name): the presets a presets.json text describes (common/printer/
// presets.json: "presets", a list of {id, name, extension, display {width_px, height_px,
// pixel_x_um, pixel_y_um, portrait, mirror_x, mirror_y}, antialiasing, job {model, exposure_s,
// bottom_exposure_s, bottom_layers, faded_layers, layer_move_s}}), in the file's order; gamma 1
// and no offsets in every profile, other keys ("about", "note") ignored. name says where the
// text is from in messages. Throws Error naming the preset and the key of a missing key, a
// value of the wrong type or a count that is not a whole number, an id given twice, no presets,
// or a profile validate_printer_profile refuses.
#include <string>
#include <vector>

#include "slicereuse/printer/printer_presets.h"

namespace slicereuse::detail {

std::vector<PrinterPreset> read_printer_presets(const std::string& text, const std::string& name);

}  // namespace slicereuse::detail
