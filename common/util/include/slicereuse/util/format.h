#pragma once
// format: printf-style formatting into a std::string, for messages that show numbers the way
// people write them (%g: 1e-09, not 0.000000).
// utc_time: a moment as print files write their creation time, strftime's `fmt` in UTC.
// creation_time: the moment print files record as their creation: $SOURCE_DATE_EPOCH when it is
// set (seconds since 1970, the reproducible-builds.org convention), else now. A batch that sets
// it once makes byte-identical files wherever and whenever each one is made (family.py on Dask);
// a value that is not a whole number of seconds from 0 up is refused (Error naming it).
#include <ctime>
#include <string>

namespace slicereuse {

std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

std::string utc_time(std::time_t when, const char* fmt);

std::time_t creation_time();

}  // namespace slicereuse
