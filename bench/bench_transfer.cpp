// Transfer benchmark: direct slicing of family members versus exact and barycentric transfer
// of member 0's encoding, measured in the same run so the ratio is meaningful on a shared
// machine. Prints per member: points, re-sliced layers, median seconds, and the speed-up.
// Usage: bench_transfer [--shape arch] [--faces 545000] [--height 14.484] [--thickness 0.001]
//                       [--runs 5] [--members 3]
#include <chrono>
#include <cstdio>
#include <vector>

#include "bench_args.h"
#include "family.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/transfer/transfer_contours.h"

using namespace slicereuse;

int main(int argc, char** argv) {
  BenchArgs args = parse_bench_args(argc, argv);
  // A family pipeline reuses its output buffers from member to member; without this both sides
  // would mostly measure the kernel zeroing gigabytes of fresh pages.
  const ReuseBuffers reuse;
  const SlicedBase sliced = sliced_base(args);
  const Mesh& base = sliced.base;
  const Slices& source = sliced.source;
  // Computed once per encoding, they serve every member (see encoded_edge_ends).
  Buffer<uint32_t> ends;
  std::vector<double> ends_seconds;
  for (int r = 0; r < args.runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    ends = encoded_edge_ends(source, base);
    ends_seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::printf("encoded edge ends, once per encoding: %.3f s\n", median_of(ends_seconds));
  std::printf("seconds: direct slicing; exact transfer with the target's encoding, then through the edge ends,\n"
              "then contours only through the edge ends; barycentric. speed-up: direct / each exact column\n");
  std::printf("%-6s %9s %8s %7s %7s %7s %7s %7s %7s %7s %7s\n", "member", "points", "resliced", "direct", "exact",
              "ends", "contour", "barycen", "exact", "ends", "contour");
  for (test::ZChange z_change : {test::ZChange::None, test::ZChange::Band, test::ZChange::Everywhere}) {
    args.family.z_change = z_change;
    for (int i = 1; i < args.members; ++i) {
      const Mesh member = test::make_family_member(base, args.family, i);
      SliceOptions same_plate;
      same_plate.thickness = source.thickness;
      same_plate.z_start = source.z_start;
      TransferStats stats;
      const Timing direct = time_runs(args.runs, [&] { return slice_layers(member, same_plate); });
      const Timing exact = time_runs(args.runs, [&] {
        return transfer_contours(source, member, TransferOptions(TransferMode::Exact), &stats);
      });
      const Timing prepared = time_runs(args.runs, [&] {
        return transfer_contours(source, ends, member, TransferOptions(TransferMode::Exact));
      });
      const Timing contours = time_runs(args.runs, [&] {
        return transfer_contours(source, ends, member, TransferOptions(TransferMode::Exact, false));
      });
      const Timing bary = time_runs(args.runs, [&] {
        return transfer_contours(source, ends, member, TransferOptions(TransferMode::Barycentric));
      });
      if (exact.points != direct.points || prepared.points != direct.points || contours.points != direct.points) {
        std::fprintf(stderr, "member %d: transfer gave %zu points, direct slicing %zu\n", i, exact.points,
                     direct.points);
        return 1;
      }
      std::printf("%-6s %9zu %8zu %7.3f %7.3f %7.3f %7.3f %7.3f %6.1fx %6.1fx %6.1fx\n",
                  (std::string(z_change == test::ZChange::None ? "xy" : z_change == test::ZChange::Band ? "band" : "z") +
                   std::to_string(i)).c_str(), exact.points, stats.resliced_layers,
                  direct.seconds, exact.seconds, prepared.seconds, contours.seconds, bary.seconds,
                  direct.seconds / exact.seconds, direct.seconds / prepared.seconds,
                  direct.seconds / contours.seconds);
    }
  }
  return 0;
}
