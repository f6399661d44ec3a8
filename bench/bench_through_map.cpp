// Transfer-through-map benchmark: a family member with other connectivity (the member with its
// vertices renumbered and faces reordered, shuffle_mesh.h) and the exact map onto it
// (map_onto_shuffled), so the figures isolate transfer from the map's construction. Direct
// slicing of the target, exact transfer through the map (tracing the target's loops from the
// map's seeds, certified) and barycentric transfer, measured in the same run, so the ratios are
// meaningful on a shared machine. Prints medians, traced/re-sliced layers and the ratios.
// Usage: bench_through_map [--shape arch] [--faces 545000] [--height 14.484] [--thickness 0.001]
//                          [--runs 5] [--members 3]
#include <cstdio>

#include "bench_args.h"
#include "family.h"
#include "shuffle_mesh.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/transfer/transfer_through_map.h"

using namespace slicereuse;

int main(int argc, char** argv) {
  BenchArgs args = parse_bench_args(argc, argv);
  const ReuseBuffers reuse;
  const SlicedBase sliced = sliced_base(args);
  const Mesh& base = sliced.base;
  const Slices& source = sliced.source;
  std::printf("member  points      direct_s  exact_s  traced  resliced  bary_s  direct/exact  direct/bary\n");
  for (int m = 1; m <= args.members; ++m) {
    test::ShuffledMesh shuffled = test::shuffle_mesh(test::make_family_member(base, args.family, m), 1000 + m);
    const SurfaceMap map = test::map_onto_shuffled(base, shuffled);
    const Mesh& target = shuffled.mesh;
    SliceOptions plate;
    plate.thickness = source.thickness;
    plate.z_start = source.z_start;
    TransferStats st;
    const Timing direct = time_runs(args.runs, [&] { return slice_layers(target, plate); });
    const Timing exact =
        time_runs(args.runs, [&] { return transfer_through_map(source, map, target, TransferOptions(TransferMode::Exact), &st); });
    const Timing bary = time_runs(args.runs, [&] {
      return transfer_through_map(source, map, target, TransferOptions(TransferMode::Barycentric, false));
    });
    if (exact.points != direct.points)
      std::printf("ERROR: exact transfer gave %zu points, direct slicing %zu\n", exact.points, direct.points);
    std::printf("%6d  %10zu  %8.3f  %7.3f  %6zu  %8zu  %6.3f  %12.2f  %11.2f\n", m, direct.points, direct.seconds,
                exact.seconds, st.transferred_layers, st.resliced_layers, bary.seconds, direct.seconds / exact.seconds,
                direct.seconds / bary.seconds);
  }
  return 0;
}
