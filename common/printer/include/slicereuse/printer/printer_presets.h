#pragma once
// printer_presets: named printer profiles with the real printers' figures, so that a user picks
// a printer instead of typing its display. Each preset gives the display (pixels, pixel size,
// orientation, mirrors), the anti-aliasing gamma its own slicer uses, what its print file
// carries (printer model, exposure, bottom and faded layers), and the print file it takes.
// Offsets stay the user's (a preset centres the part). docs/formats.md, "Printer profiles",
// lists the sources. The presets are data, common/printer/presets.json (python/ reads it too),
// compiled in and read on first use.
//   printer_presets()       every preset, in the order menus show them
//   printer_preset(id)      the one named id, or Error listing the ids
#include <string>
#include <vector>

#include "slicereuse/printer/printer_profile.h"

namespace slicereuse {

struct PrinterPreset {
  std::string id;         // what filters, family.py and .mlx files name it by, e.g. "prusa_sl1s_speed"
  std::string name;       // what people call it, e.g. "Prusa SL1S Speed"
  std::string extension;  // the print file the printer takes: ".sl1", ".sl1s", ".goo", or "" (PNG folder)
  PrinterProfile profile;
};

const std::vector<PrinterPreset>& printer_presets();
const PrinterPreset& printer_preset(const std::string& id);

}  // namespace slicereuse
