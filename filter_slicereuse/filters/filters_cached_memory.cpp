// The plugin's cached encoding (Make Print Job), and "Free Cached Memory", which gives back what
// the plugin keeps between filters: the cached encoding and the buffers kept for the next job.
#include "filter_params.h"
#include "filters_common.h"
#include "slicereuse/util/buffer.h"
#include "slicereuse/util/memory_budget.h"

namespace slicereuse::plugin {

// Lives as long as the plugin; a job short of memory frees it (reclaim_memory).
EncodingCache& encoding_cache() {
  static EncodingCache& cache = [] () -> EncodingCache& {
    static EncodingCache c;
    add_memory_reclaimer([] { return uint64_t(c.try_clear()); });
    return c;
  }();
  return cache;
}

// Kept from the first job on (at most a quarter of the machine's memory, ReuseBuffers): the
// kernel would zero gigabytes of fresh pages for every member or plate (bench_member_loop shows
// what that costs).
void keep_buffers_for_the_next_job() {
  static ReuseBuffers keep;
}

namespace {

struct NoParams {};

Result run_free_cached_memory(const NoParams&, Host& host) {
  const uint64_t encoding = encoding_cache().bytes();
  const uint64_t freed = reclaim_memory();
  host.log(format("Free Cached Memory: %.1f MB freed (cached encoding %.1f MB, buffers kept for the next job "
                  "%.1f MB)",
                  double(freed) * 1e-6, double(encoding) * 1e-6, double(freed - std::min(freed, encoding)) * 1e-6));
  return {{"freed_bytes", int64_t(freed)}, {"encoding_bytes", int64_t(encoding)}};
}

}  // namespace

FilterSpec free_cached_memory_filter() {
  const std::string description =
      "<p>Gives back the memory that <i>Make Print Job</i> and <i>Make Plate Job</i> keep between "
      "jobs: the last encoding file read (about 1.5 GB for a 545k-face part at 1 &micro;m) and the "
      "large buffers kept for the next member's or plate's job. Run it after the last member of a family, in a "
      "pymeshlab session or a meshlabserver script that goes on with other work. A job short of "
      "memory frees them on its own. The next print job reads the encoding again.</p>";
  return typed_filter({FilterId::FreeCachedMemory, "Free Cached Memory", "free_cached_memory", description,
                       Arity::None, kLayerClass, false},
                      ParamList<NoParams>(), run_free_cached_memory, {"freed_bytes", "encoding_bytes"});
}

}  // namespace slicereuse::plugin
