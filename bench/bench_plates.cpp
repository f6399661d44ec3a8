// Plates (issue #17): seconds per build plate of family members, by reuse (the source's encoding
// transferred onto every placed member, exact) against direct slicing of every placed member,
// both writing the plate's print file, and the arrangement's own seconds. Also writes the first
// S plates' placed members, a plate as one binary STL (plate_<k>.stl; --stl-plates S, default
// 1), and PrusaSlicer's display options for the profile (prusa_display_args), for
// bench_plates.sh's PrusaSlicer runs on the same plates.
//   bench_plates [--printer ID] [--faces N] [--thickness MM] [--members M] [--plates P] [--format EXT]
//                [--repeat R] [--stl-plates S] [--out DIR]
// --members: members besides the source (default 20); --plates: how many plates to time (default
// all); --format: the print file's extension (.sl1, .sl1s, .goo; default the printer's own, a PNG
// folder for the method's display, whose thousands of files time the file system more than the
// masks at 1 um); --repeat: make each plate by reuse R times in a row and give the median (the
// first run's seconds in brackets: it may fill fresh pages, the others reuse them). Freed buffers are kept for the next plate (ReuseBuffers), as Make Plate Job keeps them:
// the first plate fills fresh pages, the others reuse them; the median is over the plates timed.
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "bench_args.h"
#include "family.h"
#include "slicereuse/plates/arrange_plates.h"
#include "slicereuse/plates/placements_file.h"
#include "slicereuse/plates/plate_file_names.h"
#include "slicereuse/plates/plate_job.h"
#include "slicereuse/plates/plate_layout.h"
#include "slicereuse/printer/printer_presets.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/buffer.h"
#include "slicereuse/util/memory_budget.h"

using namespace slicereuse;

namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// A binary STL of several meshes: what PrusaSlicer reads (it reads no PLY).
void write_stl(const std::string& path, const std::vector<Mesh>& meshes) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) {
    std::perror(path.c_str());
    std::exit(1);
  }
  char header[80] = "slicereuse bench_plates plate";
  uint32_t n = 0;
  for (const Mesh& m : meshes) n += uint32_t(m.faces());
  std::fwrite(header, 1, 80, f);
  std::fwrite(&n, 4, 1, f);
  for (const Mesh& m : meshes)
    for (size_t t = 0; t < m.faces(); ++t) {
      float rec[12] = {0, 0, 0};
      for (int c = 0; c < 3; ++c)
        for (int d = 0; d < 3; ++d) rec[3 + 3 * c + d] = float(m.V[3 * m.F[3 * t + c] + d]);
      const uint16_t attr = 0;
      std::fwrite(rec, 4, 12, f);
      std::fwrite(&attr, 2, 1, f);
    }
  std::fclose(f);
}

}  // namespace

