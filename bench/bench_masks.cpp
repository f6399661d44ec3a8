// Mask benchmark: slices a generated family member (default: the arch, 14,484 layers at 1 um)
// in memory (not timed), centres it on a 1024x768 display at 75 um (--printer ID: a preset's
// display and job instead, e.g. elegoo_saturn_3_ultra; --aa still chooses the masks), then times
//   rasterize  - every layer into memory, all cores, no encoding
//   folder     - export_masks to <out>/masks (one PNG per layer)
//   sl1        - export_masks to <out>/masks.sl1
//   compare    - compare_mask_stacks(folder, sl1), which must report S = 1 and grey difference 0
//   goo, ctb, pwmx, pm4n, ... - (only when asked for) export_masks to <out>/masks.<step>, any
//                print format of print_formats.h, and, with the sl1 step, compare_mask_stacks(sl1,
//                it), which must report S = 1 (not timed; a .goo has the sl1's grey levels, a
//                .ctb or Anycubic file the nearest it holds: their largest grey difference)
//   layer      - (only when asked for) every layer on one thread, as an .sl1 encodes it:
//                rasterize_layer_runs, then encode_mask_png of the runs (anti-aliased: also
//                rasterize_layer_antialiased_png); microseconds per layer of each in thread CPU
//                time (the fastest run: the least disturbed by other processes on a shared
//                machine), runs and PNG bytes per layer
//   deflate    - (only when asked for) the PNG image data of every 8th layer (filter byte and
//                8-bit row, as in an .sl1) deflated on one thread by RunDeflater and by
//                libdeflate at levels 1, 3 and 6: seconds and total compressed size each
// Prints the median seconds over runs and layers per second, and each file's size. --aa 1 for anti-aliased masks
// (--gamma G, default 1), --aa 0,1 for both in the same run, taking turns within each run, and
// their sl1 time ratio; their archives are <out>/masks.sl1 and <out>/masks_aa.sl1.
// --reference R (an .sl1 or folder made by another build, e.g. before a change) compares the
// binary sl1 step's archive against R with compare_mask_stacks, which must report S = 1, 0
// differing pixels and grey difference 0; --aa-reference R the anti-aliased one.
// Usage: bench_masks [--shape arch] [--faces 545000] [--height 14.484] [--thickness 0.001]
//                    [--runs 3] [--out /tmp/slicereuse-bench] [--aa 0|1|0,1] [--gamma 1]
//                    [--reference R] [--aa-reference R] [--printer ID]
//                    [--steps rasterize,folder,sl1,compare[,goo][,ctb][,pwmx]...[,layer][,deflate]]
#include <libdeflate.h>
#include <omp.h>
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "bench_args.h"
#include "family.h"
#include "slicereuse/png/deflate_runs.h"
#include "slicereuse/png/mask_png.h"
#include "slicereuse/printer/print_formats.h"
#include "slicereuse/printer/printer_presets.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/printfiles/compare_mask_stacks.h"
#include "slicereuse/printfiles/export_masks.h"
#include "slicereuse/raster/rasterize_layer.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/util/buffer.h"

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

