#pragma once
// check_memory_for: refuses, before allocating, a job whose output would not fit in memory, with
// the figures a person can act on, instead of a std::bad_alloc (or the kernel's OOM killer) half
// way through. Reads MemAvailable from /proc/meminfo (what the kernel can hand out without
// swapping); where that cannot be read, it checks nothing.
//   bytes: what the job is about to allocate; what: the job and its size, for the message, e.g.
//   "slicing 730,000,000 contour points". Throws Error when bytes > MemAvailable.
#include <cstdint>
#include <string>

namespace slicereuse {

void check_memory_for(uint64_t bytes, const std::string& what, const std::string& advice);

// MemAvailable in bytes, or less when the process's memory control group (cgroup v1 or v2, e.g. a
// container's limit) allows less; 0 when unknown.
uint64_t available_memory();

}  // namespace slicereuse
