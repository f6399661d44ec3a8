#pragma once
// format: printf-style formatting into a std::string, for messages that show numbers the way
// people write them (%g: 1e-09, not 0.000000).
#include <string>

namespace slicereuse {

std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

}  // namespace slicereuse
