#pragma once
// ByteFields: numbers and texts appended to a byte string as a print file's fields, in the
// file's byte order: BigEndian (.goo) or LittleEndian (.ctb). f32 stores an IEEE 754 single; text
// a field of n bytes, zero-filled (a longer text is cut).
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace slicereuse {

template <bool kBigEndian>
struct ByteFields {
  std::vector<uint8_t>& out;
  void u8(unsigned v) { out.push_back(uint8_t(v)); }
  void u16(unsigned v) {
    u8(kBigEndian ? v >> 8 : v & 0xFF);
    u8(kBigEndian ? v & 0xFF : v >> 8);
  }
  void u32(uint32_t v) {
    u16(kBigEndian ? v >> 16 : v & 0xFFFF);
    u16(kBigEndian ? v & 0xFFFF : v >> 16);
  }
  void f32(double v) {
    const float f = float(v);
    uint32_t bits;
    std::memcpy(&bits, &f, 4);
    u32(bits);
  }
  void bytes(const uint8_t* p, size_t n) { out.insert(out.end(), p, p + n); }
  void zeros(size_t n) { out.insert(out.end(), n, 0); }
  void text(const std::string& s, size_t n) {
    const size_t used = std::min(s.size(), n);
    out.insert(out.end(), s.begin(), s.begin() + long(used));
    zeros(n - used);
  }
};

using BigEndian = ByteFields<true>;
using LittleEndian = ByteFields<false>;

}  // namespace slicereuse