int main(int argc, char** argv) {
  std::string printer = "prusa_sl1s_speed", extension;
  int plates_to_time = 1 << 30, members = 20, repeat = 1, stl_plates = 1;
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    if (i + 1 < argc && k == "--printer") printer = argv[++i];
    else if (i + 1 < argc && k == "--plates") plates_to_time = std::atoi(argv[++i]);
    else if (i + 1 < argc && k == "--members") members = std::atoi(argv[++i]);
    else if (i + 1 < argc && k == "--format") extension = argv[++i];
    else if (i + 1 < argc && k == "--repeat") repeat = std::max(1, std::atoi(argv[++i]));
    else if (i + 1 < argc && k == "--stl-plates") stl_plates = std::atoi(argv[++i]);
    else rest.push_back(argv[i]);
  }
  BenchArgs args = parse_bench_args(int(rest.size()), rest.data());
  args.thickness = 0.05;
  for (size_t i = 1; i + 1 < rest.size(); i += 2)
    if (std::string(rest[i]) == "--thickness") args.thickness = std::atof(rest[i + 1]);
  std::filesystem::create_directories(args.out);
  const ReuseBuffers keep;
  const PrinterPreset& preset = printer_preset(printer);
  if (extension.empty()) extension = preset.extension;
  // Anti-aliased at gamma 1, as PrusaSlicer draws the same plate (its gamma_correction default).
  PrinterProfile profile = preset.profile;
  profile.antialiasing = true;
  profile.gamma = 1;
  const Platform platform = printer_platform(profile);

  const Mesh base = test::make_family_base(args.family);
  std::vector<Mesh> family;
  std::vector<std::string> names;
  for (int i = 1; i <= members; ++i) {
    family.push_back(test::make_family_member(base, args.family, i));
    names.push_back(format("member_%03d", i));
  }
  std::vector<const Mesh*> ptrs;
  for (const Mesh& m : family) ptrs.push_back(&m);
  std::printf("%s, %zu faces, %d members, %s (%.1f x %.1f mm), layers %g mm, threads %d\n",
              args.family.shape.c_str(), base.faces(), members, preset.name.c_str(), platform.x1 - platform.x0,
              platform.y1 - platform.y0, args.thickness, omp_get_max_threads());

  auto t = std::chrono::steady_clock::now();
  const Arrangement a = arrange_plates(ptrs, names, platform, {});
  std::printf("arranged on %zu plates in %.2f s:", a.members.size(), since(t));
  for (size_t k = 0; k < a.members.size(); ++k) std::printf(" %zu (%.0f %%)", a.members[k].size(), 100 * a.area_used[k]);
  std::printf("\n");
  write_placements_file(args.out + "/plates.json", placements_of(a, names, 2, platform));

  SliceOptions so;
  so.thickness = args.thickness;
  t = std::chrono::steady_clock::now();
  const Slices encoding = slice_layers(base, so);
  const Buffer<uint32_t> ends = encoded_edge_ends(encoding, base);
  const VertexOrder order = vertex_order(ends);  // as Make Plate Job: once for all its plates
  std::printf("source sliced with encoding once: %zu layers, %zu points, %.2f s\n", encoding.layers(), encoding.points(),
              since(t));

  std::vector<double> reuse_times, direct_times;
  std::printf("%-6s %8s %8s %12s %10s %10s %12s\n", "plate", "members", "layers", "points", "reuse s", "direct s", "direct/reuse");
  for (size_t k = 0; k < a.members.size() && int(k) < plates_to_time; ++k) {
    std::vector<Mesh> placed;
    for (size_t m : a.members[k]) placed.push_back(place_mesh(family[m], a.placement[m]));
    if (int(k) < stl_plates) write_stl(args.out + format("/plate_%zu.stl", k + 1), placed);
    const std::string out = plate_file_name(args.out + "/plate" + extension, k + 1);
    PlateJobOptions reuse;
    reuse.encoding = &encoding;
    reuse.edge_ends = &ends;
    reuse.vertex_order = &order;
    reuse.range_budget_bytes = available_memory() / 4;
    PlateJobStats r;
    std::vector<double> runs;
    for (int run = 0; run < repeat; ++run) {
      t = std::chrono::steady_clock::now();
      r = export_plate(placed, reuse, profile, out);
      runs.push_back(since(t));
    }
    const double reuse_s = median_of(runs);
    PlateJobOptions direct;
    direct.slicing = so;
    direct.slicing.encoding = false;
    direct.slicing.z_start = encoding.z_start;
    direct.range_budget_bytes = available_memory() / 4;
    t = std::chrono::steady_clock::now();
    const PlateJobStats d = export_plate(placed, direct, profile, out + ".direct" + extension);
    const double direct_s = since(t);
    reuse_times.push_back(reuse_s);
    direct_times.push_back(direct_s);
    std::vector<std::string> plate_names;
    for (size_t m : a.members[k]) plate_names.push_back(names[m]);
    t = std::chrono::steady_clock::now();
    write_plate_layout(plate_layout_file_name(out), placed, plate_names, platform);
    const double layout_s = since(t);
    std::printf("%-6zu %8zu %8zu %12zu %10.3f %10.2f %12.2f   (%stransfer %.2f s, slicing %.2f s; reuse: %zu member "
                "layers transferred, %zu sliced; %zu ranges; layout picture %.2f s)\n",
                k + 1, placed.size(), r.layers, r.points, reuse_s, direct_s, direct_s / reuse_s,
                repeat > 1 ? format("median of %d, first %.3f s; ", repeat, runs[0]).c_str() : "", r.slicing_seconds,
                d.slicing_seconds, r.transferred_layers, r.resliced_layers, r.ranges, layout_s);
    if (d.points != r.points) std::printf("  points differ: reuse %zu, direct %zu\n", r.points, d.points);
  }
  if (!reuse_times.empty())
    std::printf("median over %zu plates: reuse %.2f s, direct %.2f s\n", reuse_times.size(), median_of(reuse_times),
                median_of(direct_times));
  // PrusaSlicer's options for the same display (bench_plates.sh).
  FILE* f = std::fopen((args.out + "/prusa_display_args").c_str(), "w");
  std::fprintf(f, "--display-pixels-x %d --display-pixels-y %d --display-width %.6f --display-height %.6f "
                  "--display-orientation %s --%sdisplay-mirror-x --%sdisplay-mirror-y --gamma-correction 1\n",
               profile.width_px, profile.height_px, profile.width_px * profile.pixel_size_x_um / 1000,
               profile.height_px * profile.pixel_size_y_um / 1000, profile.portrait ? "portrait" : "landscape",
               profile.mirror_x ? "" : "no-", profile.mirror_y ? "" : "no-");
  std::fclose(f);
  return 0;
}
