// Hollowing benchmark: a generated part sliced directly, then its cavity (cavity_regions) from its
// layers' regions. Prints the part's layers and points, the cavity's volume, and the median
// seconds of the cavity in all and per layer (the layers' regions made beforehand, not counted),
// wall and CPU (all threads': on a busy machine the steadier figure, and PrusaSlicer's user time's
// match). Then the plate job end to end into 50 um masks, solid and hollowed, drained and
// labelled: what the three add to it. Then the part hollowed alone (no drain holes), and its
// thinnest wall measured on its masks in 3-D (wall_measure.h), against the wall asked less a pixel.
// Usage: bench_hollowing [--shape sphere] [--faces 200000] [--height 35] [--thickness 0.05]
//                        [--wall 2] [--closing 2] [--runs 3]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_args.h"
#include "family.h"
#include "wall_measure.h"
#include "slicereuse/hollowing/cavity.h"
#include "slicereuse/hollowing/drain_holes.h"
#include "slicereuse/plates/plate_job.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/slicing/slice_layers.h"

using namespace slicereuse;

int main(int argc, char** argv) {
  HollowingOptions hollowing;
  hollowing.wall_mm = 2;
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    if ((k == "--wall" || k == "--closing") && i + 1 < argc)
      (k == "--wall" ? hollowing.wall_mm : hollowing.closing_mm) = std::atof(argv[++i]);
    else
      rest.push_back(argv[i]);
  }
  char* defaults[] = {argv[0], (char*)"--shape", (char*)"sphere", (char*)"--faces", (char*)"200000",
                      (char*)"--height", (char*)"35", (char*)"--thickness", (char*)"0.05", (char*)"--runs", (char*)"3"};
  std::vector<char*> all(defaults, defaults + 11);
  all.insert(all.end(), rest.begin() + 1, rest.end());
  const BenchArgs args = parse_bench_args(int(all.size()), all.data());
  const Mesh mesh = test::make_family_base(args.family);
  SliceOptions options;
  options.thickness = args.thickness;
  const Slices s = slice_layers(mesh, options);
  std::vector<ClipperLib::Paths> layers(s.layers());
  for (size_t k = 0; k < s.layers(); ++k) layers[k] = layer_region(LayerView(s, k));
  std::vector<double> seconds, cpu;
  std::vector<ClipperLib::Paths> cavity;
  for (int r = 0; r < args.runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    cavity = cavity_regions(layers, s.thickness, hollowing);
    cpu.push_back(double(std::clock() - c0) / CLOCKS_PER_SEC);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  double part = 0, hollow = 0;
  size_t cavity_points = 0;
  for (size_t k = 0; k < s.layers(); ++k) {
    part += region_area_mm2(layers[k]) * s.thickness;
    hollow += region_area_mm2(cavity[k]) * s.thickness;
    for (const auto& p : cavity[k]) cavity_points += p.size();
  }
  const double median = median_of(seconds);
  std::printf("shape %s, height %g mm, layers of %g mm, wall %g mm, closing %g mm, threads %d\n",
              args.family.shape.c_str(), args.family.height, args.thickness, hollowing.wall_mm,
              hollowing.closing_mm, omp_get_max_threads());
  const double cpu_median = median_of(cpu);
  std::printf("%9s %7s %9s %10s %10s %8s %9s %9s %12s\n", "faces", "layers", "points", "part mm3", "cavity mm3",
              "saved", "seconds", "CPU s", "CPU ms/layer");
  std::printf("%9zu %7zu %9zu %10.1f %10.1f %7.1f%% %9.3f %9.3f %12.3f\n", mesh.faces(), s.layers(), s.points(), part,
              hollow, 100 * hollow / part, median, cpu_median, 1e3 * cpu_median / double(s.layers()));
  std::printf("cavity points %zu; runs:", cavity_points);
  for (double t : seconds) std::printf(" %.3f", t);
  std::printf("\n");

  // The masks: the part centred on a display of 50 um pixels with a millimetre to spare.
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (size_t v = 0; v < mesh.V.size(); v += 3)
    x0 = std::min(x0, mesh.V[v]), x1 = std::max(x1, mesh.V[v]), y0 = std::min(y0, mesh.V[v + 1]),
    y1 = std::max(y1, mesh.V[v + 1]);
  Mesh centred = mesh;
  for (size_t v = 0; v < centred.V.size(); v += 3) centred.V[v] -= (x0 + x1) / 2, centred.V[v + 1] -= (y0 + y1) / 2;
  constexpr double kPixelMm = 0.05;
  PrinterProfile display;
  display.width_px = int(std::ceil((x1 - x0 + 2) / kPixelMm)), display.height_px = int(std::ceil((y1 - y0 + 2) / kPixelMm));
  display.pixel_size_x_um = display.pixel_size_y_um = kPixelMm * 1e3;
  const std::string folder = (std::filesystem::temp_directory_path() / "bench_hollowing_masks").string();
  // The plate job end to end, solid and then hollowed, drained (PrusaSlicer's 4 mm hole) and
  // labelled (on its front, at the height that fits; unlabelled when none does): what the three
  // add to the member's job, in wall and CPU seconds (medians).
  PlateJobOptions solid;
  solid.slicing = options;
  PlateJobOptions whole = solid;
  whole.hollowing = hollowing;
  whole.drain_hole_mm = kDrainHoleMm;
  whole.labels = {"C-0412"};
  whole.label.side = LabelSide::Front;
  whole.label.depth_mm = std::min(whole.label.depth_mm, hollowing.wall_mm - 1);
  whole.allow_unlabelled = true;
  std::vector<double> job_wall[2], job_cpu[2];
  PlateJobStats st;
  for (int r = 0; r < args.runs; ++r)
    for (int hollowed = 0; hollowed < 2; ++hollowed) {
      std::filesystem::remove_all(folder);
      const auto t0 = std::chrono::steady_clock::now();
      const std::clock_t c0 = std::clock();
      st = export_plate({centred}, hollowed ? whole : solid, display, folder);
      job_cpu[hollowed].push_back(double(std::clock() - c0) / CLOCKS_PER_SEC);
      job_wall[hollowed].push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
  std::printf("the plate job into %g um masks, solid %.3f s (CPU %.3f), hollowed, drained (%zu holes) and labelled "
              "(%.3g mm high) %.3f s (CPU %.3f): the three add %.3f s (CPU %.3f)\n",
              kPixelMm * 1e3, median_of(job_wall[0]), median_of(job_cpu[0]), st.drain_holes[0].size(),
              st.label_heights_mm[0], median_of(job_wall[1]), median_of(job_cpu[1]),
              median_of(job_wall[1]) - median_of(job_wall[0]), median_of(job_cpu[1]) - median_of(job_cpu[0]));

  PlateJobOptions o = solid;
  o.hollowing = hollowing;
  std::filesystem::remove_all(folder);
  export_plate({centred}, o, display, folder);
  MaskStack stack(folder);
  const test::WallMeasure walls = test::measure_walls(stack, kPixelMm, s.thickness, hollowing.wall_mm + 1);
  std::printf("on %zu masks of %g um pixels: thinnest wall %.3f mm between pixel centres (at least %.3f: the wall "
              "asked less a pixel), cavity %.1f mm3\n",
              stack.layers(), kPixelMm * 1e3, walls.thinnest_mm, hollowing.wall_mm - kPixelMm, walls.cavity_mm3);
  std::filesystem::remove_all(folder);
  return 0;
}
