#include "slicereuse/util/ordered_parallel.h"

#include <omp.h>

#include <algorithm>

#include "slicereuse/util/error.h"

namespace slicereuse {

OrderedParallel::OrderedParallel(size_t n, size_t window, Make make)
    : n_(n), window_(std::max<size_t>(1, window)), make_(std::move(make)), slots_(window_) {
  const int workers = std::max(0, omp_get_max_threads() - 1);
  try {
    for (int i = 0; i < workers; ++i) workers_.emplace_back([this] { work(); });
  } catch (...) {  // no more threads: the ones started (or the caller alone) do the work
  }
}

OrderedParallel::~OrderedParallel() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  more_work_.notify_all();
  for (std::thread& t : workers_) t.join();
}

// Item next_ may be made when its slot is free: it is within the window after current_.
bool OrderedParallel::claimable() const { return next_ < n_ && next_ < current_ + window_; }

// Claims item next_, makes it without the lock and stores it.
void OrderedParallel::make_claimed(std::unique_lock<std::mutex>& lock) {
  const size_t k = next_++;
  Slot& slot = slots_[k % window_];
  lock.unlock();
  std::exception_ptr error;
  try {
    make_(k, slot.bytes);
  } catch (...) {
    error = std::current_exception();
  }
  lock.lock();
  slot.error = error;
  slot.item = k;
  item_done_.notify_all();
}

void OrderedParallel::work() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    more_work_.wait(lock, [this] { return stop_ || claimable(); });
    if (stop_) return;
    make_claimed(lock);
  }
}

const std::vector<uint8_t>& OrderedParallel::get(size_t k) {
  if (k >= n_ || k < current_) throw Error("internal error: item " + std::to_string(k) + " asked for out of order");
  std::unique_lock<std::mutex> lock(mutex_);
  current_ = k;
  next_ = std::max(next_, k);  // items the caller skipped are not made
  more_work_.notify_all();  // the window moved
  Slot& slot = slots_[k % window_];
  while (slot.item != k) {
    if (claimable()) make_claimed(lock);
    else item_done_.wait(lock);
  }
  if (slot.error) std::rethrow_exception(slot.error);
  return slot.bytes;
}

}  // namespace slicereuse
