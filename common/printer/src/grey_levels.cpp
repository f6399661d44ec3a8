#include "slicereuse/printer/grey_levels.h"

#include <cstdlib>

namespace slicereuse {
namespace {

// Whether a reader of a file with that many levels can give level.
bool decodes_to(int level, int grey_levels) {
  if (grey_levels == 128) return level == 0 || (level % 2 == 1 && level >= 3);
  if (grey_levels == 16) return level % 17 == 0;
  return true;
}

}  // namespace

uint8_t representable_grey_level(uint8_t level, int grey_levels) {
  for (int d = 0;; ++d) {  // 0 and 255 are representable: ends within 17 steps
    if (level - d >= 0 && decodes_to(level - d, grey_levels)) return uint8_t(level - d);
    if (level + d <= 255 && decodes_to(level + d, grey_levels)) return uint8_t(level + d);
  }
}

}  // namespace slicereuse
