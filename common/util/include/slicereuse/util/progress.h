#pragma once
// Progress reporting shared by all long-running core functions.
// The callback gets a fraction in [0, 1] and a short phase name; it returns false to cancel,
// in which case the function throws Cancelled and leaves no output behind.
// It is only ever called from the calling thread, never from worker threads.
#include <functional>

namespace slicereuse {

using Progress = std::function<bool(double fraction, const char* phase)>;

// Calls progress (if set) and throws Cancelled when it returns false.
void report_progress(const Progress& progress, double fraction, const char* phase);

// Progress of one part of a job mapped onto [from, to] of the whole; empty when progress is.
Progress sub_progress(const Progress& progress, double from, double to);

}  // namespace slicereuse
