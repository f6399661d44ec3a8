#pragma once
// json_string: text as a JSON string literal, quotes included: '"' and '\' escaped, control
// characters as \u00XX, other bytes (UTF-8) as they are: the hosts' result lines (host_adapter.h),
// written a line at a time. Files are written with nlohmann::json (placements_file.h).
#include <cstdio>
#include <string>

namespace slicereuse {

inline std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", unsigned(c));
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace slicereuse
