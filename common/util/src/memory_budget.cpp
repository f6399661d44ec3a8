#include "slicereuse/util/memory_budget.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "slicereuse/util/buffer.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {

namespace {

uint64_t read_number(const std::string& path) {  // 0 when missing or not a number ("max")
  FILE* f = std::fopen(path.c_str(), "r");
  if (f == nullptr) return 0;
  unsigned long long n = 0;
  const bool ok = std::fscanf(f, "%llu", &n) == 1;
  std::fclose(f);
  return ok ? uint64_t(n) : 0;
}

// The group's inactive file cache in bytes, from memory.stat.
uint64_t inactive_file(const std::string& group, bool v2) {
  FILE* f = std::fopen((group + "/memory.stat").c_str(), "r");
  if (f == nullptr) return 0;
  const char* key = v2 ? "inactive_file %llu" : "total_inactive_file %llu";
  char line[256];
  unsigned long long n = 0;
  while (std::fgets(line, sizeof line, f))
    if (std::sscanf(line, key, &n) == 1) break;
  std::fclose(f);
  return uint64_t(n);
}

// What the process's memory control group (and each group above it) still allows: a container's
// or a systemd unit's limit, which MemAvailable does not show. cgroup v2 (0::/path, memory.max)
// and v1 (N:memory:/path, memory.limit_in_bytes). UINT64_MAX when there is no limit.
uint64_t cgroup_headroom() {
  uint64_t headroom = UINT64_MAX;
  FILE* f = std::fopen("/proc/self/cgroup", "r");
  if (f == nullptr) return headroom;
  char line[4096];
  while (std::fgets(line, sizeof line, f)) {
    std::string entry(line);
    if (!entry.empty() && entry.back() == '\n') entry.pop_back();
    std::string root, limit, usage;
    const bool v2 = entry.rfind("0::", 0) == 0;
    if (v2) {
      root = "/sys/fs/cgroup";
      limit = "/memory.max";
      usage = "/memory.current";
      entry.erase(0, 3);
    } else if (const size_t at = entry.find(":memory:"); at != std::string::npos) {
      root = "/sys/fs/cgroup/memory";
      limit = "/memory.limit_in_bytes";
      usage = "/memory.usage_in_bytes";
      entry.erase(0, at + 8);
    } else {
      continue;
    }
    for (std::string group = entry;;) {  // the group, then each one above it
      const uint64_t max = read_number(root + group + limit);
      if (max != 0) {
        // Usage counts the page cache; its inactive part is given back before the limit bites
        // (the figure `docker stats` shows).
        const uint64_t charged = read_number(root + group + usage), cache = inactive_file(root + group, v2);
        const uint64_t used = charged > cache ? charged - cache : 0;
        headroom = std::min(headroom, max > used ? max - used : 0);
      }
      const size_t slash = group.rfind('/');
      if (slash == std::string::npos || group == "/") break;
      group = slash == 0 ? "/" : group.substr(0, slash);
    }
  }
  std::fclose(f);
  return headroom;
}

// SLICEREUSE_MEMORY_LIMIT: what a person allows the plugin to plan for (bytes, or with a K, M or G
// suffix, powers of 1024), e.g. to leave room for other jobs. UINT64_MAX when not set.
uint64_t user_limit() {
  const char* text = std::getenv("SLICEREUSE_MEMORY_LIMIT");
  if (text == nullptr || *text == '\0') return UINT64_MAX;
  char* end = nullptr;
  const double n = std::strtod(text, &end);
  const std::string unit(end);
  const double scale = unit.empty() ? 1 : unit == "K" ? 0x1p10 : unit == "M" ? 0x1p20 : unit == "G" ? 0x1p30 : 0;
  if (end == text || !(n > 0) || scale == 0 || !(n * scale < 0x1p63))
    throw Error(format("SLICEREUSE_MEMORY_LIMIT is '%s', which is not a memory size such as 4G, 500M or "
                       "1000000 bytes",
                       text));
  return uint64_t(n * scale);
}

std::mutex& reclaimers_mutex() {
  static std::mutex m;
  return m;
}

std::vector<std::function<uint64_t()>>& reclaimers() {
  static std::vector<std::function<uint64_t()>> r;
  return r;
}

}  // namespace

uint64_t available_memory() {
  FILE* f = std::fopen("/proc/meminfo", "r");
  if (f == nullptr) return 0;
  char line[256];
  unsigned long long kib = 0;
  while (std::fgets(line, sizeof line, f))
    if (std::sscanf(line, "MemAvailable: %llu kB", &kib) == 1) break;
  std::fclose(f);
  if (kib == 0) return 0;
  return std::min({uint64_t(kib) * 1024, cgroup_headroom(), user_limit()});
}

void add_memory_reclaimer(std::function<uint64_t()> reclaim) {
  std::lock_guard<std::mutex> lock(reclaimers_mutex());
  reclaimers().push_back(std::move(reclaim));
}

uint64_t reclaim_memory() {
  // What the reclaimers free may join the kept buffers: counted once, when those are released.
  const uint64_t kept_before = kept_buffer_bytes();
  uint64_t freed = 0;
  {
    std::lock_guard<std::mutex> lock(reclaimers_mutex());
    for (const auto& reclaim : reclaimers()) freed += reclaim();
  }
  const uint64_t kept_now = kept_buffer_bytes();
  const uint64_t joined = kept_now > kept_before ? kept_now - kept_before : 0;
  return (freed > joined ? freed - joined : 0) + release_kept_buffers();
}

void check_memory_for(uint64_t bytes, const std::string& what, const std::string& advice) {
  uint64_t available = available_memory();
  if (available != 0 && bytes > available && reclaim_memory() > 0) available = available_memory();
  if (available != 0 && bytes > available)
    throw Error(format("%s needs %.1f GB of memory, but only %.1f GB are available; %s", what.c_str(),
                       double(bytes) * 1e-9, double(available) * 1e-9, advice.c_str()));
}

}  // namespace slicereuse
