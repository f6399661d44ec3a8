// read_mesh_file (slicereuse/formats/mesh_file.h): hand-written files of each format with the
// exact V and F MeshLab's loader makes of them, the refusals with their messages, and round
// trips of a generated mesh through every format (tools/family/mesh_file_writers.h).
#include "slicereuse/formats/mesh_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "error_of.h"
#include "mesh_file_writers.h"
#include "shapes.h"
#include "temp_folder.h"

namespace slicereuse {
namespace {

using test::MeshFileKind;

class MeshFileTest : public test::TempFolderTest {
 protected:
  std::string write(const std::string& name, const std::string& bytes) {
    const std::string p = path(name);
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }
};

// Little- or big-endian bytes of v appended to out.
template <class T>
void put(std::string& out, T v, bool big = false) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof v);
  if (big) std::reverse(b, b + sizeof b);
  out.append(b, sizeof b);
}

std::string binary_stl(const std::vector<std::vector<float>>& facets, uint32_t count) {
  std::string out(80, 'h');
  put(out, count);
  for (const std::vector<float>& f : facets) {
    for (int k = 0; k < 3; ++k) put(out, 0.0f);
    for (float c : f) put(out, c);
    out.append(2, '\0');
  }
  return out;
}

TEST_F(MeshFileTest, AsciiStlWithTwoSolidsUnifiesCornersInFirstUseOrder) {
  const std::string stl =
      "solid a\n"
      "facet normal 0 0 -1\n outer loop\n  vertex 0 0 0\n  vertex 0 1 0\n  vertex 1 0 0\n endloop\nendfacet\n"
      "facet normal 0 -1 0\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 0 0.1\n endloop\nendfacet\n"
      "endsolid a\nsolid b\n"
      "  facet normal -1 0 0\r\n outer loop\r\n vertex 0 0 0\r\n vertex 0 0 1e-1\r\n vertex 0 +1 0\r\n endloop\r\n endfacet\r\n"
      "facet normal 1 1 1 outer loop vertex 1 0 0 vertex 0 1 0 vertex 0.0 0 0.1 endloop endfacet\n"
      "endsolid b\n";
  const Mesh m = read_mesh_file(write("two_solids.STL", stl));
  const double t = double(0.1f);  // ASCII STL coordinates are floats
  EXPECT_EQ(m.V, (std::vector<double>{0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, t}));
  EXPECT_EQ(m.F, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 1, 2, 1, 3}));
}

TEST_F(MeshFileTest, BinaryStlKeepsTheFirstOfMinusAndPlusZeroAndDropsDegenerateFacets) {
  const float nz = -0.0f;
  const std::string stl = binary_stl({{nz, 0, 0, 1, 0, 0, 0, 1, 0},
                                      {0, 0, 0, 0, 1, 0, 0, 0, 1},
                                      {1, 0, 0, 1, 0, 0, 0, 0, 1},
                                      {1, 0, 0, 0, 0, 1, 0, 1, 0}},
                                     4);
  ASSERT_EQ(stl.size(), 84u + 4 * 50);
  const Mesh m = read_mesh_file(write("zeros.stl", stl));
  EXPECT_EQ(m.V, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}));
  EXPECT_TRUE(std::signbit(m.V[0])) << "the -0.0 came first, so it is the one kept";
  EXPECT_EQ(m.F, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 1, 3, 2}));
}

TEST_F(MeshFileTest, AsciiPlyFansAQuadAndStepsOverOtherPropertiesAndElements) {
  const std::string ply =
      "ply\nformat ascii 1.0\ncomment made by hand\nobj_info test\n"
      "element vertex 5\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty float nx\n"
      "element group 1\nproperty list uchar int members\nproperty int flags\n"
      "element face 2\nproperty uchar flags\nproperty list uchar int vertex_indices\nproperty float quality\n"
      "end_header\n"
      "0 0 0 255 1\n1 0 0 0 1\n1 1 0 0 1\n0 1 0.1 0 1\n5 5 5 0 0\n"
      "2 0 1 7\n"
      "0 4 0 1 2 3 0.5\n0 3 0 2 4 0.5\n";
  const Mesh m = read_mesh_file(write("quad.Ply", ply));
  EXPECT_EQ(m.V, (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, double(0.1f), 5, 5, 5}));
  EXPECT_EQ(m.F, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 2, 4}));
}

