#pragma once
// check_memory_for: refuses, before allocating, a job whose output would not fit in memory, with
// the figures a person can act on, instead of a std::bad_alloc (or the kernel's OOM killer) half
// way through, against available_memory() below; where that is unknown, it checks nothing.
//   bytes: what the job is about to allocate; what: the job and its size, for the message, e.g.
//   "slicing 730,000,000 contour points". Throws Error when bytes > available_memory() even
//   after reclaim_memory() gave back what it could.
#include <cstdint>
#include <functional>
#include <string>

namespace slicereuse {

void check_memory_for(uint64_t bytes, const std::string& what, const std::string& advice);

// MemAvailable from /proc/meminfo in bytes (what the kernel can hand out without swapping), or less
// when the process's memory control group (cgroup v1 or v2, e.g. a container's limit) allows less,
// or when the environment variable SLICEREUSE_MEMORY_LIMIT (a size such as 4G or 500M; K, M, G are
// powers of 1024) says so; 0 when unknown. Throws Error naming SLICEREUSE_MEMORY_LIMIT when it is
// not a size.
uint64_t available_memory();

// Memory kept for reuse that a job may take back when it needs it: caches register a reclaimer (it
// frees what it holds and returns the bytes freed), and reclaim_memory() calls every one, then
// releases the buffers kept for reuse (buffer.h), which the caches' freed buffers join; it returns
// the bytes given back, each counted once. check_memory_for calls it before it refuses a job; a
// caller that plans by available_memory() (Make Print Job's ranges of layers) calls it before it
// settles for less. Thread safe. A reclaimer must not wait for a lock that a thread checking
// memory may hold (EncodingCache::try_clear gives up instead).
void add_memory_reclaimer(std::function<uint64_t()> reclaim);
uint64_t reclaim_memory();

}  // namespace slicereuse
