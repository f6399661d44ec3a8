#pragma once
// What the print file tests (test_goo.cpp, test_ctb.cpp, test_photon_workshop.cpp) share: the
// layers they export, a display, a file's bytes and its little-endian fields, and a stack's every layer
// through MaskStack.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "mask_layers.h"
#include "mask_stack.h"

namespace slicereuse::test {

// Holes, thin walls (1.5 and 0.5 pixels wide at 100 um), a star, an empty layer, and a part
// that runs off the display.
inline std::vector<Layer> part_layers() {
  return {{rect(-5, -5, 5, 5), rect(-2, -2, 2, 2, true)},
          {rect(-6, -6, 6, 6), rect(-5.85, -5.85, 5.85, 5.85, true), rect(-0.025, -4, 0.025, 4)},
          {star(0.3, -0.2, 3, 7.5, 9), rect(-1, -1, 1, 1, true)},
          {},
          {rect(-12, -3, 3.33, 2.71), rect(-1.1, -0.9, 0.7, 1.3, true)}};
}

// 240 x 160 pixels of 80 x 120 um, mirrored both ways, off centre: nothing symmetric to hide a
// swapped axis or flip.
inline PrinterProfile mirrored_display() {
  PrinterProfile p;
  p.width_px = 240;
  p.height_px = 160;
  p.pixel_size_x_um = 80;
  p.pixel_size_y_um = 120;
  p.mirror_x = true;
  p.mirror_y = true;
  p.offset_x_mm = 0.37;
  p.offset_y_mm = -1.21;
  return p;
}

inline std::string read_bytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

inline void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

inline uint32_t le32(const std::string& b, size_t at) {
  uint32_t v = 0;
  for (size_t i = 4; i-- > 0;) v = v << 8 | uint8_t(b[at + i]);
  return v;
}

inline uint16_t le16(const std::string& b, size_t at) { return uint16_t(uint8_t(b[at]) | uint8_t(b[at + 1]) << 8); }

inline float f32(const std::string& b, size_t at) {
  const uint32_t bits = le32(b, at);
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

// Every layer of the stack at path, decoded.
inline std::vector<MaskImage> read_stack(const std::string& path) {
  MaskStack stack(path);
  std::vector<MaskImage> images(stack.layers());
  std::vector<uint8_t> bytes;
  for (size_t k = 0; k < stack.layers(); ++k) {
    stack.read(k, bytes);
    stack.decode(k, bytes, images[k]);
  }
  return images;
}

}  // namespace slicereuse::test
