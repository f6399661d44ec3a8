// Supports kernel benchmark (a diagnosis; the end-to-end figures against PrusaSlicer are
// bench/bench_supports.py's): on a family's source, generating support points and building the
// support tree; on each member, slicing it, transferring the source's points (certify, add) and
// building its tree, and exporting the member with its supports (by reuse) into a Prusa SL1S
// SPEED .sl1s, anti-aliased, with its elephant-foot compensation and without. Prints median
// seconds and the points kept, moved, added, dropped.
// Usage: bench_supports [--shape ear] [--faces 200000] [--height 8.8] [--thickness 0.05]
//                       [--runs 3] [--members 4]
//        bench_supports --family DIR [--thickness 0.05] [--runs 3] [--members 4]
// --family: the members gen_family wrote into DIR (member_000.ply the source), e.g. tilted.
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "bench_args.h"
#include "family.h"
#include "slicereuse/formats/mesh_file.h"
#include "slicereuse/plates/plate_job.h"
#include "slicereuse/printer/printer_presets.h"
#include "slicereuse/supports/generate_support_points.h"
#include "slicereuse/supports/support_tree.h"
#include "slicereuse/supports/transfer_support_points.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "shapes.h"

using namespace slicereuse;

namespace {

template <class F>
double median_seconds(int runs, F&& job) {
  std::vector<double> s;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    job();
    s.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return median_of(s);
}

}  // namespace

int main(int argc, char** argv) {
  BenchArgs args;
  args.family.shape = "ear";
  args.family.faces = 200000;
  args.family.height = 8.8;
  args.thickness = 0.05;
  args.runs = 3;
  args.members = 4;
  std::string family_dir;
  {
    // Defaults above; the command line overrides them (--family aside, bench_args' options).
    std::vector<char*> rest{argv[0]};
    for (int i = 1; i < argc; ++i) {
      if (std::string(argv[i]) == "--family" && i + 1 < argc) family_dir = argv[++i];
      else rest.push_back(argv[i]);
    }
    const BenchArgs given = parse_bench_args(int(rest.size()), rest.data());
    for (size_t i = 1; i + 1 < rest.size(); i += 2) {
      const std::string k = rest[i];
      if (k == "--shape") args.family.shape = given.family.shape;
      if (k == "--faces") args.family.faces = given.family.faces;
      if (k == "--height") args.family.height = given.family.height;
      if (k == "--thickness") args.thickness = given.thickness;
      if (k == "--runs") args.runs = given.runs;
      if (k == "--members") args.members = given.members;
    }
  }
  auto member_of = [&](const Mesh& base, int i) {
    if (family_dir.empty()) return test::make_family_member(base, args.family, i);
    char name[32];
    std::snprintf(name, sizeof name, "/member_%03d.ply", i);
    return read_mesh_file(family_dir + name);
  };
  SlicedBase sliced;
  if (family_dir.empty()) {
    sliced = sliced_base(args);
  } else {
    SliceOptions o;
    o.thickness = args.thickness;
    sliced.base = member_of({}, 0);
    sliced.source = slice_layers(sliced.base, o);
    std::printf("family %s, %zu faces, %zu layers, threads %d, median of %d runs\n", family_dir.c_str(),
                sliced.base.faces(), sliced.source.layers(), omp_get_max_threads(), args.runs);
  }
  const SupportPointOptions points_options;
  const SupportTreeOptions tree_options;
  const double ground = support_ground_z(sliced.source.z_start, args.thickness, tree_options);
  SupportPoints source_points;
  const double generate = median_seconds(args.runs, [&] {
    source_points = generate_support_points(sliced.base, sliced.source, points_options);
  });
  SupportTree tree;
  const double build = median_seconds(args.runs, [&] {
    tree = build_support_tree(sliced.base, source_points, ground, tree_options);
  });
  std::printf("source: %zu points in %.3f s; tree (%zu pillars, %zu on the part, %zu faces) in %.3f s\n",
              source_points.size(), generate, tree.pillars, tree.on_part, tree.mesh.faces(), build);
  // The job's print file: the member on the source's planes, its supports below.
  PrinterProfile foot = printer_preset("prusa_sl1s_speed").profile;
  foot.antialiasing = true;
  PrinterProfile no_foot = foot;
  no_foot.elephant_foot_mm = 0;
  std::filesystem::create_directories(args.out);
  const std::string sl1s = args.out + "/supported_member.sl1s";
  PlateJobOptions job;
  job.encoding = &sliced.source;
  job.layers_below = support_layers_below(tree_options, args.thickness);
  std::printf("%-6s %7s %9s %9s %9s %9s %9s %9s %5s %5s %5s %5s\n", "member", "slice", "contours", "transfer", "tree",
              "generate", "export", "no foot", "kept", "moved", "added", "drop");
  SliceOptions slice_options;
  slice_options.thickness = args.thickness;
  for (int i = 1; i < args.members; ++i) {
    const Mesh member = member_of(sliced.base, i);
    Slices slicing;
    const double slice = median_seconds(args.runs, [&] { slicing = slice_layers(member, slice_options); });
    // What a job's supports analyse: the member's contours transferred from the source's encoding.
    const double contours = median_seconds(args.runs, [&] { slicing = transfer_contours(sliced.source, member, TransferOptions()); });
    SupportTransferStats stats;
    SupportPoints points;
    const double transfer = median_seconds(args.runs, [&] {
      points = transfer_support_points(source_points, member, slicing, points_options, &stats);
    });
    const double member_tree = median_seconds(args.runs, [&] {
      tree = build_support_tree(member, points, ground, tree_options);
    });
    const double own = median_seconds(args.runs, [&] { generate_support_points(member, slicing, points_options); });
    job.supports = {&tree.mesh};
    const std::vector<Mesh> placed{member};
    const double exported = median_seconds(args.runs, [&] { export_plate(placed, job, foot, sl1s); });
    const double unfooted = median_seconds(args.runs, [&] { export_plate(placed, job, no_foot, sl1s); });
    std::printf("%-6d %7.3f %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %5zu %5zu %5zu %5zu\n", i, slice, contours, transfer,
                member_tree, own, exported, unfooted, stats.kept, stats.moved, stats.added, stats.dropped);
  }
  return 0;
}
