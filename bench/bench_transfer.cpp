// Transfer benchmark: direct slicing of family members versus exact and barycentric transfer
// of member 0's encoding, measured in the same run so the ratio is meaningful on a shared
// machine. Prints per member: points, re-sliced layers, median seconds, and the speed-up.
// Usage: bench_transfer [--shape arch] [--faces 545000] [--height 14.484] [--thickness 0.001]
//                       [--runs 5] [--members 3]
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <vector>

#include "bench_args.h"
#include "family.h"
#include "slicereuse/slice_layers.h"
#include "slicereuse/transfer_contours.h"

using namespace slicereuse;

namespace {

double median_seconds(int runs, const std::function<void()>& job) {
  std::vector<double> s;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    job();
    s.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return median_of(s);
}

}  // namespace

int main(int argc, char** argv) {
  BenchArgs args = parse_bench_args(argc, argv);
  // A family pipeline reuses its output buffers from member to member; without this both sides
  // would mostly measure the kernel zeroing gigabytes of fresh pages.
  const ReuseBuffers reuse;
  SliceOptions options;
  options.thickness = args.thickness;
  const Mesh base = test::make_family_base(args.family);
  const Slices source = slice_layers(base, options);
  std::printf("shape %s, %zu faces, %zu layers, threads %d, median of %d runs\n", args.family.shape.c_str(),
              base.faces(), source.layers(), omp_get_max_threads(), args.runs);
  std::printf("%-10s %10s %9s %9s %9s %9s %8s\n", "member", "points", "resliced", "direct", "exact", "barycen.",
              "speedup");
  for (int z_change = 0; z_change < 2; ++z_change) {
    args.family.z_change = z_change;
    for (int i = 1; i < args.members; ++i) {
      const Mesh member = test::make_family_member(base, args.family, i);
      Slices direct, exact, bary;
      TransferStats stats;
      SliceOptions same_plate = options;
      same_plate.z_start = source.z_start;
      const double t_direct = median_seconds(args.runs, [&] {
        direct = Slices();
        direct = slice_layers(member, same_plate);
      });
      const double t_exact = median_seconds(args.runs, [&] {
        exact = Slices();
        exact = transfer_contours(source, member, TransferMode::Exact, &stats);
      });
      const double t_bary = median_seconds(args.runs, [&] {
        bary = Slices();
        bary = transfer_contours(source, member, TransferMode::Barycentric);
      });
      if (exact.points() != direct.points()) {
        std::fprintf(stderr, "member %d: transfer gave %zu points, direct slicing %zu\n", i, exact.points(),
                     direct.points());
        return 1;
      }
      std::printf("%-10s %10zu %9zu %9.3f %9.3f %9.3f %7.1fx\n",
                  ((z_change ? "z" : "xy") + std::to_string(i)).c_str(), exact.points(), stats.resliced_layers,
                  t_direct, t_exact, t_bary, t_direct / t_exact);
    }
  }
  return 0;
}
