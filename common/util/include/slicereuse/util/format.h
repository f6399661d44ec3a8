#pragma once
// format: printf-style formatting into a std::string, for messages that show numbers the way
// people write them (%g: 1e-09, not 0.000000).
// utc_time: a moment as print files write their creation time, strftime's `fmt` in UTC.
#include <ctime>
#include <string>

namespace slicereuse {

std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

std::string utc_time(std::time_t when, const char* fmt);

}  // namespace slicereuse
