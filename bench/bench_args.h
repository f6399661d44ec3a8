#pragma once
// What the benchmarks share: command-line options (the family workload and the run count), the
// median, timing a job that returns slices, and the sliced base the transfer benchmarks start from.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "family.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/slicing/slices.h"

struct BenchArgs {
  slicereuse::test::FamilyOptions family;
  double thickness = 0.001;
  int runs = 5;
  int members = 3;
  std::string out = "/tmp/slicereuse-bench";
};

inline BenchArgs parse_bench_args(int argc, char** argv) {
  BenchArgs a;
  a.family.faces = 545000;
  a.family.height = 14.484;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--shape") a.family.shape = v;
    else if (k == "--faces") a.family.faces = std::strtoull(v.c_str(), nullptr, 10);
    else if (k == "--height") a.family.height = std::atof(v.c_str());
    else if (k == "--thickness") a.thickness = std::atof(v.c_str());
    else if (k == "--runs") a.runs = std::max(1, std::atoi(v.c_str()));
    else if (k == "--members") a.members = std::max(2, std::atoi(v.c_str()));
    else if (k == "--out") a.out = v;
    else {
      std::fprintf(stderr, "unknown option %s\n", k.c_str());
      std::exit(2);
    }
  }
  return a;
}

inline double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

struct Timing {
  double seconds;  // median
  size_t points;   // of the last run's result
};

// Runs job `runs` times, keeping only one result alive at a time.
inline Timing time_runs(int runs, const std::function<slicereuse::Slices()>& job) {
  std::vector<double> s;
  size_t points = 0;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const slicereuse::Slices result = job();
    s.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    points = result.points();
  }
  return {median_of(s), points};
}

// The family's base sliced at args.thickness (the source of every transfer), after printing the
// workload line.
struct SlicedBase {
  slicereuse::Mesh base;
  slicereuse::Slices source;
};
inline SlicedBase sliced_base(const BenchArgs& args) {
  slicereuse::SliceOptions options;
  options.thickness = args.thickness;
  SlicedBase b{slicereuse::test::make_family_base(args.family), {}};
  b.source = slicereuse::slice_layers(b.base, options);
  std::printf("shape %s, %zu faces, %zu layers, threads %d, median of %d runs\n", args.family.shape.c_str(),
              b.base.faces(), b.source.layers(), omp_get_max_threads(), args.runs);
  return b;
}
