#pragma once
// print_formats: the print files the product writes besides a folder of PNG images, as
// common/printer/presets.json lists them ("formats"), in its order: each file's extension (lower
// case, with its dot), what people call it, and how many grey levels it holds (grey_levels.h).
// Filters offer them, family.py's --format takes them, export_masks writes by them.
//   print_formats()           every format
//   print_format(extension)   the one with that extension (lower case, ".ctb"), or nullptr
//   profile_for_format(p, f)  p with the grey levels f holds when fewer than p's: the masks
//                             written into f are the ones its readers will see
#include <string>
#include <vector>

#include "slicereuse/printer/printer_profile.h"

namespace slicereuse {

struct PrintFormat {
  std::string extension;  // ".sl1", ".ctb", ...
  std::string name;       // "Chitubox CTB (versions 3 and 4)"
  int grey_levels = 256;
};

const std::vector<PrintFormat>& print_formats();
const PrintFormat* print_format(const std::string& extension);
PrinterProfile profile_for_format(const PrinterProfile& p, const PrintFormat* format);

}  // namespace slicereuse