TEST_F(MeshFileTest, AsciiPlyDoubleCoordinatesStayDoubles) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0.1 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_EQ(read_mesh_file(write("d.ply", ply)).V, (std::vector<double>{0.1, 0, 0, 1, 0, 0, 0, 1, 0}));
}

TEST_F(MeshFileTest, BinaryLittleEndianPlyStepsOverListsInVerticesAndOtherElements) {
  std::string ply =
      "ply\nformat binary_little_endian 1.0\n"
      "element vertex 4\nproperty uchar red\nproperty float x\nproperty float y\nproperty list uchar float w\n"
      "property float z\n"
      "element material 2\nproperty list ushort int ids\nproperty double shine\n"
      "element face 2\nproperty list ushort uint vertex_index\nproperty int tag\nend_header\n";
  const float xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.1f, 0, 1}};
  for (int v = 0; v < 4; ++v) {
    put<uint8_t>(ply, 7);
    put(ply, xyz[v][0]), put(ply, xyz[v][1]);
    put<uint8_t>(ply, uint8_t(v));  // v list items
    for (int k = 0; k < v; ++k) put(ply, 2.5f);
    put(ply, xyz[v][2]);
  }
  put<uint16_t>(ply, 3), put<int32_t>(ply, 1), put<int32_t>(ply, 2), put<int32_t>(ply, 3), put(ply, 0.5);
  put<uint16_t>(ply, 0), put(ply, 0.25);
  put<uint16_t>(ply, 3), put<uint32_t>(ply, 0), put<uint32_t>(ply, 2), put<uint32_t>(ply, 1), put<int32_t>(ply, 9);
  put<uint16_t>(ply, 4), put<uint32_t>(ply, 0), put<uint32_t>(ply, 1), put<uint32_t>(ply, 3), put<uint32_t>(ply, 2),
      put<int32_t>(ply, 9);
  const Mesh m = read_mesh_file(write("le.ply", ply));
  EXPECT_EQ(m.V, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, double(0.1f), 0, 1}));
  EXPECT_EQ(m.F, (std::vector<uint32_t>{0, 2, 1, 0, 1, 3, 0, 3, 2}));
}

TEST_F(MeshFileTest, BinaryBigEndianPlyWithDoublesAndShortIndices) {
  std::string ply =
      "ply\r\nformat binary_big_endian 1.0\r\nelement vertex 4\r\nproperty double x\r\nproperty double y\r\n"
      "property double z\r\nelement face 2\r\nproperty list int short vertex_indices\r\nend_header\r\n";
  const double xyz[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.1, -2, 1e300};
  for (double c : xyz) put(ply, c, true);
  put<int32_t>(ply, 3, true), put<int16_t>(ply, 0, true), put<int16_t>(ply, 1, true), put<int16_t>(ply, 2, true);
  put<int32_t>(ply, 3, true), put<int16_t>(ply, 3, true), put<int16_t>(ply, 2, true), put<int16_t>(ply, 1, true);
  const Mesh m = read_mesh_file(write("be.ply", ply));
  EXPECT_EQ(m.V, std::vector<double>(xyz, xyz + 12));
  EXPECT_EQ(m.F, (std::vector<uint32_t>{0, 1, 2, 3, 2, 1}));
}

TEST_F(MeshFileTest, ObjNegativeIndicesSlashTokensQuadsAndIgnoredLines) {
  const std::string obj =
      "# comment\nmtllib a.mtl\no thing\n"
      "v 0 0 0\nv +1.5 0 0 1.0\nvt 0 0\nvn 0 0 1\nv 1 1 0\r\nv 0 1 0\nv 9 9 9\n"
      "g group\nusemtl m\ns 1\n"
      "f 1 2 3\n"
      "f -5/1 -3/1 -2/1\n"
      "\tf 1//1 2//1 4//1 3//1\n"
      "f 1/1/1 2/1/1\n"
      "f 2 2 3\n";
  const Mesh m = read_mesh_file(write("thing.OBJ", obj));
  EXPECT_EQ(m.V, (std::vector<double>{0, 0, 0, 1.5, 0, 0, 1, 1, 0, 0, 1, 0, 9, 9, 9}));
  EXPECT_EQ(m.F, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 1, 3, 0, 3, 2}))
      << "the 2-vertex face is skipped and the one using vertex 2 twice dropped";
}

