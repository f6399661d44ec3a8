#pragma once
// Buffer<T>: a std::vector whose elements are default-initialised, not zeroed, on resize.
// Why: the slicer sizes output arrays of hundreds of MB up front and then fills them from
// several threads; zeroing first would touch every page twice and on one thread only.
// Large buffers are also backed by transparent huge pages where the kernel allows it: filling
// gigabytes of fresh 4 KiB pages costs more in page faults than the slicing itself.
#include <cstddef>
#include <memory>
#include <vector>

namespace slicereuse {

void* allocate_buffer(size_t bytes);
void free_buffer(void* p, size_t bytes) noexcept;

// While a ReuseBuffers object lives, freed large buffers are kept and handed out again instead
// of being returned to the kernel, which would have to zero them anew: a loop over the members
// of a family then fills the same warm pages every time (large buffers get an eighth more
// address space than asked for, so a slightly larger member still fits). Everything kept is
// released when the last ReuseBuffers object goes away. Thread safe.
class ReuseBuffers {
 public:
  ReuseBuffers();
  ~ReuseBuffers();
  ReuseBuffers(const ReuseBuffers&) = delete;
  ReuseBuffers& operator=(const ReuseBuffers&) = delete;
};

// Frees every buffer kept for reuse now (ReuseBuffers goes on keeping those freed later);
// returns their bytes. reclaim_memory() (memory_budget.h) calls it when a job needs memory.
size_t release_kept_buffers();
// The bytes of the buffers kept for reuse now.
size_t kept_buffer_bytes();

template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  template <class U> struct rebind { using other = DefaultInitAllocator<U>; };
  DefaultInitAllocator() = default;
  template <class U> DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
  T* allocate(size_t n) { return static_cast<T*>(allocate_buffer(n * sizeof(T))); }
  void deallocate(T* p, size_t n) noexcept { free_buffer(p, n * sizeof(T)); }
  template <class U> void construct(U* p) noexcept(noexcept(::new (static_cast<void*>(p)) U)) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... A> void construct(U* p, A&&... a) {
    ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
  }
};

template <class T> using Buffer = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace slicereuse
