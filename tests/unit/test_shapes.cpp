// Test meshes and PLY I/O: every shape is a closed, consistently oriented 2-manifold with the
// expected Euler characteristic and volume, and PLY round trips are bit-exact.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "shapes.h"
#include "slicereuse/util/error.h"

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

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
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
  const Mesh r = read_ply(path);
  EXPECT_EQ(r.V, m.V);
  EXPECT_EQ(r.F, m.F);
  std::remove(path.c_str());
}

TEST(Ply, ReadsAsciiFloatWithExtraPropertiesAndElements) {
  const std::string path = temp_path("ascii.ply");
  write_text(path,
             "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nelement vertex 4\r\n"
             "property float x\r\nproperty float y\r\nproperty float z\r\nproperty uchar red\r\n"
             "element face 4\r\nproperty uchar flags\r\nproperty list uchar int vertex_index\r\n"
             "element edge 1\r\nproperty list uchar int verts\r\nend_header\r\n"
             "0 0 0 1\r\n1 0 0 2\r\n0 1 0 3\r\n0 0 1.5 4\r\n"
             "7 3 0 2 1\r\n7 3 0 1 3\r\n7 3 0 3 2\r\n7 3 1 2 3\r\n2 0 1\r\n");
  const Mesh m = read_ply(path);
  EXPECT_EQ(m.V, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1.5}));
  EXPECT_EQ(m.F, (std::vector<uint32_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
  expect_closed_manifold(m, 2, "tetrahedron");
  std::remove(path.c_str());
}

TEST(Ply, ReadsBinaryFloatWithIntCounts) {
  const std::string path = temp_path("float.ply");
  std::string text =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list int uint vertex_indices\nend_header\n";
  const float v[9] = {0, 0, 0, 0.1f, 0, 0, 0, 0.25f, 0};
  const int32_t f[4] = {3, 0, 1, 2};
  text.append(reinterpret_cast<const char*>(v), sizeof v);
  text.append(reinterpret_cast<const char*>(f), sizeof f);
  write_text(path, text);
  const Mesh m = read_ply(path);
  EXPECT_EQ(m.V[3], double(0.1f));
  EXPECT_EQ(m.V[7], 0.25);
  EXPECT_EQ(m.F, (std::vector<uint32_t>{0, 1, 2}));
  std::remove(path.c_str());
}

TEST(Ply, RejectsBadFilesWithClearErrors) {
  const std::string path = temp_path("bad.ply");
  auto expect_error = [&](const std::string& text, const std::string& needle) {
    write_text(path, text);
    try {
      read_ply(path);
      ADD_FAILURE() << "no error for " << needle;
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(path), std::string::npos) << what;
      EXPECT_NE(what.find(needle), std::string::npos) << what;
    }
  };
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
      "property double z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string verts = "0 0 0\n1 0 0\n0 1 0\n";
  expect_error(head + verts + "4 0 1 2 0\n", "only triangles");
  expect_error(head + verts + "3 0 1 3\n", "out of range");
  expect_error(head + verts + "3 0 1\n", "truncated");
  expect_error(head + "0 0 0\n1 x 0\n", "expected a number");
  expect_error("ply\nformat binary_big_endian 1.0\nend_header\n", "unsupported format");
  expect_error("solid x\n", "not a PLY file");
  expect_error("ply\nformat ascii 1.0\nelement vertex 0\n", "no end_header");
  std::remove(path.c_str());
  EXPECT_THROW(read_ply(path), Error);  // missing file
}