bool wants(const std::string& steps, const char* step) {
  return ("," + steps + ",").find("," + std::string(step) + ",") != std::string::npos;
}

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// RunDeflater against libdeflate on the same PNG image data, one thread, same layers.
void compare_deflaters(const Slices& s, const PrinterProfile& profile) {
  const size_t W = size_t(profile.width_px), H = size_t(profile.height_px), stride = 8;
  Buffer<uint8_t> image(W * H);
  std::vector<uint8_t> data((W + 1) * H), z;
  const int levels[] = {1, 3, 6};
  libdeflate_compressor* c[3];
  for (int i = 0; i < 3; ++i) c[i] = libdeflate_alloc_compressor(levels[i]);
  double t_run = 0, t_lib[3] = {0, 0, 0};
  size_t n_run = 0, n_lib[3] = {0, 0, 0}, layers = 0;
  for (size_t k = 0; k < s.layers(); k += stride, ++layers) {
    rasterize_layer(s, k, profile, image.data());
    for (size_t r = 0; r < H; ++r) {
      data[r * (W + 1)] = 0;
      std::memcpy(&data[r * (W + 1) + 1], &image[r * W], W);
    }
    z.clear();
    auto t0 = std::chrono::steady_clock::now();
    RunDeflater d;
    d.add(data.data(), data.size());
    d.finish(z);
    t_run += since(t0);
    n_run += z.size();
    for (int i = 0; i < 3; ++i) {
      z.resize(libdeflate_zlib_compress_bound(c[i], data.size()));
      t0 = std::chrono::steady_clock::now();
      const size_t n = libdeflate_zlib_compress(c[i], data.data(), data.size(), z.data(), z.size());
      t_lib[i] += since(t0);
      n_lib[i] += n;
    }
  }
  for (auto* x : c) libdeflate_free_compressor(x);
  const double mb = double(layers) * double(data.size()) / 1e6;
  std::printf("deflate, %zu layers (every %zu-th), %.0f MB of image data, one thread:\n", layers, stride, mb);
  std::printf("  %-14s %8.3f s %8.0f MB/s %10zu bytes\n", "RunDeflater", t_run, mb / t_run, n_run);
  for (int i = 0; i < 3; ++i)
    std::printf("  libdeflate %-3d %8.3f s %8.0f MB/s %10zu bytes  (RunDeflater %.2fx faster)\n", levels[i],
                t_lib[i], mb / t_lib[i], n_lib[i], t_lib[i] / t_run);
}

// CPU seconds of the calling thread: unlike wall time, not inflated while other processes hold
// the core, so single-thread figures compare across runs on a shared machine.
double thread_seconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double fastest(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

// Reads layer k's points (returns their sum so the reads stay): mask export reads each layer's
// points for its area and extent just before it rasterizes the layer, which then finds them in
// cache.
double touch_points(const Slices& s, size_t k) {
  double sum = 0;
  const size_t a = s.contour_begin[s.layer_begin[k]], b = s.contour_begin[s.layer_begin[k + 1]];
  for (size_t i = 3 * a; i < 3 * b; i += 4) sum += s.xyz[i];  // one read per 32 bytes, every cache line
  return sum;
}

// One thread, every layer: rasterize_layer_runs (rasterize_layer_antialiased_runs when
// anti-aliased), then encode_mask_png of its runs, timed apart in thread CPU time; anti-aliased
// also rasterize_layer_antialiased_png, which .sl1 export calls instead of the two. Each
// layer's points are read first, untimed, as in mask export.
void time_layers(const Slices& s, const PrinterProfile& profile, int runs) {
  const bool aa = profile.antialiasing;
  MaskRuns mask;
  std::vector<uint8_t> png;
  std::vector<double> t_runs, t_png, t_direct;
  size_t n_runs = 0, n_bytes = 0;
  double touched = 0;
  for (int r = 0; r < runs; ++r) {
    double a = 0, b = 0, c = 0;
    n_runs = n_bytes = 0;
    for (size_t k = 0; k < s.layers(); ++k) {
      touched += touch_points(s, k);
      const double t0 = thread_seconds();
      if (aa)
        rasterize_layer_antialiased_runs(s, k, profile, mask);
      else
        rasterize_layer_runs(s, k, profile, mask);
      const double t1 = thread_seconds();
      encode_mask_png(mask, png);
      b += thread_seconds() - t1;
      a += t1 - t0;
      n_runs += mask.row_begin.back();
      n_bytes += png.size();
      if (!aa) continue;
      touched += touch_points(s, k);
      const double t2 = thread_seconds();
      rasterize_layer_antialiased_png(s, k, profile, png);
      c += thread_seconds() - t2;
    }
    t_runs.push_back(a);
    t_png.push_back(b);
    t_direct.push_back(c);
  }
  const double L = double(s.layers());
  std::printf("layer, one thread, cpu: %s %.1f us, encode_mask_png(runs) %.1f us, together %.1f us;",
              aa ? "rasterize_layer_antialiased_runs" : "rasterize_layer_runs", 1e6 * fastest(t_runs) / L,
              1e6 * fastest(t_png) / L, 1e6 * (fastest(t_runs) + fastest(t_png)) / L);
  if (aa) std::printf(" rasterize_layer_antialiased_png %.1f us;", 1e6 * fastest(t_direct) / L);
  std::printf(" %.0f runs, %.0f PNG bytes per layer\n", double(n_runs) / L, double(n_bytes) / L);
  if (touched == 0.5) std::printf("\n");  // keeps touch_points' reads
}

}  // namespace

