// The hollowing's filters through a fake host (#36): Hollow Mesh shows the cavity the jobs take
// out, Add Drain Holes the holes they drill; errors in words, nothing added on failure.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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

}  // namespace
}  // namespace slicereuse::plugin
