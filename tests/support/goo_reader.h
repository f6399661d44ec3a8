#pragma once
// A reader for Elegoo .goo files written straight from Elegoo's "Goo Format Spec V1.2"
// (github.com/elegooofficial/GOO), independent of the core's writer and reader (it shares no
// code with common/), so that tests check written files against the format itself. It reads the
// whole file: the header field by field (both magics, delimiters, the layer content offset),
// every layer's definition, data size, image data and delimiter, and the ending; it checks each
// layer's 0x55 magic and checksum (the complement of the byte sum of the chunks, the magic and
// the checksum itself excluded, as the open-source implementations agree) and decodes its
// run-length chunks into exactly X resolution x Y resolution pixels. Strict: grey chunks must
// hold a level in 0x01..0xFE, runs must not be empty, a diff must stay within 0..255. Anything
// else throws std::runtime_error naming what and where (the layer). Numbers as stored (float32).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace slicereuse::test {

struct SpecGooLayer {
  uint16_t pause = 0;
  float pause_z = 0, z = 0, exposure = 0, off_time = 0;
  float before_lift = 0, after_lift = 0, after_retract = 0;
  // lift distance, speed, second lift distance, speed, retract distance, speed, second retract
  // distance, speed
  std::array<float, 8> moves{};
  uint16_t pwm = 0;
  uint32_t data_size = 0;
  std::vector<uint8_t> pixels;  // x_resolution * y_resolution, row-major
};

struct SpecGoo {
  std::string version, software, software_version, file_time, printer_name, printer_type, profile_name;
  uint16_t antialiasing_level = 0, grey_level = 0, blur_level = 0;
  std::vector<uint16_t> small_preview, big_preview;  // 116 x 116, 290 x 290 RGB565
  uint32_t layer_count = 0;
  uint16_t x_resolution = 0, y_resolution = 0;
  bool x_mirror = false, y_mirror = false;
  float x_size = 0, y_size = 0, z_size = 0, layer_thickness = 0, exposure = 0;
  bool delay_mode_static = false;
  float turn_off_time = 0;
  // bottom before lift, after lift, after retract; then the same for other layers
  std::array<float, 6> waits{};
  float bottom_exposure = 0;
  uint32_t bottom_layers = 0;
  // bottom lift distance, speed, lift distance, speed, bottom retract distance, speed, retract
  // distance, speed, then the same 8 for the second stages
  std::array<float, 16> moves{};
  uint16_t bottom_pwm = 0, pwm = 0;
  bool advance_mode = false;
  uint32_t print_time = 0;
  float volume = 0, weight = 0, price = 0;
  std::string price_unit;
  uint32_t layer_content_offset = 0;
  bool grey_scale_256 = false;
  uint16_t transition_layers = 0;
  std::vector<SpecGooLayer> layers;
};

SpecGoo read_goo_per_spec(const std::string& bytes);

}  // namespace slicereuse::test
