#pragma once
// grey_levels: the grey levels a printer's file can hold, as its readers decode them
// (printer_profile.h's grey_levels):
//   256  every level 0..255 (PNG, .sl1, .goo)
//   128  Chitubox .ctb: a 7-bit code c, read as 0 for c = 0 and 2c + 1 otherwise (0, 3, 5, ..., 255)
//   16   Anycubic Photon Workshop (pw0Img): a 4-bit code c, read as 17c (0, 17, ..., 255)
// representable_grey_level(level, grey_levels) -> the level of those nearest to level (the lower
// of two as near); 0 and 255 stay. grey_levels must be one of the three (validate_printer_profile).
#include <cstdint>

namespace slicereuse {

uint8_t representable_grey_level(uint8_t level, int grey_levels);

}  // namespace slicereuse
