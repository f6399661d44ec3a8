// The hollowing's filters through a fake host (#36): Hollow Mesh shows the cavity the jobs take
// out, Add Drain Holes the holes they drill; errors in words, nothing added on failure.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "error_of.h"
#include "fake_host.h"
#include "shapes.h"
#include "slicereuse/hollowing/hollow_layers.h"
#include "slicereuse/slicing/slice_layers.h"
#include "temp_folder.h"

namespace slicereuse::plugin {
namespace {

using test::error_of;

class HollowingFilters : public test::TempFolderTest {};

// A box 10 x 8 x 6 mm, walls of 1 mm, no closing: the cavity layer is the box shrunk by the wall
// on every side (8 x 6 x 4 mm), its volume that of the cavity's regions, and the resin saved
// its share of the box's.
TEST_F(HollowingFilters, HollowMeshShowsTheBoxShrunkByTheWall) {
  FakeHost host;
  host.meshes.push_back(test::make_box(0, 0, 0, 10, 8, 6, 3));
  const FilterSpec& spec = spec_named("hollow_mesh");
  const Result r = spec.run(defaults(spec, {}, {{"hollow_wall_mm", 1}, {"hollow_closing_mm", 0}}), host);
  ASSERT_EQ(host.mesh_layers.count("mesh0 cavity"), 1u);
  const Mesh& cavity = host.mesh_layers.at("mesh0 cavity");
  HollowingOptions o;
  o.wall_mm = 1;
  o.closing_mm = 0;
  SliceOptions slicing;
  slicing.thickness = 0.1;
  const double regions_mm3 = cavity_volume_mm3(layers_cavity(slice_layers(host.meshes[0], slicing), o), 0.1);
  EXPECT_NEAR(test::signed_volume(cavity), regions_mm3, 1e-9);
  EXPECT_NEAR(regions_mm3, 8 * 6 * 4, 1e-9);
  EXPECT_NEAR(std::get<double>(r.at("cavity_mm3")), regions_mm3, 1e-12);
  EXPECT_NEAR(std::get<double>(r.at("part_mm3")), 10 * 8 * 6, 1e-9);
  EXPECT_NEAR(std::get<double>(r.at("saved_percent")), 100.0 * 192 / 480, 1e-9);
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (size_t i = 0; i < cavity.V.size(); ++i) lo[i % 3] = std::min(lo[i % 3], cavity.V[i]), hi[i % 3] = std::max(hi[i % 3], cavity.V[i]);
  EXPECT_NEAR(lo[0], 1, 1e-9);
  EXPECT_NEAR(hi[0], 9, 1e-9);
  EXPECT_NEAR(lo[1], 1, 1e-9);
  EXPECT_NEAR(hi[1], 7, 1e-9);
  EXPECT_NEAR(lo[2], 1, 1e-9);
  EXPECT_NEAR(hi[2], 5, 1e-9);
  EXPECT_NE(std::find_if(host.lines.begin(), host.lines.end(),
                         [](const std::string& l) { return l.find("40.0% of the part's 480 mm3 of resin saved") != std::string::npos; }),
            host.lines.end());
}

TEST_F(HollowingFilters, HollowMeshRefusesAWallThickerThanThePartInWords) {
  FakeHost host;
  host.meshes.push_back(test::make_box(0, 0, 0, 10, 8, 3));
  const FilterSpec& spec = spec_named("hollow_mesh");
  EXPECT_EQ(error_of([&] { spec.run(defaults(spec, {}, {{"hollow_wall_mm", 1.6}}), host); }),
            "mesh0 has no cavity with walls of 1.6 mm and a closing distance of 2 mm: no ball of 3.6 mm radius fits "
            "inside it, so it stays solid; nothing was added");
  EXPECT_EQ(error_of([&] { spec.run(defaults(spec, {}, {{"hollow_wall_mm", 0}}), host); }),
            "hollow_wall_mm is 0, which keeps the part solid: give the walls' thickness, e.g. PrusaSlicer's 3 mm");
  EXPECT_TRUE(host.added_layers.empty());
}

bool logged(const FakeHost& host, const std::string& text) {
  return std::find_if(host.lines.begin(), host.lines.end(),
                      [&](const std::string& l) { return l.find(text) != std::string::npos; }) != host.lines.end();
}

// A box 20 x 16 x 10 mm, walls of 2 mm: Add Drain Holes shows the hole the jobs drill under its
// cavity as a point where it opens on the base, its normal down the hole; with drain_holes 3,
// three points, the same a print job drills.
TEST_F(HollowingFilters, AddDrainHolesShowsWhereTheJobsDrill) {
  FakeHost host;
  host.meshes.push_back(test::make_box(0, 0, 0, 20, 16, 10, 4));
  const FilterSpec& spec = spec_named("add_drain_holes");
  const std::map<std::string, double> hollow{{"hollow_wall_mm", 2}, {"hollow_closing_mm", 0}};
  const Result one = spec.run(defaults(spec, {{"drain_holes_file", path("holes.srp")}}, hollow), host);
  EXPECT_EQ(count(one, "drain_holes"), 1);
  EXPECT_NEAR(std::get<double>(one.at("cavity_mm3")), 16 * 12 * 6, 1e-6);
  ASSERT_EQ(host.point_layers.count("mesh0 drain holes"), 1u);
  EXPECT_EQ(host.point_layers.at("mesh0 drain holes"), (std::vector<double>{10, 8, 0}));
  EXPECT_TRUE(std::filesystem::exists(path("holes.srp")));
  std::map<std::string, double> three = hollow;
  three["drain_holes"] = 3;
  const Result spread = spec.run(defaults(spec, {}, three), host);
  EXPECT_EQ(count(spread, "drain_holes"), 3);
  const FilterSpec& job = spec_named("make_print_job");
  const Result printed = job.run(defaults(job, {{"output_path", path("three.goo")}}, three), host);
  EXPECT_EQ(count(printed, "drain_holes"), 3);
  EXPECT_EQ(count(printed, "resin_traps"), 0);
  EXPECT_EQ(error_of([&] { spec.run(defaults(spec, {}, {{"drain_hole_mm", 0}}), host); }),
            "drain_hole_mm is 0, which drills no holes: give their diameter, e.g. 4 mm");
}

// The user's holes: Add Drain Holes' layer, edited (its point moved off the middle), given back
// as drain_points_layer: the job drills there and nothing is trapped; a point on the side wall
// drains it sideways. A point 2 mm off the surface, or one whose hole ends in the wall, is refused
// in words naming it, and nothing is written.
TEST_F(HollowingFilters, TheJobsDrillTheUsersHolesWhereThePointsAre) {
  FakeHost host;
  host.meshes.push_back(test::make_box(0, 0, 0, 20, 16, 10, 4));
  const FilterSpec& job = spec_named("make_print_job");
  const auto run = [&](const std::string& out, const std::vector<double>& points) {
    host.meshes.resize(1);
    host.meshes.push_back(Mesh{points, {}});
    return job.run(defaults(job, {{"output_path", path(out)}},
                            {{"hollow_wall_mm", 2}, {"hollow_closing_mm", 0}, {"drain_points_layer", 1}}),
                   host);
  };
  const Result bottom = run("bottom.goo", {6, 5, 0.3});
  EXPECT_EQ(count(bottom, "drain_holes"), 1);
  EXPECT_EQ(count(bottom, "resin_traps"), 0);
  EXPECT_EQ(count(bottom, "suction_cups"), 0);
  EXPECT_TRUE(logged(host, "drain hole at (6.00, 5.00, 0.00) mm along (0.00, 0.00, -1.00), through layers 0-29"))
      << ::testing::PrintToString(host.lines);
  const Result side = run("side.goo", {0, 8, 5});
  EXPECT_EQ(count(side, "drain_holes"), 1);
  EXPECT_EQ(count(side, "resin_traps"), 0);
  EXPECT_TRUE(logged(host, "drain hole at (0.00, 8.00, 5.00) mm along (-1.00, 0.00, 0.00), through layers 30-69"));

  EXPECT_EQ(error_of([&] { run("far.goo", {6, 5, -2}); }),
            "drain hole point 1 at (6, 5, -2) mm is 2 mm from the mesh's surface, farther than the 1 mm a point may be "
            "moved onto it: the points are not this mesh's, or were moved off it");
  EXPECT_FALSE(std::filesystem::exists(path("far.goo")));
  EXPECT_EQ(error_of([&] { run("wall.goo", {0.5, 0.5, 10}); }).substr(0, 86),
            "the current mesh: drain hole 1 at (0.50, 0.50, 10.00) mm reaches no cavity: drilled 3 ");
  EXPECT_FALSE(std::filesystem::exists(path("wall.goo")));
}

// A family: the source's holes (Add Drain Holes' file: faces and area coordinates) on a member
// (its vertices moved, the same faces) are at the same place on the member's own surface, by
// reuse as by direct slicing (identical masks); a member of other faces is refused in words.
TEST_F(HollowingFilters, EveryMemberGetsTheSourcesHolesOnItsOwnSurface) {
  FakeHost host;
  const Mesh source = test::make_box(0, 0, 0, 20, 16, 10, 4);
  Mesh member = source;
  for (size_t i = 0; i < member.V.size(); i += 3) member.V[i] *= 1.1, member.V[i + 1] *= 1.25;
  host.meshes = {source, member};
  const std::map<std::string, double> hollow{{"hollow_wall_mm", 2}, {"hollow_closing_mm", 0}};
  const FilterSpec& holes = spec_named("add_drain_holes");
  holes.run(defaults(holes, {{"drain_holes_file", path("holes.srp")}}, hollow), host);
  const FilterSpec& slice = spec_named("slice_mesh_with_encoding");
  slice.run(defaults(slice, {{"encoding_file", path("s.srb")}}), host);
  host.current = 1;
  const FilterSpec& job = spec_named("make_print_job");
  const Result reused = job.run(
      defaults(job, {{"output_path", path("reused.goo")}, {"encoding_file", path("s.srb")}, {"drain_holes_file", path("holes.srp")}},
               hollow),
      host);
  EXPECT_EQ(count(reused, "reused"), 1);
  EXPECT_EQ(count(reused, "resin_traps"), 0);
  EXPECT_TRUE(logged(host, "drain hole at (11.00, 10.00, 0.00) mm along (0.00, 0.00, -1.00)"));
  const Result direct =
      job.run(defaults(job, {{"output_path", path("direct.goo")}, {"drain_holes_file", path("holes.srp")}}, hollow), host);
  EXPECT_EQ(count(direct, "reused"), 0);
  const FilterSpec& compare = spec_named("compare_mask_stacks");
  const Result same = compare.run(defaults(compare, {{"stack_a", path("reused.goo")}, {"stack_b", path("direct.goo")}}), host);
  EXPECT_EQ(std::get<double>(same.at("min_similarity")), 1.0);
  EXPECT_EQ(count(same, "differing_pixels"), 0);
  host.meshes[1] = test::make_box(0, 0, 0, 20, 16, 10, 5);
  EXPECT_NE(error_of([&] {
              job.run(defaults(job, {{"output_path", path("other.goo")}, {"drain_holes_file", path("holes.srp")}}, hollow),
                      host);
            }).find("drain_holes_file " + path("holes.srp") + ": the support points are for a mesh of"),
            std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(path("other.goo")));
}

// A hollowed box raised on generated supports: its drain hole's mouth keeps clear of heads (the
// points within the hole's radius plus the head's dropped, as PrusaSlicer places none on a hole),
// so the job has fewer points than undrained, says so, and the cavity drains.
TEST_F(HollowingFilters, SupportHeadsKeepClearOfDrainHoles) {
  FakeHost host;
  host.meshes.push_back(test::make_box(0, 0, 0, 20, 16, 10, 8));
  const FilterSpec& job = spec_named("make_print_job");
  std::map<std::string, double> numbers{{"hollow_wall_mm", 2}, {"hollow_closing_mm", 0}, {"supports", 1}, {"drain_hole_mm", 0}};
  const Result sealed = job.run(defaults(job, {{"output_path", path("sealed.goo")}}, numbers), host);
  EXPECT_FALSE(logged(host, "support points dropped"));
  numbers["drain_hole_mm"] = 4;
  const Result drained = job.run(defaults(job, {{"output_path", path("drained.goo")}}, numbers), host);
  EXPECT_LT(count(drained, "support_points"), count(sealed, "support_points"));
  EXPECT_TRUE(logged(host, "support points dropped: their heads would reach into a drain hole"));
  EXPECT_EQ(count(drained, "drain_holes"), 1);
  // The cavity drains: what stays trapped are the supports' own specks between heads (0.002 mm3
  // each, as on any supported part at this display's 75 um), not the 1152 mm3 cavity.
  EXPECT_GT(std::get<double>(sealed.at("trapped_mm3")), 1000);
  EXPECT_LT(std::get<double>(drained.at("trapped_mm3")), 0.1);
}

// On a plate, each member (placed: moved and turned) gets the first member's user holes at the
// same place on its own surface, and every cavity drains.
TEST_F(HollowingFilters, APlatesMembersEachGetTheUsersHoles) {
  FakeHost host;
  const Mesh source = test::make_box(0, 0, 0, 20, 16, 10, 4);
  Mesh member = source;
  for (size_t i = 0; i < member.V.size(); i += 3) member.V[i] *= 1.2;
  host.meshes = {source, member, Mesh{{6, 5, 0, 14, 11, 0}, {}}};
  const FilterSpec& plate = spec_named("make_plate_job");
  const Result r = plate.run(defaults(plate, {{"output_path", path("plate.goo")}},
                                      {{"hollow_wall_mm", 2}, {"hollow_closing_mm", 0}, {"drain_points_layer", 2}}),
                             host);
  EXPECT_EQ(count(r, "drain_holes_mesh0"), 2);
  EXPECT_EQ(count(r, "drain_holes_mesh1"), 2);
  EXPECT_EQ(count(r, "resin_traps"), 0);
  EXPECT_EQ(count(r, "suction_cups"), 0);
}

}  // namespace
}  // namespace slicereuse::plugin
