// OrderedParallel: items arrive in order, each made once; an error reaches the caller, and the
// workers make nothing beyond the window once the caller stops at the failed item.
#include <gtest/gtest.h>

#include <omp.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <vector>

#include "error_of.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/ordered_parallel.h"

using namespace slicereuse;

namespace {

// Runs a test body with `threads` OpenMP threads (OrderedParallel starts threads - 1 workers),
// whatever OMP_NUM_THREADS says, so that the workers under test exist.
class WithThreads {
 public:
  explicit WithThreads(int threads) : before_(omp_get_max_threads()) { omp_set_num_threads(threads); }
  ~WithThreads() { omp_set_num_threads(before_); }

 private:
  int before_;
};

}  // namespace

TEST(OrderedParallel, HandsOutItemsInOrder) {
  WithThreads threads(4);
  std::atomic<int> made{0};
  OrderedParallel items(1000, 7, [&](size_t k, std::vector<uint8_t>& bytes) {
    bytes.assign(k % 50 + 1, uint8_t(k));
    ++made;
  });
  for (size_t k = 0; k < 1000; ++k) {
    const std::vector<uint8_t>& b = items.get(k);
    ASSERT_EQ(b.size(), k % 50 + 1);
    ASSERT_EQ(b[0], uint8_t(k));
  }
  EXPECT_EQ(made, 1000);
  EXPECT_THROW(items.get(3), Error);  // out of order
}

// Item 10 fails, and its make waits until the rest of the window (11 .. 25) is made, so the
// workers have had every chance to run on while the caller waits for it and after the error
// reaches it. They must not: every item up to the window's end is made once, none beyond it.
// The failing item lies inside the first window and the caller asks for nothing before a worker
// has begun it: a caller that waits for an earlier item makes items ahead itself, and would
// otherwise be the one to take item 10, holding the window where it was (its make waits for
// items the window does not reach yet).
TEST(OrderedParallel, ErrorsReachTheCallerAndStopTheWorkers) {
  WithThreads threads(4);
  constexpr size_t kWindow = 16, kFailing = 10;
  std::mutex mutex;
  std::condition_variable failing_begun, window_made;
  std::vector<int> made(10000, 0);
  size_t made_after_failing = 0;
  bool window_full = false;
  {
    OrderedParallel items(made.size(), kWindow, [&](size_t k, std::vector<uint8_t>& bytes) {
      std::unique_lock<std::mutex> lock(mutex);
      ++made[k];
      if (k > kFailing && k < kFailing + kWindow && ++made_after_failing == kWindow - 1) window_made.notify_all();
      if (k == kFailing) {
        failing_begun.notify_all();
        // A guard, not a timing: without a free worker (or a broken window) this would wait forever.
        window_full = window_made.wait_for(lock, std::chrono::seconds(60),
                                           [&] { return made_after_failing == kWindow - 1; });
        throw Error("item 10 failed");
      }
      bytes.assign(1, uint8_t(k));
    });
    {
      std::unique_lock<std::mutex> lock(mutex);
      ASSERT_TRUE(failing_begun.wait_for(lock, std::chrono::seconds(60), [&] { return made[kFailing] == 1; }));
    }
    for (size_t k = 0; k < kFailing; ++k) ASSERT_EQ(items.get(k)[0], uint8_t(k));
    EXPECT_EQ(test::error_of([&] { items.get(kFailing); }), "item 10 failed");
  }
  EXPECT_TRUE(window_full) << "items 11 .. 25 were not made while item 10 was";
  for (size_t k = 0; k < made.size(); ++k) ASSERT_EQ(made[k], k < kFailing + kWindow ? 1 : 0) << "item " << k;
}