// A print format's step: its file and its wall and CPU seconds per run.
struct FileStep {
  std::string name, path;
  std::vector<double> wall, cpu;
};

// One kind of mask the steps are run for, and what they measured.
struct Mode {
  PrinterProfile profile;
  std::string folder, sl1, reference;
  std::vector<FileStep> files;  // the print formats asked for besides the sl1
  std::vector<double> t_raster, t_folder, t_sl1, t_compare;
  std::vector<double> c_raster, c_folder, c_sl1, c_compare;
  StackComparison cmp;
  const char* name() const { return profile.antialiasing ? "anti-aliased" : "binary"; }
};

int main(int argc, char** argv) {
  std::string aa = "0", steps = "rasterize,folder,sl1,compare", reference, aa_reference, printer;
  double gamma = 1;
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--aa" && i + 1 < argc) aa = argv[++i];
    else if (std::string(argv[i]) == "--gamma" && i + 1 < argc) gamma = std::atof(argv[++i]);
    else if (std::string(argv[i]) == "--steps" && i + 1 < argc) steps = argv[++i];
    else if (std::string(argv[i]) == "--reference" && i + 1 < argc) reference = argv[++i];
    else if (std::string(argv[i]) == "--aa-reference" && i + 1 < argc) aa_reference = argv[++i];
    else if (std::string(argv[i]) == "--printer" && i + 1 < argc) printer = argv[++i];
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
  std::filesystem::create_directories(args.out);
  std::vector<Mode> modes;
  for (const char* kind : {"0", "1"}) {
    if (!wants(aa, kind)) continue;
    Mode m;
    if (!printer.empty()) m.profile = printer_preset(printer).profile;
    m.profile.offset_x_mm = -(lo[0] + hi[0]) / 2;  // centred
    m.profile.offset_y_mm = -(lo[1] + hi[1]) / 2;
    m.profile.antialiasing = kind[0] == '1';
    m.profile.gamma = gamma;
    const std::string suffix = m.profile.antialiasing ? "_aa" : "";
    m.folder = args.out + "/masks" + suffix;
    m.sl1 = args.out + "/masks" + suffix + ".sl1";
    for (const PrintFormat& f : print_formats())
      if (f.extension != ".sl1" && f.extension != ".sl1s" && wants(steps, f.extension.c_str() + 1))
        m.files.push_back({f.extension.substr(1), args.out + "/masks" + suffix + f.extension, {}, {}});
    m.reference = m.profile.antialiasing ? aa_reference : reference;
    modes.push_back(m);
  }
  std::printf("shape %s, threads %d, %s%dx%d at %g um, extent %.2f x %.2f mm, gamma %g (anti-aliased)\n",
              args.family.shape.c_str(), omp_get_max_threads(), printer.empty() ? "" : (printer + " ").c_str(),
              modes[0].profile.width_px,
              modes[0].profile.height_px, modes[0].profile.pixel_size_x_um, hi[0] - lo[0], hi[1] - lo[1], gamma);
  std::printf("%8zu layers, %zu contours, %zu points\n", s.layers(), s.contours(), s.points());
  for (const Mode& m : modes) {
    std::printf("%s masks:\n", m.name());
    if (wants(steps, "layer")) time_layers(s, m.profile, args.runs);
    if (wants(steps, "deflate")) compare_deflaters(s, m.profile);
  }

  const bool compare = wants(steps, "compare") && wants(steps, "folder") && wants(steps, "sl1");
  // The kinds take turns within each run, so both meet the same load on a shared machine.
  for (int r = 0; r < args.runs; ++r)
    for (Mode& m : modes) {
      const PrinterProfile& profile = m.profile;
      if (wants(steps, "rasterize"))
        m.t_raster.push_back(seconds_of([&] {
#pragma omp parallel
          {
            Buffer<uint8_t> image(size_t(profile.width_px) * size_t(profile.height_px));
#pragma omp for schedule(dynamic, 16)
            for (long long k = 0; k < static_cast<long long>(s.layers()); ++k)
              rasterize_layer(s, size_t(k), profile, image.data());
          }
        }, m.c_raster));
      if (wants(steps, "folder"))
        m.t_folder.push_back(seconds_of([&] { export_masks(s, profile, m.folder); }, m.c_folder));
      if (wants(steps, "sl1")) m.t_sl1.push_back(seconds_of([&] { export_masks(s, profile, m.sl1); }, m.c_sl1));
      for (FileStep& f : m.files) f.wall.push_back(seconds_of([&] { export_masks(s, profile, f.path); }, f.cpu));
      if (compare)
        m.t_compare.push_back(seconds_of([&] { m.cmp = compare_mask_stacks(m.folder, m.sl1, ""); }, m.c_compare));
    }
  const double L = double(s.layers());
  bool ok = true;
  for (const Mode& m : modes) {
    std::printf("%s masks:\n", m.name());
    if (compare) {
      std::printf("compare: min S %.9g, %llu differing pixels, max grey difference %d\n", m.cmp.min_similarity,
                  static_cast<unsigned long long>(m.cmp.differing_pixels), m.cmp.max_grey_difference);
      ok = ok && m.cmp.min_similarity == 1 && m.cmp.max_grey_difference == 0;
    }
    for (const FileStep& f : m.files) {
      if (m.t_sl1.empty()) break;
      const StackComparison c = compare_mask_stacks(m.sl1, f.path, "");
      std::printf("%s against sl1: min S %.9g, %llu differing pixels, max grey difference %d\n", f.name.c_str(),
                  c.min_similarity, static_cast<unsigned long long>(c.differing_pixels), c.max_grey_difference);
      ok = ok && c.min_similarity == 1 && c.differing_pixels == 0;
    }
    std::printf("%-10s %9s %12s %12s   wall seconds per run\n", "step", "seconds", "layers/s", "cpu-seconds");
    struct Row {
      const char* name;
      const std::vector<double>& wall;
      const std::vector<double>& cpu;
    };
    std::vector<Row> rows = {{"rasterize", m.t_raster, m.c_raster},
                             {"folder", m.t_folder, m.c_folder},
                             {"sl1", m.t_sl1, m.c_sl1},
                             {"compare", m.t_compare, m.c_compare}};
    for (const FileStep& f : m.files) rows.push_back({f.name.c_str(), f.wall, f.cpu});
    for (const Row& row : rows) {
      if (row.wall.empty()) continue;
      const double med = median_of(row.wall);
      std::printf("%-10s %9.3f %12.0f %12.3f  ", row.name, med, L / med, median_of(row.cpu));
      for (double x : row.wall) std::printf(" %.3f", x);
      std::printf("\n");
    }
    if (!m.t_folder.empty()) {
      std::uintmax_t bytes = 0;
      for (const auto& e : std::filesystem::directory_iterator(m.folder)) bytes += e.file_size();
      std::printf("folder %.1f MB\n", double(bytes) / 1e6);
    }
    if (!m.t_sl1.empty()) std::printf("sl1 %.1f MB\n", double(std::filesystem::file_size(m.sl1)) / 1e6);
    for (const FileStep& f : m.files)
      std::printf("%s %.1f MB\n", f.name.c_str(), double(std::filesystem::file_size(f.path)) / 1e6);
    if (!m.reference.empty() && !m.t_sl1.empty()) {
      const StackComparison ref = compare_mask_stacks(m.reference, m.sl1, "");
      // S is taken on the binary threshold: only a grey difference of 0 means every level kept.
      ok = ok && ref.min_similarity == 1 && ref.differing_pixels == 0 && ref.max_grey_difference == 0;
      std::printf("against %s: min S %.9g, %llu differing pixels, max grey difference %d\n", m.reference.c_str(),
                  ref.min_similarity, static_cast<unsigned long long>(ref.differing_pixels), ref.max_grey_difference);
    }
  }
  if (modes.size() == 2 && !modes[0].t_sl1.empty())
    std::printf("sl1 anti-aliased / binary: %.2fx wall, %.2fx cpu (medians)\n",
                median_of(modes[1].t_sl1) / median_of(modes[0].t_sl1), median_of(modes[1].c_sl1) / median_of(modes[0].c_sl1));
  return ok ? 0 : 1;
}
