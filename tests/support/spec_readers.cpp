#include "spec_readers.h"

#include <cstring>
#include <sstream>
#include <stdexcept>

namespace slicereuse::test {
namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(s);
  while (std::getline(in, item, sep)) out.push_back(item);
  return out;
}

double number(const std::string& s) {
  size_t used = 0;
  const double v = std::stod(s, &used);
  if (used != s.size()) throw std::runtime_error("not a number: '" + s + "'");
  return v;
}

template <class T>
T take(const std::string& b, size_t& at) {
  if (at + sizeof(T) > b.size()) throw std::runtime_error("truncated at byte " + std::to_string(at));
  T v;
  std::memcpy(&v, b.data() + at, sizeof v);
  at += sizeof v;
  return v;
}

// Header lines are "$$NAME" or "$$NAME/parameters".
void header_line(SpecCli& f, const std::string& line) {
  const size_t slash = line.find('/');
  const std::string name = line.substr(0, slash);
  const std::string value = slash == std::string::npos ? "" : line.substr(slash + 1);
  if (name == "$$ASCII") f.binary = false;
  else if (name == "$$BINARY") f.binary = true;
  else if (name == "$$UNITS") f.units = number(value);
  else if (name == "$$VERSION") f.version = int(number(value));
  else if (name == "$$DATE") f.date = value;
  else if (name == "$$LAYERS") f.layers = long(number(value));
  else if (name == "$$DIMENSION")
    for (const std::string& v : split(value, ',')) f.dimension.push_back(number(v));
  f.header_lines.push_back(line);
}

}  // namespace

SpecCli read_cli_per_spec(const std::string& bytes) {
  SpecCli f;
  const std::string end = "$$HEADEREND";
  const size_t header_end = bytes.find(end);
  if (bytes.rfind("$$HEADERSTART", 0) != 0 || header_end == std::string::npos)
    throw std::runtime_error("no $$HEADERSTART ... $$HEADEREND");
  for (std::string line : split(bytes.substr(0, header_end), '\n')) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line == "$$HEADERSTART") continue;
    header_line(f, line);
  }
  size_t at = header_end + end.size();
  if (!f.binary) {
    const std::vector<std::string> lines = split(bytes.substr(at), '\n');
    size_t i = 0;
    while (i < lines.size() && lines[i].empty()) ++i;
    if (i == lines.size() || lines[i] != "$$GEOMETRYSTART") throw std::runtime_error("no $$GEOMETRYSTART");
    for (++i; i < lines.size(); ++i) {
      const std::string& line = lines[i];
      if (line == "$$GEOMETRYEND") return f;
      if (line.rfind("$$LAYER/", 0) == 0) {
        f.geometry.push_back({number(line.substr(8)), {}});
      } else if (line.rfind("$$POLYLINE/", 0) == 0) {
        const std::vector<std::string> v = split(line.substr(11), ',');
        if (v.size() < 3 || f.geometry.empty()) throw std::runtime_error("bad polyline: " + line);
        SpecCliPolyline pl{int32_t(number(v[0])), int32_t(number(v[1])), {}};
        const size_t n = size_t(number(v[2]));
        if (v.size() != 3 + 2 * n) throw std::runtime_error("polyline count mismatch: " + line);
        for (size_t j = 3; j < v.size(); ++j) pl.xy.push_back(number(v[j]));
        f.geometry.back().polylines.push_back(pl);
      } else {
        throw std::runtime_error("unexpected line: " + line);
      }
    }
    throw std::runtime_error("no $$GEOMETRYEND");
  }
  // Binary, long format: uint16 command, then its parameters (little-endian).
  while (at < bytes.size()) {
    const uint16_t cmd = take<uint16_t>(bytes, at);
    if (cmd == 127) {
      f.geometry.push_back({double(take<float>(bytes, at)), {}});
    } else if (cmd == 130) {
      if (f.geometry.empty()) throw std::runtime_error("polyline before a layer");
      SpecCliPolyline pl;
      pl.id = take<int32_t>(bytes, at);
      pl.dir = take<int32_t>(bytes, at);
      const int32_t n = take<int32_t>(bytes, at);
      for (int32_t j = 0; j < 2 * n; ++j) pl.xy.push_back(double(take<float>(bytes, at)));
      f.geometry.back().polylines.push_back(pl);
    } else {
      throw std::runtime_error("unexpected command " + std::to_string(cmd));
    }
  }
  return f;
}

SpecSlc read_slc_per_spec(const std::string& bytes) {
  SpecSlc f;
  const std::string terminator = "\r\n\x1a";
  const size_t header_end = bytes.find(terminator);
  if (header_end == std::string::npos || header_end + 3 > 2048)
    throw std::runtime_error("no header terminator 0D 0A 1A within 2048 bytes");
  f.header = bytes.substr(0, header_end);
  size_t at = header_end + 3;
  // 3D reserved section.
  if (at + 256 > bytes.size()) throw std::runtime_error("truncated reserved section");
  for (size_t i = 0; i < 256; ++i)
    if (bytes[at + i] != 0) throw std::runtime_error("reserved section is not zero");
  at += 256;
  // Sample table: a byte count, then four floats per entry.
  const uint8_t entries = take<uint8_t>(bytes, at);
  for (unsigned i = 0; i < entries; ++i) {
    std::array<float, 4> e;
    for (float& v : e) v = take<float>(bytes, at);
    f.samples.push_back(e);
  }
  // Contour layers until the termination record (z, 0xFFFFFFFF).
  for (;;) {
    const float z = take<float>(bytes, at);
    const uint32_t boundaries = take<uint32_t>(bytes, at);
    if (boundaries == 0xFFFFFFFFu) {
      f.end_z = z;
      break;
    }
    SpecSlcLayer layer;
    layer.z = z;
    for (uint32_t b = 0; b < boundaries; ++b) {
      const uint32_t vertices = take<uint32_t>(bytes, at);
      layer.gaps.push_back(take<uint32_t>(bytes, at));
      std::vector<std::array<float, 2>> pts(vertices);
      for (auto& p : pts) {
        p[0] = take<float>(bytes, at);
        p[1] = take<float>(bytes, at);
      }
      layer.boundaries.push_back(std::move(pts));
    }
    f.layers.push_back(std::move(layer));
  }
  if (at != bytes.size()) throw std::runtime_error("bytes after the termination record");
  return f;
}

}  // namespace slicereuse::test
