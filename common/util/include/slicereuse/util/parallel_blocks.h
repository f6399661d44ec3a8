#pragma once
// parallel_blocks: runs body(b) for b in [0, n) on all cores (OpenMP, dynamic schedule) with
// progress reported from the calling thread only, cancellation, and exceptions carried out of
// the parallel region: the first exception thrown by any body is rethrown once all threads stop,
// and a cancelled run throws Cancelled.
#include <cstddef>
#include <functional>

#include "slicereuse/util/progress.h"

namespace slicereuse {

void parallel_blocks(size_t n, const std::function<void(size_t)>& body, const Progress& progress,
                     const char* phase);

}  // namespace slicereuse
