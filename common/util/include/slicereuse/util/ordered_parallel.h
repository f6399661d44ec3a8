#pragma once
// OrderedParallel: makes items 0..n-1 (byte strings) on all cores and hands them to the calling
// thread in order, at most `window` items ahead of the one it holds.
//
// Why: an archive is written on one thread, entry after entry, while the entries (mask PNGs)
// are made independently. Batches made in parallel and then written would leave the other
// cores idle (spinning in OpenMP's barrier) while each batch is written; here workers keep
// making the next items while the caller writes, and the caller makes items itself whenever
// the one it needs is not ready, so no core waits while there is work.
//
// Use: OrderedParallel items(n, window, make); then items.get(0), items.get(1), ... in
// increasing order; the reference stays valid until the next get. make(k, bytes) fills bytes
// (replacing its content) and may run on any thread. An exception thrown by make(k) is rethrown
// by get(k). The destructor stops the workers (items not yet asked for are dropped).
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace slicereuse {

class OrderedParallel {
 public:
  using Make = std::function<void(size_t k, std::vector<uint8_t>& bytes)>;
  // Workers: omp_get_max_threads() - 1 (the caller is the last one).
  OrderedParallel(size_t n, size_t window, Make make);
  ~OrderedParallel();
  OrderedParallel(const OrderedParallel&) = delete;
  OrderedParallel& operator=(const OrderedParallel&) = delete;

  const std::vector<uint8_t>& get(size_t k);

 private:
  struct Slot {
    std::vector<uint8_t> bytes;
    size_t item = SIZE_MAX;  // the item the slot holds once made
    std::exception_ptr error;
  };
  bool claimable() const;  // with the mutex held
  void make_claimed(std::unique_lock<std::mutex>& lock);
  void work();

  const size_t n_, window_;
  const Make make_;
  std::vector<Slot> slots_;
  std::mutex mutex_;
  std::condition_variable more_work_, item_done_;
  size_t next_ = 0;     // next item to claim
  size_t current_ = 0;  // the item the caller holds or waits for
  bool stop_ = false;
  std::vector<std::thread> workers_;
};

}  // namespace slicereuse
