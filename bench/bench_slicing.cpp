// Slicing benchmark: a generated closed family member, sliced with encoding in memory.
// Prints faces, layers, points, median seconds over runs and points per second.
// Usage: bench_slicing [--shape arch] [--faces 545000] [--height 14.484] [--thickness 0.001] [--runs 5]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "bench_args.h"
#include "family.h"
#include "slicereuse/slicing/slice_layers.h"

using namespace slicereuse;

int main(int argc, char** argv) {
  const BenchArgs args = parse_bench_args(argc, argv);
  const Mesh mesh = test::make_family_base(args.family);
  SliceOptions options;
  options.thickness = args.thickness;
  std::vector<double> seconds;
  Slices s;
  for (int r = 0; r < args.runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    s = slice_layers(mesh, options);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  const double median = median_of(seconds);
  std::printf("shape %s, threads %d\n", args.family.shape.c_str(), omp_get_max_threads());
  std::printf("%10s %8s %10s %9s %9s %14s\n", "faces", "layers", "points", "contours", "seconds", "points/s");
  std::printf("%10zu %8zu %10zu %9zu %9.3f %14.0f\n", mesh.faces(), s.layers(), s.points(), s.contours(), median,
              double(s.points()) / median);
  std::printf("runs:");
  for (double t : seconds) std::printf(" %.3f", t);
  std::printf("\n");
  return 0;
}
