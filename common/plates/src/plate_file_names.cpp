#include "slicereuse/plates/plate_file_names.h"

namespace slicereuse {
namespace {

// Where pattern's extension starts (a '.' after the last '/', not leading the name), or npos.
size_t extension_at(const std::string& path) {
  const size_t slash = path.rfind('/');
  const size_t name = slash == std::string::npos ? 0 : slash + 1;
  const size_t dot = path.rfind('.');
  return dot != std::string::npos && dot > name ? dot : std::string::npos;
}

}  // namespace

std::string plate_file_name(const std::string& pattern, size_t k) {
  std::string p = pattern;
  while (p.size() > 1 && p.back() == '/') p.pop_back();
  const size_t dot = extension_at(p);
  const std::string number = "_" + std::to_string(k);
  return dot == std::string::npos ? p + number : p.substr(0, dot) + number + p.substr(dot);
}

std::string plate_layout_file_name(const std::string& plate_file) {
  std::string p = plate_file;
  while (p.size() > 1 && p.back() == '/') p.pop_back();
  const size_t dot = extension_at(p);
  return (dot == std::string::npos ? p : p.substr(0, dot)) + "_layout.png";
}

}  // namespace slicereuse
