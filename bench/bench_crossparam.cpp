// Cross-parameterization benchmark: the map from a family base onto a deformed member of
// another tessellation of the same shape (about 10 % more faces, so vertex counts, faces and
// order all differ), for pairs of about 200k and 500k source faces. Prints per pair the faces,
// the median seconds of the whole cross_parameterize (checks, registration, projection,
// quality report, patches) and the quality report of the last run.
// Usage: bench_crossparam [--shape arch] [--runs 5] [--faces N  (one pair of N faces instead)]
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <vector>

#include "bench_args.h"
#include "family.h"
#include "slicereuse/crossparam/cross_parameterize.h"

using namespace slicereuse;

int main(int argc, char** argv) {
  BenchArgs args = parse_bench_args(argc, argv);
  std::vector<size_t> sizes = {200000, 500000};
  for (int i = 1; i + 1 < argc; i += 2)
    if (std::string(argv[i]) == "--faces") sizes = {args.family.faces};
  std::printf("shape %s, threads %d, median of %d runs\n", args.family.shape.c_str(), omp_get_max_threads(), args.runs);
  std::printf("%9s %9s %8s %8s %10s %10s %8s %8s %7s %5s\n", "src faces", "tgt faces", "seconds", "flipped",
              "dz max", "dz rms", "area", "angle", "patches", "genus");
  for (size_t faces : sizes) {
    test::FamilyOptions o = args.family;
    o.faces = faces;
    const Mesh source = test::make_family_base(o);
    o.faces = faces + faces / 10;
    const Mesh target = test::make_family_member(test::make_family_base(o), o, 1);
    std::vector<double> seconds;
    CrossParamQuality q;
    for (int r = 0; r < args.runs; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      const CrossParamResult result = cross_parameterize(source, target, {});
      seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      q = result.quality;
    }
    std::printf("%9zu %9zu %8.3f %8llu %10.3g %10.3g %8.4f %8.3f %7llu %5d\n", source.faces(), target.faces(),
                median_of(seconds), (unsigned long long)q.flipped_triangles, q.max_height_error, q.rms_height_error,
                q.area_distortion, q.angle_distortion, (unsigned long long)q.patches, q.genus);
    std::fflush(stdout);
  }
  return 0;
}
