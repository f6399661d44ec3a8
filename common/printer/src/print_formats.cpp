#include "slicereuse/printer/print_formats.h"

#include <algorithm>

#include "presets_json.h"
#include "read_printer_presets.h"

namespace slicereuse {

const std::vector<PrintFormat>& print_formats() {
  // Read once, on first use, from the text compiled in (printer/CMakeLists.txt).
  static const std::vector<PrintFormat> formats =
      detail::read_print_formats(kPresetsJson, "common/printer/presets.json");
  return formats;
}

const PrintFormat* print_format(const std::string& extension) {
  for (const PrintFormat& f : print_formats())
    if (f.extension == extension) return &f;
  return nullptr;
}

PrinterProfile profile_for_format(const PrinterProfile& p, const PrintFormat* format) {
  PrinterProfile q = p;
  if (format) q.grey_levels = std::min(q.grey_levels, format->grey_levels);
  return q;
}

}  // namespace slicereuse
