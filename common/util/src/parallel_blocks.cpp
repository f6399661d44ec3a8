#include "slicereuse/util/parallel_blocks.h"

#include <omp.h>

#include <atomic>
#include <exception>
#include <mutex>

#include "slicereuse/util/error.h"

namespace slicereuse {

void parallel_blocks(size_t n, const std::function<void(size_t)>& body, const Progress& progress,
                     const char* phase) {
  std::atomic<size_t> done{0};
  std::atomic<bool> stop{false};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  // Dynamic scheduling: layers differ wildly in cost (caps versus walls of a part).
#pragma omp parallel for schedule(dynamic, 1)
  for (long long b = 0; b < static_cast<long long>(n); ++b) {
    if (stop.load(std::memory_order_relaxed)) continue;
    try {
      body(static_cast<size_t>(b));
      const size_t d = ++done;
      // Only the calling thread may talk to the host (GUI callbacks are not thread safe).
      if (omp_get_thread_num() == 0 && progress && !progress(double(d) / double(n), phase))
        throw Cancelled();
    } catch (...) {
      std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      stop = true;
    }
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace slicereuse
