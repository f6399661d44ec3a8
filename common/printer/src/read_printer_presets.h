#pragma once
// read_printer_presets(text, name): the presets a presets.json text describes (common/printer/
// presets.json: "presets", a list of {id, name, extension (one of "formats", or "" for PNG images), display {width_px, height_px,
// pixel_x_um, pixel_y_um, portrait, mirror_x, mirror_y}, antialiasing, job {model, exposure_s,
// bottom_exposure_s, bottom_layers, faded_layers, layer_move_s}}), in the file's order; gamma 1
// and no offsets in every profile, other keys ("about", "note") ignored. name says where the
// text is from in messages. Throws Error naming the preset and the key of a missing key, a
// value of the wrong type or a count that is not a whole number, an id given twice, no presets,
// or a profile validate_printer_profile refuses.
#include <string>
#include <vector>

#include "slicereuse/printer/print_formats.h"
#include "slicereuse/printer/printer_presets.h"

namespace slicereuse::detail {

std::vector<PrinterPreset> read_printer_presets(const std::string& text, const std::string& name);

// The print formats the same text lists ("formats": {extension, name, grey_levels}). Throws
// Error naming the format of a missing key, an extension that is not a dot and lower-case
// letters and digits, one given twice, or grey levels other than 16, 128 or 256.
std::vector<PrintFormat> read_print_formats(const std::string& text, const std::string& name);

}  // namespace slicereuse::detail