TEST_F(MeshFileTest, ObjCoordinatesAreDoubles) {
  const Mesh m = read_mesh_file(write("d.obj", "v 0.1 0.2 0.3\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  EXPECT_EQ(m.V, (std::vector<double>{0.1, 0.2, 0.3, 1, 0, 0, 0, 1, 0}));
}

TEST_F(MeshFileTest, RefusesTruncatedBinaryStl) {
  std::string stl = binary_stl(std::vector<std::vector<float>>(97, {1, 0, 0, 0, 1, 0, 0, 0, 1}), 100);
  ASSERT_LE(84 + 5000 - stl.size(), stl.size() / 20) << "within vcg's 5%, so it is taken as binary";
  const std::string message = test::error_of([&] { read_mesh_file(write("short.stl", stl)); });
  EXPECT_NE(message.find("short.stl"), std::string::npos) << message;
  EXPECT_NE(message.find("needs 5084 bytes but the file has 4934"), std::string::npos) << message;
  stl.resize(1000);
  EXPECT_ERROR(read_mesh_file(write("shorter.stl", stl)), "more than 5% off the 5084 bytes");
}

TEST_F(MeshFileTest, BinaryStlWithinFivePercentOfItsCountReadsTheCountedFacets) {
  // 100 facets, of which the count says 98: a byte above 127 (in 1.0f) makes it binary, as in vcg.
  std::vector<std::vector<float>> facets;
  for (int f = 0; f < 100; ++f) facets.push_back({float(f), 0, 0, float(f), 1, 0, float(f), 0, 1});
  const Mesh m = read_mesh_file(write("long.stl", binary_stl(facets, 98)));
  EXPECT_EQ(m.faces(), 98u);
  EXPECT_EQ(m.vertices(), 3u * 98);
  EXPECT_EQ(m.V[3 * (3 * 97)], 97.0);
}

TEST_F(MeshFileTest, RefusesTruncatedBinaryPly) {
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  for (int k = 0; k < 9; ++k) put(ply, float(k));
  put<uint8_t>(ply, 3), put<int32_t>(ply, 0), put<int32_t>(ply, 1);
  EXPECT_ERROR(read_mesh_file(write("short.ply", ply)), "the file ends inside face 0 of 1 (truncated)");
}

TEST_F(MeshFileTest, RefusesCountsLargerThanTheFile) {
  const std::string binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0123456789";
  EXPECT_ERROR(read_mesh_file(write("lie.ply", binary)), "4000000000 items need at least 4000000000 x 12 bytes but 10");
  const std::string ascii =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 900000000000\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_ERROR(read_mesh_file(write("lie_ascii.ply", ascii)), "900000000000 items (1 values each) cannot fit");
}

TEST_F(MeshFileTest, RefusesFaceIndicesOutOfRange) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 7 2\n";
  EXPECT_ERROR(read_mesh_file(write("range.ply", ply)), "line 14: face 1 uses vertex 7 but the file has 3 vertices (numbered from 0)");
  EXPECT_ERROR(read_mesh_file(write("range.obj", "v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n")),
               "line 3: the face uses vertex 3 but 2 vertices are read so far");
  EXPECT_ERROR(read_mesh_file(write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n")), "uses vertex 0");
}

TEST_F(MeshFileTest, RefusesObjFacesOfFiveVertices) {
  EXPECT_ERROR(read_mesh_file(write("pentagon.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv -1 0 0\nf 1 2 3 4 5\n")),
               "line 6: a face of 5 or more vertices");
  EXPECT_ERROR(read_mesh_file(write("pentagon2.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv -1 0 0\nf 1 2 3 4 5\n")),
               "triangulate the mesh first");
}

TEST_F(MeshFileTest, RefusesNonFiniteCoordinatesNamingTheVertex) {
  EXPECT_ERROR(read_mesh_file(write("nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n")),
               "line 2: vertex 2 has a coordinate that is not a finite number");
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const float xyz[9] = {0, 0, 0, 1, 0, std::numeric_limits<float>::infinity(), 0, 1, 0};
  for (float c : xyz) put(ply, c);
  put<uint8_t>(ply, 3), put<int32_t>(ply, 0), put<int32_t>(ply, 1), put<int32_t>(ply, 2);
  EXPECT_ERROR(read_mesh_file(write("inf.ply", ply)), "vertex 1 has a coordinate that is not a finite number");
  EXPECT_ERROR(read_mesh_file(write("nan.stl", binary_stl({{0, 0, 0, 1, 0, 0, 0, NAN, 0}}, 1))),
               "facet 0 (byte 84), vertex 2: a coordinate is not a finite number");
}

TEST_F(MeshFileTest, RefusesFilesWithoutFaces) {
  EXPECT_ERROR(read_mesh_file(write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n")), "OBJ file");
  EXPECT_ERROR(read_mesh_file(write("points2.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n")), "the file has no faces");
  EXPECT_ERROR(read_mesh_file(write("flat.obj", "v 0 0 0\nv 1 0 0\nf 1 2 2\n")), "all 1 faces use a vertex twice");
  EXPECT_ERROR(read_mesh_file(write("empty.stl", "solid x\nendsolid x\n" + std::string(80, ' '))), "the file has no faces");
}

TEST_F(MeshFileTest, RefusesUnknownExtensionsAndMissingFiles) {
  EXPECT_FALSE(is_mesh_file_name("a.off"));
  EXPECT_FALSE(is_mesh_file_name("stl"));
  EXPECT_FALSE(is_mesh_file_name("dir.stl/mesh"));
  EXPECT_TRUE(is_mesh_file_name("dir/a.StL"));
  EXPECT_TRUE(is_mesh_file_name("a.PLY"));
  EXPECT_TRUE(is_mesh_file_name("a.obj"));
  EXPECT_ERROR(read_mesh_file(write("a.off", "OFF\n")), "the name must end in .stl, .ply or .obj");
  EXPECT_ERROR(read_mesh_file(path("missing.ply")), "cannot open the mesh file");
}

TEST_F(MeshFileTest, RefusesMalformedText) {
  EXPECT_ERROR(read_mesh_file(write("bad.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 zero 0\n" + std::string(80, ' '))),
               "line 4: expected a vertex coordinate, found 'zero'");
  EXPECT_ERROR(read_mesh_file(write("bad.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n")),
               "the vertex element has no property y");
  EXPECT_ERROR(read_mesh_file(write("notply.ply", "solid\n")), "not a PLY file");
  EXPECT_ERROR(read_mesh_file(write("q.obj", "v 0 0 0\nq 1 2 3 4\n")), "QOBJ");
}

// Every vertex index renumbered in the order faces first use it: how STL's unified vertices come.
Mesh in_first_use_order(const Mesh& m) {
  Mesh out;
  std::vector<int64_t> renumber(m.vertices(), -1);
  for (uint32_t v : m.F) {
    if (renumber[v] < 0) {
      renumber[v] = int64_t(out.vertices());
      out.V.insert(out.V.end(), m.V.begin() + 3 * v, m.V.begin() + 3 * v + 3);
    }
    out.F.push_back(uint32_t(renumber[v]));
  }
  return out;
}

TEST_F(MeshFileTest, RoundTripsAGeneratedMeshThroughEveryFormat) {
  Mesh sphere = test::make_sphere(12.5, 9, 14);
  for (double& c : sphere.V) c = double(float(c) + 3.0f);  // float values, none -0.0
  for (MeshFileKind kind : {MeshFileKind::StlBinary, MeshFileKind::StlAscii, MeshFileKind::PlyBinary,
                            MeshFileKind::PlyAscii, MeshFileKind::Obj}) {
    SCOPED_TRACE(test::mesh_file_kind_name(kind));
    const std::string p = path(std::string("sphere") + test::mesh_file_extension(kind));
    test::write_mesh_file(p, sphere, kind);
    const Mesh m = read_mesh_file(p);
    const bool stl = kind == MeshFileKind::StlBinary || kind == MeshFileKind::StlAscii;
    const Mesh expected = stl ? in_first_use_order(sphere) : sphere;
    EXPECT_EQ(m.V, expected.V);
    EXPECT_EQ(m.F, expected.F);
  }
  // The doubles of tools/family's write_ply read back as they are.
  Mesh exact = test::make_sphere(0.3, 5, 7);
  test::write_ply(path("double.ply"), exact);
  const Mesh m = read_mesh_file(path("double.ply"));
  EXPECT_EQ(m.V, exact.V);
  EXPECT_EQ(m.F, exact.F);
}

}  // namespace
}  // namespace slicereuse
