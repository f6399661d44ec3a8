#pragma once
// flag_number: a command-line flag's value as a number of type T (from_chars: the whole text, no
// spaces); throws Error "FLAG: not a number: 'TEXT'" otherwise. For the tools' argument parsers.
#include <charconv>
#include <cstring>
#include <string>

#include "slicereuse/util/error.h"

namespace slicereuse::test {

template <class T>
T flag_number(const char* flag, const char* text) {
  T v{};
  const char* end = text + std::strlen(text);
  auto [p, ec] = std::from_chars(text, end, v);
  if (ec != std::errc() || p != end) throw Error(std::string(flag) + ": not a number: '" + text + "'");
  return v;
}

}  // namespace slicereuse::test
