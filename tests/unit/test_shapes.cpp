// Test meshes and PLY I/O: every shape is a closed, consistently oriented 2-manifold with the
// expected Euler characteristic and volume, and PLY round trips are bit-exact.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "shapes.h"
#include "slicereuse/formats/mesh_file.h"

using namespace slicereuse;
using namespace slicereuse::test;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Closed oriented 2-manifold with Euler characteristic `euler` and positive volume.
void expect_closed_manifold(const Mesh& m, long euler, const std::string& what) {
  SCOPED_TRACE(what);
  const EdgeCensus c = edge_census(m);
  EXPECT_EQ(c.bad_edges, 0u);
  EXPECT_EQ(2 * c.edges, 3 * m.faces());
  EXPECT_EQ(long(m.vertices()) - long(c.edges) + long(m.faces()), euler);
  EXPECT_GT(signed_volume(m), 0);
}

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("slicereuse_test_shapes_" + name)).string();
}

}  // namespace

TEST(Shapes, BoxIsClosedWithExactVolume) {
  for (int n : {1, 2, 7}) {
    const Mesh m = make_box(-1, 2, 0.5, 3, 4.5, 2, n);
    EXPECT_EQ(m.vertices(), size_t(6 * n * n + 2));
    EXPECT_EQ(m.faces(), size_t(12 * n * n));
    expect_closed_manifold(m, 2, "box n=" + std::to_string(n));
    EXPECT_NEAR(signed_volume(m), 4 * 2.5 * 1.5, 1e-12);
  }
}

TEST(Shapes, SphereIsClosedWithVolumeNearBall) {
  const Mesh m = make_sphere(2, 64, 128);
  EXPECT_EQ(m.vertices(), size_t(2 + 63 * 128));
  EXPECT_EQ(m.faces(), size_t(2 * 128 * 63));
  expect_closed_manifold(m, 2, "sphere");
  const double ball = 4.0 / 3 * kPi * 8;
  EXPECT_LT(signed_volume(m), ball);  // inscribed polyhedron
  EXPECT_NEAR(signed_volume(m), ball, 0.005 * ball);
}

TEST(Shapes, TorusIsClosedGenusOne) {
  const Mesh m = make_torus(3, 1, 96, 48);
  expect_closed_manifold(m, 0, "torus");
  const double exact = 2 * kPi * kPi * 3 * 1;
  EXPECT_NEAR(signed_volume(m), exact, 0.005 * exact);
}

TEST(Shapes, EdgeCensusFindsFlippedFaceAndHole) {
  Mesh m = make_box(0, 0, 0, 1, 1, 1, 2);
  std::swap(m.F[1], m.F[2]);
  EXPECT_EQ(edge_census(m).bad_edges, 3u);
  m.F.resize(m.F.size() - 3);
  EXPECT_GT(edge_census(m).bad_edges, 0u);
}

TEST(Ply, BinaryRoundTripIsBitExact) {
  const Mesh m = make_torus(3, 1.1, 37, 23);
  const std::string path = temp_path("roundtrip.ply");
  write_ply(path, m);
  const Mesh r = read_mesh_file(path);
  EXPECT_EQ(r.V, m.V);
  EXPECT_EQ(r.F, m.F);
  std::remove(path.c_str());
}
