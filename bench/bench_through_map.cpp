// Transfer-through-map benchmark: a family member with other connectivity (the member with its
// vertices renumbered and faces reordered, shuffle_mesh.h) and the exact map onto it
// (map_onto_shuffled), so the figures isolate transfer from the map's construction. Direct
// slicing of the target, exact transfer through the map (tracing the target's loops from the
// map's seeds, certified) and barycentric transfer, measured in the same run, so the ratios are
// meaningful on a shared machine. Prints medians, traced/re-sliced layers and the ratios.
// Usage: bench_through_map [--shape arch] [--faces 545000] [--height 14.484] [--thickness 0.001]
//                          [--runs 5] [--members 3]
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <vector>

#include "bench_args.h"
#include "family.h"
#include "shuffle_mesh.h"
#include "slicereuse/slice_layers.h"
#include "slicereuse/transfer_through_map.h"

using namespace slicereuse;

namespace {

double median_seconds(int runs, const std::function<Slices()>& job, size_t& points) {
  std::vector<double> s;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const Slices result = job();
    s.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    points = result.points();
  }
  return median_of(s);
}

}  // namespace

int main(int argc, char** argv) {
  BenchArgs args = parse_bench_args(argc, argv);
  const ReuseBuffers reuse;
  SliceOptions options;
  options.thickness = args.thickness;
  const Mesh base = test::make_family_base(args.family);
  const Slices source = slice_layers(base, options);
  std::printf("shape %s, %zu faces, %zu layers, threads %d, median of %d runs\n", args.family.shape.c_str(),
              base.faces(), source.layers(), omp_get_max_threads(), args.runs);
  std::printf("member  points      direct_s  exact_s  traced  resliced  bary_s  direct/exact  direct/bary\n");
  for (int m = 1; m <= args.members; ++m) {
    test::ShuffledMesh shuffled = test::shuffle_mesh(test::make_family_member(base, args.family, m), 1000 + m);
    const SurfaceMap map = test::map_onto_shuffled(base, shuffled);
    const Mesh& target = shuffled.mesh;
    SliceOptions plate = options;
    plate.z_start = source.z_start;
    size_t points = 0, exact_points = 0, bary_points = 0;
    TransferStats st;
    const double direct = median_seconds(args.runs, [&] { return slice_layers(target, plate); }, points);
    const double exact = median_seconds(
        args.runs, [&] { return transfer_through_map(source, map, target, TransferMode::Exact, &st); }, exact_points);
    const double bary = median_seconds(
        args.runs,
        [&] { return transfer_through_map(source, map, target, TransferOptions(TransferMode::Barycentric, false)); },
        bary_points);
    if (exact_points != points) std::printf("ERROR: exact transfer gave %zu points, direct %zu\n", exact_points, points);
    std::printf("%6d  %10zu  %8.3f  %7.3f  %6zu  %8zu  %6.3f  %12.2f  %11.2f\n", m, points, direct, exact,
                st.transferred_layers, st.resliced_layers, bary, direct / exact, direct / bary);
  }
  return 0;
}
