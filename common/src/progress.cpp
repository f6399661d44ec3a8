#include "slicereuse/progress.h"

#include "slicereuse/error.h"

namespace slicereuse {

void report_progress(const Progress& progress, double fraction, const char* phase) {
  if (progress && !progress(fraction, phase)) throw Cancelled();
}

}  // namespace slicereuse
