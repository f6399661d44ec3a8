// Mask benchmark: slices a generated family member (default: the arch, 14,484 layers at 1 um)
// in memory (not timed), centres it on a 1024x768 display at 75 um, then times
//   rasterize  - every layer into memory, all cores, no encoding
//   folder     - export_masks to <out>/masks (one PNG per layer)
//   sl1        - export_masks to <out>/masks.sl1
//   compare    - compare_mask_stacks(folder, sl1), which must report S = 1
// Prints the median seconds over runs and layers per second; --aa 1 for anti-aliased masks.
// Usage: bench_masks [--shape arch] [--faces 545000] [--height 14.484] [--thickness 0.001]
//                    [--runs 3] [--out /tmp/slicereuse-bench] [--aa 0]
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "bench_args.h"
#include "family.h"
#include "slicereuse/buffer.h"
#include "slicereuse/masks.h"
#include "slicereuse/slice_layers.h"

using namespace slicereuse;

namespace {

double cpu_seconds() {
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// Wall seconds of work; adds its CPU seconds (all threads) to cpu. On a shared machine the
// CPU time divided by the core count is what the wall time would be on idle cores.
double seconds_of(const std::function<void()>& work, std::vector<double>& cpu) {
  const double c0 = cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  work();
  cpu.push_back(cpu_seconds() - c0);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  bool aa = false;
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--aa" && i + 1 < argc) aa = std::atoi(argv[++i]) != 0;
    else rest.push_back(argv[i]);
  }
  BenchArgs args = parse_bench_args(int(rest.size()), rest.data());
  const Mesh mesh = test::make_family_base(args.family);
  SliceOptions options;
  options.thickness = args.thickness;
  const Slices s = slice_layers(mesh, options);

  double lo[2] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  double hi[2] = {-lo[0], -lo[1]};
  for (size_t p = 0; p < s.points(); ++p)
    for (int d = 0; d < 2; ++d) {
      lo[d] = std::min(lo[d], s.xyz[3 * p + d]);
      hi[d] = std::max(hi[d], s.xyz[3 * p + d]);
    }
  PrinterProfile profile;  // 1024 x 768 at 75 um: 76.8 x 57.6 mm
  profile.offset_x_mm = -(lo[0] + hi[0]) / 2;
  profile.offset_y_mm = -(lo[1] + hi[1]) / 2;
  profile.antialiasing = aa;

  std::filesystem::create_directories(args.out);
  const std::string folder = args.out + "/masks", sl1 = args.out + "/masks.sl1";
  std::vector<double> t_raster, t_folder, t_sl1, t_compare;
  std::vector<double> c_raster, c_folder, c_sl1, c_compare;
  StackComparison cmp;
  for (int r = 0; r < args.runs; ++r) {
    t_raster.push_back(seconds_of([&] {
#pragma omp parallel
      {
        Buffer<uint8_t> image(size_t(profile.width_px) * size_t(profile.height_px));
#pragma omp for schedule(dynamic, 16)
        for (long long k = 0; k < static_cast<long long>(s.layers()); ++k)
          rasterize_layer(s, size_t(k), profile, image.data());
      }
    }, c_raster));
    t_folder.push_back(seconds_of([&] { export_masks(s, profile, folder); }, c_folder));
    t_sl1.push_back(seconds_of([&] { export_masks(s, profile, sl1); }, c_sl1));
    t_compare.push_back(seconds_of([&] { cmp = compare_mask_stacks(folder, sl1, ""); }, c_compare));
  }
  const double L = double(s.layers());
  std::printf("shape %s, threads %d, %s masks %dx%d at %g um, extent %.2f x %.2f mm\n",
              args.family.shape.c_str(), omp_get_max_threads(), aa ? "anti-aliased" : "binary",
              profile.width_px, profile.height_px, profile.pixel_size_x_um, hi[0] - lo[0],
              hi[1] - lo[1]);
  std::printf("%8zu layers, %zu contours, %zu points; compare: min S %.9g, %llu differing pixels\n",
              s.layers(), s.contours(), s.points(), cmp.min_similarity,
              static_cast<unsigned long long>(cmp.differing_pixels));
  std::printf("%-10s %9s %12s %12s   wall seconds per run\n", "step", "seconds", "layers/s",
              "cpu-seconds");
  struct Row {
    const char* name;
    const std::vector<double>& wall;
    const std::vector<double>& cpu;
  };
  const Row rows[] = {{"rasterize", t_raster, c_raster},
                      {"folder", t_folder, c_folder},
                      {"sl1", t_sl1, c_sl1},
                      {"compare", t_compare, c_compare}};
  for (const Row& row : rows) {
    const double m = median_of(row.wall);
    std::printf("%-10s %9.3f %12.0f %12.3f  ", row.name, m, L / m, median_of(row.cpu));
    for (double x : row.wall) std::printf(" %.3f", x);
    std::printf("\n");
  }
  std::uintmax_t bytes = 0;
  for (const auto& e : std::filesystem::directory_iterator(folder)) bytes += e.file_size();
  std::printf("folder %.1f MB, sl1 %.1f MB\n", double(bytes) / 1e6,
              double(std::filesystem::file_size(sl1)) / 1e6);
  return cmp.min_similarity == 1 ? 0 : 1;
}
