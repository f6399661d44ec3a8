#pragma once
// seconds_since(t): the seconds from t to now on the steady clock, as the figures a job reports
// (stats, progress lines) are timed.
#include <chrono>

namespace slicereuse {

inline double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace slicereuse
