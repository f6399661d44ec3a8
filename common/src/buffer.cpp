#include "slicereuse/buffer.h"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdlib>
#include <mutex>
#include <new>
#include <vector>

namespace slicereuse {
namespace {

constexpr size_t kHugePage = size_t(2) << 20;
constexpr size_t kLarge = 4 * kHugePage;

struct Pool {
  std::mutex mutex;
  int users = 0;
  size_t kept_bytes = 0;
  std::vector<std::pair<void*, size_t>> kept;  // (pointer, rounded size), oldest first
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
  const size_t size = rounded(bytes);
  {
    // Best fit among kept buffers that are not more than twice too large.
    Pool& pl = pool();
    std::lock_guard<std::mutex> lock(pl.mutex);
    size_t best = pl.kept.size();
    for (size_t i = 0; i < pl.kept.size(); ++i)
      if (pl.kept[i].second >= size && pl.kept[i].second <= 2 * size &&
          (best == pl.kept.size() || pl.kept[i].second < pl.kept[best].second))
        best = i;
    if (best < pl.kept.size()) {
      void* p = pl.kept[best].first;
      pl.kept_bytes -= pl.kept[best].second;
      pl.kept.erase(pl.kept.begin() + best);
      return p;
    }
  }
  void* p = std::aligned_alloc(kHugePage, size);
  if (!p) throw std::bad_alloc();
  madvise(p, size, MADV_HUGEPAGE);  // advice only: without THP it is plain memory
  return p;
}

void free_buffer(void* p, size_t bytes) noexcept {
  if (!p) return;
  std::vector<void*> release;
  if (bytes >= kLarge) {
    Pool& pl = pool();
    std::lock_guard<std::mutex> lock(pl.mutex);
    if (pl.users > 0) {
      try {
        pl.kept.emplace_back(p, rounded(bytes));
        pl.kept_bytes += rounded(bytes);
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
  std::vector<std::pair<void*, size_t>> release;
  {
    std::lock_guard<std::mutex> lock(pool().mutex);
    if (--pool().users == 0) {
      release.swap(pool().kept);
      pool().kept_bytes = 0;
    }
  }
  for (auto& b : release) std::free(b.first);
}

}  // namespace slicereuse
