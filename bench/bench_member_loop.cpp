// Per-member stability of a family loop: the same members transferred (contours only, through
// the edge ends, as Make Print Job does) and sliced directly (xyz only), one after the other in
// one process, as a pymeshlab loop or a meshlabserver script runs them. For every member: wall
// and CPU seconds and minor page faults of each step, first with every large buffer returned
// to the kernel when freed, then with freed buffers kept for the next member (ReuseBuffers,
// which the plugin holds while it caches an encoding). Page faults on fresh memory are what
// grows member to member when buffers are not kept; CPU seconds are less disturbed than wall
// seconds by other processes on a shared machine.
// Usage: bench_member_loop [--shape arch] [--faces 545000] [--height 14.484] [--thickness 0.001]
//                          [--members 4]
#include <omp.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

#include "bench_args.h"
#include "family.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/transfer/transfer_contours.h"

using namespace slicereuse;

namespace {

struct Cost {
  double wall, cpu;
  long faults;
};

Cost cost_of(const std::function<void()>& work) {
  rusage a, b;
  getrusage(RUSAGE_SELF, &a);
  const auto t0 = std::chrono::steady_clock::now();
  work();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  getrusage(RUSAGE_SELF, &b);
  auto secs = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return {wall, secs(b.ru_utime) - secs(a.ru_utime) + secs(b.ru_stime) - secs(a.ru_stime),
          b.ru_minflt - a.ru_minflt};
}

}  // namespace

int main(int argc, char** argv) {
  BenchArgs args = parse_bench_args(argc, argv);
  args.members = std::max(args.members, 4);
  SliceOptions options;
  options.thickness = args.thickness;
  const Mesh base = test::make_family_base(args.family);
  const Slices source = slice_layers(base, options);
  const Buffer<uint32_t> ends = encoded_edge_ends(source, base);
  std::vector<Mesh> members;
  for (int i = 1; i < args.members; ++i) members.push_back(test::make_family_member(base, args.family, i));
  SliceOptions direct = options;
  direct.z_start = source.z_start;
  direct.encoding = false;
  std::printf("shape %s, %zu faces, %zu layers, %zu points, threads %d\n", args.family.shape.c_str(), base.faces(),
              source.layers(), source.points(), omp_get_max_threads());
  std::printf("%-14s %6s %8s %8s %10s %8s %8s %10s\n", "buffers", "member", "transfer", "cpu", "faults", "direct",
              "cpu", "faults");
  for (int keep = 0; keep < 2; ++keep) {
    std::unique_ptr<ReuseBuffers> reuse;
    if (keep) reuse = std::make_unique<ReuseBuffers>();
    for (size_t i = 0; i < members.size(); ++i) {
      const Cost t = cost_of([&] { transfer_contours(source, ends, members[i], TransferOptions(TransferMode::Exact, false)); });
      const Cost d = cost_of([&] { slice_layers(members[i], direct); });
      std::printf("%-14s %6zu %8.3f %8.3f %10ld %8.3f %8.3f %10ld\n", keep ? "kept" : "to the kernel", i + 1, t.wall,
                  t.cpu, t.faults, d.wall, d.cpu, d.faults);
    }
  }
  return 0;
}
