// The support filters through the fake host: points generated on a source, written and shown as
// a point layer, transferred to a member with the same faces, the member's supports built from
// its file and from its point layer; a print job with transferred supports; a points file for
// another mesh refused in the core's words, with nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "error_of.h"
#include "fake_host.h"
#include "shapes.h"
#include "shuffle_mesh.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/supports/support_points_file.h"
#include "temp_folder.h"

namespace slicereuse::plugin {
namespace {

using test::error_of;
using test::make_sphere;

class SupportFilters : public test::TempFolderTest {
 protected:
  // Mesh 0: a sphere of radius 5 mm (raised, its first layer is an island; its lower half overhangs), mesh 1:
  // the same faces stretched in x, mesh 2: the sphere's faces renumbered.
  void SetUp() override {
    test::TempFolderTest::SetUp();
    host.meshes.push_back(make_sphere(5, 24, 32));
    Mesh moved = host.meshes[0];
    for (size_t i = 0; i < moved.V.size(); i += 3) moved.V[i] = 1.1 * moved.V[i] + 0.05 * moved.V[i + 2];
    host.meshes.push_back(moved);
    host.meshes.push_back(test::shuffle_mesh(host.meshes[0], 7).mesh);
  }
  FakeHost host;
};

TEST_F(SupportFilters, PointsAreGeneratedTransferredAndBuiltIntoSupports) {
  const FilterSpec& generate = spec_named("generate_support_points");
  // Dense, and up to 80 degrees: the sphere's points on its widening first layers hold its lower
  // half's slopes at 100 %; at 300 % they fall short of its sections near the equator.
  const Result g = generate.run(
      defaults(generate, {{"support_points_file", path("source.srp")}}, {{"density", 300}, {"critical_angle", 80}}), host);
  EXPECT_EQ(keys_of(g), (std::set<std::string>{"points", "islands", "overhangs", "seconds"}));
  const SupportPoints source = read_support_points(path("source.srp"));
  EXPECT_EQ(count(g, "points"), int64_t(source.size()));
  EXPECT_GE(count(g, "islands"), 1);
  EXPECT_GE(count(g, "overhangs"), 1);
  EXPECT_EQ(count(g, "islands") + count(g, "overhangs"), count(g, "points"));
  EXPECT_EQ(host.point_layers.at("mesh0 support points"), source.xyz);

  host.current = 1;
  const FilterSpec& transfer = spec_named("transfer_support_points");
  const Result t = transfer.run(
      defaults(transfer, {{"support_points_file", path("source.srp")}, {"member_points_file", path("member.srp")}}),
      host);
  EXPECT_EQ(keys_of(t), (std::set<std::string>{"transferred", "kept", "moved", "added", "dropped", "points", "seconds"}));
  const SupportPoints member = read_support_points(path("member.srp"));
  EXPECT_EQ(count(t, "transferred"), int64_t(source.size()));
  EXPECT_EQ(count(t, "kept") + count(t, "moved") + count(t, "dropped"), count(t, "transferred"));
  EXPECT_EQ(count(t, "kept") + count(t, "moved") + count(t, "added"), int64_t(member.size()));
  EXPECT_GT(count(t, "kept"), 0);
  EXPECT_EQ(host.point_layers.at("mesh1 support points"), member.xyz);

  // From the file, and from the point layer (mesh 3, as the host added it): the same supports.
  const FilterSpec& build = spec_named("build_supports");
  const Result from_file = build.run(defaults(build, {{"support_points_file", path("member.srp")}}), host);
  EXPECT_EQ(keys_of(from_file),
            (std::set<std::string>{"points", "pillars", "bridged", "on_part", "layers_below", "ground_z", "seconds"}));
  EXPECT_EQ(count(from_file, "points"), int64_t(member.size()));
  EXPECT_EQ(count(from_file, "layers_below"), 60);  // 5 mm and the pad's 1 mm in layers of 0.1 mm
  EXPECT_NEAR(std::get<double>(from_file.at("ground_z")), -5 - 6.0, 1e-9);
  const Mesh supports = host.mesh_layers.at("mesh1 supports");
  EXPECT_GT(supports.faces(), 0u);
  Mesh layer;
  layer.V = member.xyz;
  host.meshes.push_back(layer);
  host.mesh_layers.clear();
  const Result from_layer = build.run(defaults(build, {}, {{"points_layer", 3}}), host);
  EXPECT_EQ(count(from_layer, "points"), int64_t(member.size()));
  EXPECT_EQ(count(from_layer, "pillars"), count(from_file, "pillars"));
  // The layer's positions located back on the surface: the same points, to rounding.
  const Mesh again = host.mesh_layers.at("mesh1 supports");
  ASSERT_EQ(again.V.size(), supports.V.size());
  EXPECT_EQ(again.F, supports.F);
  for (size_t i = 0; i < again.V.size(); ++i) EXPECT_NEAR(again.V[i], supports.V[i], 1e-9) << i;
}

// The job (supports 2: transfer) transfers the source's points to the member, builds its supports and stands it on them:
// 60 layers of supports and pad below the member's own.
TEST_F(SupportFilters, MakePrintJobTakesTheSourcesPointsAndPrintsTheMemberOnItsSupports) {
  const FilterSpec& generate = spec_named("generate_support_points");
  generate.run(defaults(generate, {{"support_points_file", path("source.srp")}}), host);
  host.current = 1;
  const FilterSpec& job = spec_named("make_print_job");
  const Result r = job.run(defaults(job, {{"support_points_file", path("source.srp")}, {"output_path", path("m.sl1")}},
                                    {{"supports", 2}}),
                           host);
  SliceOptions options;
  options.thickness = 0.1;
  EXPECT_EQ(count(r, "layers"), int64_t(slice_layers(host.meshes[1], options).layers()) + 60);
  EXPECT_GT(count(r, "support_points"), 0);
  EXPECT_EQ(count(r, "kept") + count(r, "moved") + count(r, "added"), count(r, "support_points"));
  EXPECT_TRUE(std::filesystem::exists(path("m.sl1")));
}

// A points file made for another mesh (the renumbered copy's faces differ) is refused in the
// validation's words by every filter that reads one, and nothing is written.
TEST_F(SupportFilters, APointsFileForAnotherMeshIsRefusedInWordsAndNothingIsWritten) {
  const FilterSpec& generate = spec_named("generate_support_points");
  generate.run(defaults(generate, {{"support_points_file", path("source.srp")}}), host);
  host.current = 2;
  const FilterSpec& build = spec_named("build_supports");
  EXPECT_NE(error_of([&] { build.run(defaults(build, {{"support_points_file", path("source.srp")}}), host); })
                .find("the support points are for a mesh of"),
            std::string::npos);
  const FilterSpec& transfer = spec_named("transfer_support_points");
  EXPECT_EQ(error_of([&] {
              transfer.run(defaults(transfer, {{"support_points_file", path("source.srp")},
                                               {"member_points_file", path("member.srp")}}),
                           host);
            }).rfind("the support points are for a mesh of ", 0),
            0u);
  const FilterSpec& job = spec_named("make_print_job");
  EXPECT_EQ(error_of([&] {
              job.run(defaults(job, {{"support_points_file", path("source.srp")}, {"output_path", path("m.sl1")}},
                               {{"supports", 2}}),
                      host);
            }).rfind("the current mesh's supports: the support points are for a mesh of ", 0),
            0u);
  EXPECT_FALSE(std::filesystem::exists(path("member.srp")));
  EXPECT_FALSE(std::filesystem::exists(path("m.sl1")));
  EXPECT_TRUE(host.mesh_layers.empty());
}

// Build Supports from a point layer moves each point onto the surface only from within 1 mm
// (PrusaSlicer's cap for manual points): another mesh's layer (here the sphere's points on one
// of radius 7) or a point dragged off is refused in words naming the point and its distance; a
// mesh layer is not a point layer. Nothing is added.
TEST_F(SupportFilters, BuildRefusesAPointLayerOffTheMeshInWords) {
  const FilterSpec& generate = spec_named("generate_support_points");
  generate.run(defaults(generate, {{"support_points_file", path("source.srp")}}), host);
  const std::vector<double> on_mesh = host.point_layers.at("mesh0 support points");
  Mesh other;
  other.V = on_mesh;
  for (double& v : other.V) v *= 7.0 / 5;
  host.meshes.push_back(other);
  const FilterSpec& build = spec_named("build_supports");
  const std::string message = error_of([&] { build.run(defaults(build, {}, {{"points_layer", 3}}), host); });
  EXPECT_EQ(message.rfind("support point 1 at (", 0), 0u) << message;
  EXPECT_NE(message.find("mm from the mesh's surface, farther than the 1 mm a point may be moved onto it"),
            std::string::npos)
      << message;
  // One point of the current mesh's own layer moved 2 mm out.
  Mesh dragged;
  dragged.V = on_mesh;
  dragged.V[3 * 2 + 0] *= 1 + 2.0 / std::hypot(dragged.V[6], dragged.V[7], dragged.V[8]);
  dragged.V[3 * 2 + 1] *= 1 + 2.0 / std::hypot(on_mesh[6], on_mesh[7], on_mesh[8]);
  dragged.V[3 * 2 + 2] *= 1 + 2.0 / std::hypot(on_mesh[6], on_mesh[7], on_mesh[8]);
  host.meshes.push_back(dragged);
  EXPECT_EQ(error_of([&] { build.run(defaults(build, {}, {{"points_layer", 4}}), host); }).rfind("support point 3 at (", 0),
            0u);
  EXPECT_EQ(error_of([&] { build.run(defaults(build, {}, {{"points_layer", 1}}), host); }),
            "the support points layer (layer 1) is a mesh of " + std::to_string(host.meshes[1].faces()) +
                " faces, not a point layer");
  EXPECT_TRUE(host.mesh_layers.empty());
}

}  // namespace
}  // namespace slicereuse::plugin
