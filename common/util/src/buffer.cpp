#include "slicereuse/util/buffer.h"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdlib>
#include <mutex>
#include <new>
#include <unordered_map>
#include <vector>

namespace slicereuse {
namespace {

constexpr size_t kHugePage = size_t(2) << 20;
constexpr size_t kLarge = 4 * kHugePage;

struct Pool {
  std::mutex mutex;
  int users = 0;
  size_t kept_bytes = 0;
  std::vector<std::pair<void*, size_t>> kept;  // (pointer, capacity), oldest first
  std::unordered_map<void*, size_t> capacity;  // of every large buffer in use
};

// Never keep more than a quarter of the machine's memory idle.
size_t pool_limit() {
  static const size_t limit = size_t(sysconf(_SC_PHYS_PAGES)) * size_t(sysconf(_SC_PAGESIZE)) / 4;
  return limit;
}

Pool& pool() {
  static Pool p;
  return p;
}

size_t rounded(size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }

}  // namespace

void* allocate_buffer(size_t bytes) {
  if (bytes < kLarge) {
    void* p = std::malloc(bytes ? bytes : 1);
    if (!p) throw std::bad_alloc();
    return p;
  }
  const size_t need = rounded(bytes);
  Pool& pl = pool();
  std::lock_guard<std::mutex> lock(pl.mutex);
  // Best fit among kept buffers that are not more than twice too large.
  size_t best = pl.kept.size();
  for (size_t i = 0; i < pl.kept.size(); ++i)
    if (pl.kept[i].second >= need && pl.kept[i].second <= 2 * need &&
        (best == pl.kept.size() || pl.kept[i].second < pl.kept[best].second))
      best = i;
  if (best < pl.kept.size()) {
    const auto [p, size] = pl.kept[best];
    pl.capacity[p] = size;
    pl.kept_bytes -= size;
    pl.kept.erase(pl.kept.begin() + best);
    return p;
  }
  // An eighth more address space than asked for, so that the next family member's slightly
  // larger buffer still fits when this one is kept. Pages are only backed once written, so the
  // headroom costs no memory.
  const size_t size = rounded(bytes + bytes / 8);
  void* p = std::aligned_alloc(kHugePage, size);
  if (!p) throw std::bad_alloc();
  madvise(p, size, MADV_HUGEPAGE);  // advice only: without THP it is plain memory
  try {
    pl.capacity[p] = size;
  } catch (...) {
    std::free(p);
    throw;
  }
  return p;
}

void free_buffer(void* p, size_t bytes) noexcept {
  if (!p) return;
  std::vector<void*> release;
  if (bytes >= kLarge) {
    Pool& pl = pool();
    std::lock_guard<std::mutex> lock(pl.mutex);
    const auto it = pl.capacity.find(p);
    const size_t size = it == pl.capacity.end() ? rounded(bytes) : it->second;
    if (it != pl.capacity.end()) pl.capacity.erase(it);
    if (pl.users > 0) {
      try {
        pl.kept.emplace_back(p, size);
        pl.kept_bytes += size;
        p = nullptr;
        while (pl.kept_bytes > pool_limit()) {
          release.push_back(pl.kept.front().first);
          pl.kept_bytes -= pl.kept.front().second;
          pl.kept.erase(pl.kept.begin());
        }
      } catch (...) {  // no room to remember it: just free it
      }
    }
  }
  std::free(p);
  for (void* r : release) std::free(r);
}

ReuseBuffers::ReuseBuffers() {
  std::lock_guard<std::mutex> lock(pool().mutex);
  ++pool().users;
}

ReuseBuffers::~ReuseBuffers() {
  bool last;
  {
    std::lock_guard<std::mutex> lock(pool().mutex);
    last = --pool().users == 0;
  }
  if (last) release_kept_buffers();
}

size_t release_kept_buffers() {
  std::vector<std::pair<void*, size_t>> release;
  size_t bytes;
  {
    std::lock_guard<std::mutex> lock(pool().mutex);
    release.swap(pool().kept);
    bytes = pool().kept_bytes;
    pool().kept_bytes = 0;
  }
  for (auto& b : release) std::free(b.first);
  return bytes;
}

size_t kept_buffer_bytes() {
  std::lock_guard<std::mutex> lock(pool().mutex);
  return pool().kept_bytes;
}

}  // namespace slicereuse
