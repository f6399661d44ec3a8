#pragma once
// Command-line options shared by the benchmarks: the family workload and the run count.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "family.h"

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
