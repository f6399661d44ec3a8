#pragma once
// Readers for CLI and SLC written straight from the two specifications, independent of the
// core's reader and writer (they share no code with common/), so that tests check the files
// against the formats themselves. Small and strict: they read what the specifications define
// (CLI: ASCII with one command per line, or binary long format; SLC: the whole file) and
// throw std::runtime_error on anything else. Values are kept as stored (file units, float32).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace slicereuse::test {

struct SpecCliPolyline {
  int32_t id = 0, dir = 0;
  std::vector<double> xy;  // 2n values as in the file
};
struct SpecCliLayer {
  double z = 0;
  std::vector<SpecCliPolyline> polylines;
};
struct SpecCli {
  bool binary = false;
  std::vector<std::string> header_lines;  // "$$..." lines between $$HEADERSTART and $$HEADEREND
  double units = 0;
  int version = 0;
  std::string date;
  std::vector<double> dimension;  // x1, y1, z1, x2, y2, z2
  long layers = -1;               // $$LAYERS
  std::vector<SpecCliLayer> geometry;
};
SpecCli read_cli_per_spec(const std::string& bytes);

struct SpecSlcLayer {
  float z = 0;
  std::vector<std::vector<std::array<float, 2>>> boundaries;  // vertices as stored
  std::vector<uint32_t> gaps;
};
struct SpecSlc {
  std::string header;                        // without the 0D 0A 1A terminator
  std::vector<std::array<float, 4>> samples; // min z, thickness, line width comp., reserved
  std::vector<SpecSlcLayer> layers;
  float end_z = 0;                           // z of the termination record
};
SpecSlc read_slc_per_spec(const std::string& bytes);

}  // namespace slicereuse::test
