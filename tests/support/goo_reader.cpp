#include "goo_reader.h"

#include <cstring>
#include <stdexcept>

namespace slicereuse::test {
namespace {

// The file's bytes, read front to back; every number big-endian.
struct Cursor {
  const std::string& b;
  size_t at = 0;

  const uint8_t* take(size_t n, const char* what) {
    if (n > b.size() || at > b.size() - n)
      throw std::runtime_error(std::string("truncated: ") + what + " at byte " + std::to_string(at));
    const uint8_t* p = reinterpret_cast<const uint8_t*>(b.data()) + at;
    at += n;
    return p;
  }
  uint32_t be(size_t n, const char* what) {
    const uint8_t* p = take(n, what);
    uint32_t v = 0;
    for (size_t i = 0; i < n; ++i) v = v << 8 | p[i];
    return v;
  }
  uint8_t u8(const char* what) { return uint8_t(be(1, what)); }
  uint16_t u16(const char* what) { return uint16_t(be(2, what)); }
  uint32_t u32(const char* what) { return be(4, what); }
  float f32(const char* what) {
    const uint32_t bits = be(4, what);
    float f;
    std::memcpy(&f, &bits, 4);
    return f;
  }
  bool flag(const char* what) {
    const uint8_t v = u8(what);
    if (v > 1) throw std::runtime_error(std::string(what) + " is " + std::to_string(v) + ", not 0 or 1");
    return v == 1;
  }
  // A string field: its bytes up to the first zero.
  std::string text(size_t n, const char* what) {
    const char* p = reinterpret_cast<const char*>(take(n, what));
    return std::string(p, strnlen(p, n));
  }
  void expect(const std::vector<uint8_t>& fixed, const char* what) {
    const uint8_t* p = take(fixed.size(), what);
    if (std::memcmp(p, fixed.data(), fixed.size()) != 0)
      throw std::runtime_error(std::string("wrong ") + what + " at byte " + std::to_string(at - fixed.size()));
  }
};

const std::vector<uint8_t> kDelimiter = {0x0d, 0x0a};

std::vector<uint16_t> preview(Cursor& c, size_t side, const char* what) {
  std::vector<uint16_t> px(side * side);
  for (uint16_t& p : px) p = c.u16(what);
  c.expect(kDelimiter, "preview delimiter");
  return px;
}

// The image data of one layer: 0x55, chunks, checksum.
std::vector<uint8_t> decode(const uint8_t* d, size_t n, size_t pixels, const std::string& layer) {
  if (n < 2) throw std::runtime_error(layer + ": image data of " + std::to_string(n) + " bytes");
  if (d[0] != 0x55) throw std::runtime_error(layer + ": image data does not start with 0x55");
  uint8_t sum = 0;
  for (size_t i = 1; i + 1 < n; ++i) sum = uint8_t(sum + d[i]);
  if (uint8_t(~sum) != d[n - 1]) throw std::runtime_error(layer + ": checksum mismatch");
  std::vector<uint8_t> out;
  out.reserve(pixels);
  int value = -1;  // the previous pixel's value; none before the first chunk
  size_t i = 1;
  const size_t end = n - 1;
  auto byte = [&]() -> uint32_t {
    if (i >= end) throw std::runtime_error(layer + ": chunk cut off by the checksum");
    return d[i++];
  };
  while (i < end) {
    const uint32_t b0 = byte();
    const uint32_t kind = b0 >> 6, bits54 = b0 >> 4 & 3, low = b0 & 0xf;
    uint64_t run = 0;
    if (kind == 2) {  // diff from the previous pixel; bit 5: negative, bit 4: run-length in byte 1
      if (value < 0) throw std::runtime_error(layer + ": diff chunk before any pixel");
      value += (bits54 & 2) ? -int(low) : int(low);
      if (value < 0 || value > 255) throw std::runtime_error(layer + ": diff leaves 0..255");
      run = (bits54 & 1) ? byte() : 1;
    } else {
      if (kind == 0) value = 0;
      if (kind == 3) value = 255;
      if (kind == 1) {
        value = int(byte());
        if (value == 0 || value == 255) throw std::runtime_error(layer + ": grey chunk of level " + std::to_string(value));
      }
      // bits 5-4: how many bytes, most significant first, come above the low 4 bits
      run = 0;
      for (uint32_t k = 0; k < bits54; ++k) run = run << 8 | byte();
      run = run << 4 | low;
    }
    if (run == 0) throw std::runtime_error(layer + ": empty run at byte " + std::to_string(i));
    if (run > pixels - out.size()) throw std::runtime_error(layer + ": more pixels than the image holds");
    out.insert(out.end(), size_t(run), uint8_t(value));
  }
  if (out.size() != pixels)
    throw std::runtime_error(layer + ": " + std::to_string(out.size()) + " of " + std::to_string(pixels) + " pixels");
  return out;
}

}  // namespace

SpecGoo read_goo_per_spec(const std::string& bytes) {
  SpecGoo g;
  Cursor c{bytes};
  g.version = c.text(4, "version");
  c.expect({0x07, 0x00, 0x00, 0x00, 0x44, 0x4c, 0x50, 0x00}, "magic");
  g.software = c.text(32, "software info");
  g.software_version = c.text(24, "software version");
  g.file_time = c.text(24, "file time");
  g.printer_name = c.text(32, "printer name");
  g.printer_type = c.text(32, "printer type");
  g.profile_name = c.text(32, "profile name");
  g.antialiasing_level = c.u16("anti-aliasing level");
  g.grey_level = c.u16("grey level");
  g.blur_level = c.u16("blur level");
  g.small_preview = preview(c, 116, "small preview");
  g.big_preview = preview(c, 290, "big preview");
  g.layer_count = c.u32("total layers");
  g.x_resolution = c.u16("x resolution");
  g.y_resolution = c.u16("y resolution");
  g.x_mirror = c.flag("x mirror");
  g.y_mirror = c.flag("y mirror");
  g.x_size = c.f32("x size");
  g.y_size = c.f32("y size");
  g.z_size = c.f32("z size");
  g.layer_thickness = c.f32("layer thickness");
  g.exposure = c.f32("exposure");
  g.delay_mode_static = c.flag("exposure delay mode");
  g.turn_off_time = c.f32("turn off time");
  for (float& w : g.waits) w = c.f32("wait times");
  g.bottom_exposure = c.f32("bottom exposure");
  g.bottom_layers = c.u32("bottom layers");
  for (float& m : g.moves) m = c.f32("lift and retract");
  g.bottom_pwm = c.u16("bottom light PWM");
  g.pwm = c.u16("light PWM");
  g.advance_mode = c.flag("advance mode");
  g.print_time = c.u32("printing time");
  g.volume = c.f32("total volume");
  g.weight = c.f32("total weight");
  g.price = c.f32("total price");
  g.price_unit = c.text(8, "price unit");
  g.layer_content_offset = c.u32("offset of layer content");
  g.grey_scale_256 = c.flag("gray scale level");
  g.transition_layers = c.u16("transition layers");
  if (g.layer_content_offset != c.at)
    throw std::runtime_error("layer content offset " + std::to_string(g.layer_content_offset) +
                             ", but the header ends at " + std::to_string(c.at));
  const size_t pixels = size_t(g.x_resolution) * g.y_resolution;
  for (uint32_t k = 0; k < g.layer_count; ++k) {
    const std::string name = "layer " + std::to_string(k);
    SpecGooLayer l;
    l.pause = c.u16("pause flag");
    l.pause_z = c.f32("pause position");
    l.z = c.f32("layer position");
    l.exposure = c.f32("layer exposure");
    l.off_time = c.f32("layer off time");
    l.before_lift = c.f32("before lift time");
    l.after_lift = c.f32("after lift time");
    l.after_retract = c.f32("after retract time");
    for (float& m : l.moves) m = c.f32("layer lift and retract");
    l.pwm = c.u16("layer light PWM");
    c.expect(kDelimiter, "layer definition delimiter");
    l.data_size = c.u32("data size");
    const uint8_t* data = c.take(l.data_size, "image data");
    l.pixels = decode(data, l.data_size, pixels, name);
    c.expect(kDelimiter, "layer delimiter");
    g.layers.push_back(std::move(l));
  }
  c.expect({0x00, 0x00, 0x00, 0x07, 0x00, 0x00, 0x00, 0x44, 0x4c, 0x50, 0x00}, "ending string");
  if (c.at != bytes.size()) throw std::runtime_error(std::to_string(bytes.size() - c.at) + " bytes after the ending");
  return g;
}

}  // namespace slicereuse::test
