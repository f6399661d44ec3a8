#include "slicereuse/util/format.h"

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "slicereuse/util/error.h"

namespace slicereuse {

std::string format(const char* fmt, ...) {
  va_list args, copy;
  va_start(args, fmt);
  va_copy(copy, args);
  const int n = std::vsnprintf(nullptr, 0, fmt, copy);
  va_end(copy);
  std::string s(n > 0 ? size_t(n) : 0, '\0');
  if (n > 0) std::vsnprintf(s.data(), s.size() + 1, fmt, args);
  va_end(args);
  return s;
}

std::string utc_time(std::time_t when, const char* fmt) {
  std::tm tm;
  gmtime_r(&when, &tm);
  char buf[64];
  const size_t n = std::strftime(buf, sizeof buf, fmt, &tm);
  return std::string(buf, n);
}

std::time_t creation_time() {
  const char* epoch = std::getenv("SOURCE_DATE_EPOCH");
  if (!epoch || !*epoch) return std::time(nullptr);
  const std::string text(epoch);
  // Digits only (no sign, space or exponent), and at most 12 of them: years up to 33,000.
  if (text.size() > 12 || text.find_first_not_of("0123456789") != std::string::npos)
    throw Error("SOURCE_DATE_EPOCH is '" + text + "': it must be the creation time as a whole number of seconds "
                "since 1970-01-01 UTC, or unset");
  return std::time_t(std::stoll(text));
}

}  // namespace slicereuse
