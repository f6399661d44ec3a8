#pragma once
// read_mask_stack: what the mask_stack fuzz target calls, since MaskStack (mask_stack.h) has no
// read_X function of its own: opens the stack at path, then reads and decodes every layer, as
// compare_mask_stacks does. Its seeds are .goo files and an Anycubic .pm5s (its previews cut
// out); fuzz inputs have no extension, and MaskStack knows a .goo by its magic and an Anycubic
// file by its "ANYCUBIC" (an input whose magic is mutated away is tried as a zip).
#include <cstdint>
#include <string>
#include <vector>

#include "mask_stack.h"

namespace slicereuse {

inline void read_mask_stack(const std::string& path) {
  MaskStack stack(path);
  std::vector<uint8_t> bytes;
  MaskImage image;
  for (size_t k = 0; k < stack.layers(); ++k) {
    stack.read(k, bytes);
    stack.decode(k, bytes, image);
  }
}

}  // namespace slicereuse
