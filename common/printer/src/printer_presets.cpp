#include "slicereuse/printer/printer_presets.h"

#include "presets_json.h"
#include "read_printer_presets.h"
#include "slicereuse/util/error.h"

namespace slicereuse {

const std::vector<PrinterPreset>& printer_presets() {
  // Read once, on first use, from the text compiled in (printer/CMakeLists.txt).
  static const std::vector<PrinterPreset> presets =
      detail::read_printer_presets(kPresetsJson, "common/printer/presets.json");
  return presets;
}

const PrinterPreset& printer_preset(const std::string& id) {
  std::string ids;
  for (const PrinterPreset& p : printer_presets()) {
    if (p.id == id) return p;
    ids += (ids.empty() ? "" : ", ") + p.id;
  }
  throw Error("no printer profile named '" + id + "' (the profiles are: " + ids + ")");
}

}  // namespace slicereuse
