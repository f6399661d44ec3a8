#include "slicereuse/formats/file_names.h"

#include <algorithm>
#include <cctype>

namespace slicereuse {

bool is_binary_file_name(const std::string& path) {
  constexpr char kExtension[] = ".srb";
  const size_t n = sizeof kExtension - 1;
  return path.size() >= n && std::equal(path.end() - n, path.end(), kExtension, [](char a, char b) {
           return std::tolower(static_cast<unsigned char>(a)) == b;
         });
}

std::string encoding_file_beside(const std::string& contour_path, FileFormat format) {
  const size_t dot = contour_path.find_last_of('.'), slash = contour_path.find_last_of('/');
  const bool has_extension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return contour_path.substr(0, has_extension ? dot : std::string::npos) +
         (format == FileFormat::Binary ? "_enc.srb" : ".enc");
}

std::string encoding_file_beside(const std::string& contour_path) {
  return encoding_file_beside(contour_path, is_binary_file_name(contour_path) ? FileFormat::Binary : FileFormat::Text);
}

}  // namespace slicereuse
