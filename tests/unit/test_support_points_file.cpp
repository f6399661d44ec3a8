// The support-points file (support_points_file.h): a written file reads back to the same doubles,
// and every damage (header, counts, numbers, truncation, another mesh) is refused in words.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "error_of.h"
#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/supports/support_points_file.h"
#include "temp_folder.h"

using namespace slicereuse;
namespace fs = std::filesystem;

namespace {

// Two triangles (a unit square), and a point on each.
Mesh square() { return Mesh{{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, {0, 1, 2, 0, 2, 3}}; }

SupportPoints two_points(const Mesh& m) {
  SupportPoints p;
  p.fingerprint = mesh_fingerprint(m);
  p.face = {0, 1};
  p.bary = {0.1, 0.2, 0.7, 1.0 / 3, 1.0 / 3, 1 - 2.0 / 3};
  p.kind = {uint8_t(SupportKind::Island), uint8_t(SupportKind::Overhang)};
  p.layer = {0, 17};
  place_support_points(p, m);
  return p;
}

class SupportPointsFile : public test::TempFolderTest {
 protected:
  std::string error_reading(const std::string& text) const {
    std::ofstream(path("bad.srp")) << text;
    return test::error_of([&] { read_support_points(path("bad.srp")); });
  }
  std::string written() const {
    write_support_points(path("p.srp"), two_points(square()));
    std::ifstream in(path("p.srp"));
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
};

}  // namespace

TEST_F(SupportPointsFile, RoundTripsExactly) {
  const Mesh m = square();
  const SupportPoints a = two_points(m);
  write_support_points(path("p.srp"), a);
  const SupportPoints b = read_support_points(path("p.srp"));
  EXPECT_EQ(b.fingerprint, a.fingerprint);
  EXPECT_EQ(b.face, a.face);
  EXPECT_EQ(b.bary, a.bary);
  EXPECT_EQ(b.xyz, a.xyz);
  EXPECT_EQ(b.normal, a.normal);
  EXPECT_EQ(b.kind, a.kind);
  EXPECT_EQ(b.layer, a.layer);
  validate_support_points(b, &m);
  // The positions are the faces' points: face 1, (1/3, 1/3, 1/3) of (0,0,0), (1,1,0), (0,1,0).
  EXPECT_NEAR(b.xyz[3], 1.0 / 3, 1e-15);
  EXPECT_NEAR(b.xyz[4], 2.0 / 3, 1e-15);
  EXPECT_EQ(b.normal[5], 1.0);
}

TEST_F(SupportPointsFile, RefusesDamageInWords) {
  const std::string good = written();
  EXPECT_EQ(error_reading("ply\nformat ascii 1.0\n"),
            "'" + path("bad.srp") + "' is not a support-points file: its first line is not 'slicereuse support points 1'");
  EXPECT_NE(error_reading("slicereuse support points 1\nmesh 2\npoints 0\n").find("line 2: expected 'mesh <faces> <16-digit hexadecimal hash>'"),
            std::string::npos);
  // Truncated: the last point line cut off.
  const std::string cut = good.substr(0, good.rfind('\n', good.size() - 2) + 1);
  EXPECT_NE(error_reading(cut).find("is truncated: it says 2 points and ends after 1"), std::string::npos);
  // A count the file cannot hold is refused before anything is allocated for it.
  std::string huge = good;
  huge.replace(huge.find("points 2"), 8, "points 99999999999");
  EXPECT_NE(error_reading(huge).find("says it has 99999999999 points, but its"), std::string::npos);
  std::string bad_number = good;
  bad_number.replace(bad_number.rfind("\n1 ") + 1, 1, "x");
  EXPECT_NE(error_reading(bad_number).find("line 5: expected '<face> <3 area coordinates>"), std::string::npos);
  std::string bad_face = good;
  bad_face.replace(bad_face.rfind("\n1 ") + 1, 1, "7");
  EXPECT_NE(error_reading(bad_face).find("support point 2 lies on face 7, but the mesh it was made for has 2 faces"),
            std::string::npos);
  EXPECT_NE(error_reading(good + "1 0 0 1 0 0 0 0 0 1 1 0\n").find("line 6: text after the 2 points the header announces"),
            std::string::npos);
  EXPECT_NE(test::error_of([&] { read_support_points(path("missing.srp")); }).find("cannot open the support-points file"),
            std::string::npos);
}

TEST_F(SupportPointsFile, RefusesAnotherMesh) {
  const SupportPoints p = two_points(square());
  Mesh other = square();
  std::swap(other.F[0], other.F[1]);
  EXPECT_EQ(test::error_of([&] { validate_support_points(p, &other); }),
            "the support points are for a mesh of " + describe_fingerprint(p.fingerprint) + ", this one has " +
                describe_fingerprint(mesh_fingerprint(other)));
}

TEST_F(SupportPointsFile, NothingWrittenOnBadPoints) {
  SupportPoints p = two_points(square());
  p.bary[0] = 2;
  EXPECT_NE(test::error_of([&] { write_support_points(path("p.srp"), p); }).find("area coordinate 2, outside [0, 1]"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(path("p.srp")));
  EXPECT_TRUE(fs::is_empty(dir));
}
