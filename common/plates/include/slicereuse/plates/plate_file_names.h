#pragma once
// The names of a job's plate files, from one output name for all plates:
// plate_file_name(pattern, k): plate k's print file (k from 1): "_k" before the extension of
// pattern's last component ("out/plate.sl1" -> "out/plate_2.sl1"), or after a folder name
// without one ("out/masks" and "out/masks/" -> "out/masks_2").
// plate_layout_file_name(plate_file): the top-view picture written beside it, its name without
// the extension then "_layout.png" ("out/plate_2.sl1" -> "out/plate_2_layout.png",
// "out/masks_2" -> "out/masks_2_layout.png").
#include <cstddef>
#include <string>

namespace slicereuse {

std::string plate_file_name(const std::string& pattern, size_t k);

std::string plate_layout_file_name(const std::string& plate_file);

}  // namespace slicereuse
