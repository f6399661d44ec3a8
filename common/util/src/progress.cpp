#include "slicereuse/util/progress.h"

#include "slicereuse/util/error.h"

namespace slicereuse {

void report_progress(const Progress& progress, double fraction, const char* phase) {
  if (progress && !progress(fraction, phase)) throw Cancelled();
}

Progress sub_progress(const Progress& progress, double from, double to) {
  if (!progress) return {};
  return [progress, from, to](double f, const char* phase) { return progress(from + (to - from) * f, phase); };
}

}  // namespace slicereuse
