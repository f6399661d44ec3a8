// Supports kernel benchmark (a diagnosis; the end-to-end figures against PrusaSlicer are
// bench/bench_supports.py's): on a family's source, generating support points and building the
// support tree; on each member, slicing it, transferring the source's points (certify, add) and
// building its tree. Prints median seconds and the points kept, moved, added, dropped.
// Usage: bench_supports [--shape ear] [--faces 200000] [--height 8.8] [--thickness 0.05]
//                       [--runs 3] [--members 4]
#include <chrono>
#include <cstdio>

#include "bench_args.h"
#include "family.h"
#include "slicereuse/supports/generate_support_points.h"
#include "slicereuse/supports/support_tree.h"
#include "slicereuse/supports/transfer_support_points.h"

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
  {
    // Defaults above; the command line overrides them.
    const BenchArgs given = parse_bench_args(argc, argv);
    for (int i = 1; i + 1 < argc; i += 2) {
      const std::string k = argv[i];
      if (k == "--shape") args.family.shape = given.family.shape;
      if (k == "--faces") args.family.faces = given.family.faces;
      if (k == "--height") args.family.height = given.family.height;
      if (k == "--thickness") args.thickness = given.thickness;
      if (k == "--runs") args.runs = given.runs;
      if (k == "--members") args.members = given.members;
    }
  }
  const SlicedBase sliced = sliced_base(args);
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
  std::printf("%-6s %7s %9s %9s %9s %5s %5s %5s %5s\n", "member", "slice", "transfer", "tree", "generate", "kept",
              "moved", "added", "drop");
  SliceOptions slice_options;
  slice_options.thickness = args.thickness;
  for (int i = 1; i < args.members; ++i) {
    const Mesh member = test::make_family_member(sliced.base, args.family, i);
    Slices slicing;
    const double slice = median_seconds(args.runs, [&] { slicing = slice_layers(member, slice_options); });
    SupportTransferStats stats;
    SupportPoints points;
    const double transfer = median_seconds(args.runs, [&] {
      points = transfer_support_points(source_points, member, slicing, points_options, &stats);
    });
    const double member_tree = median_seconds(args.runs, [&] {
      tree = build_support_tree(member, points, ground, tree_options);
    });
    const double own = median_seconds(args.runs, [&] { generate_support_points(member, slicing, points_options); });
    std::printf("%-6d %7.3f %9.3f %9.3f %9.3f %5zu %5zu %5zu %5zu\n", i, slice, transfer, member_tree, own, stats.kept,
                stats.moved, stats.added, stats.dropped);
  }
  return 0;
}
