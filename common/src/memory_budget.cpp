#include "slicereuse/memory_budget.h"

#include <cstdio>
#include <cstring>

#include "slicereuse/error.h"
#include "slicereuse/format.h"

namespace slicereuse {

uint64_t available_memory() {
  FILE* f = std::fopen("/proc/meminfo", "r");
  if (f == nullptr) return 0;
  char line[256];
  unsigned long long kib = 0;
  while (std::fgets(line, sizeof line, f))
    if (std::sscanf(line, "MemAvailable: %llu kB", &kib) == 1) break;
  std::fclose(f);
  return uint64_t(kib) * 1024;
}

void check_memory_for(uint64_t bytes, const std::string& what, const std::string& advice) {
  const uint64_t available = available_memory();
  if (available != 0 && bytes > available)
    throw Error(format("%s needs %.1f GB of memory, but only %.1f GB are available; %s", what.c_str(),
                       double(bytes) * 1e-9, double(available) * 1e-9, advice.c_str()));
}

}  // namespace slicereuse
