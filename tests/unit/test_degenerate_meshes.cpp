// Broken meshes as scanners and design tools make them: find_mesh_defects names each defect,
// and slicing keeps working (open polylines flagged and counted) or refuses with a message that
// says what is wrong. Never a crash, a hang or an allocation sized by garbage.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "error_of.h"
#include "shapes.h"
#include "slicereuse/mesh/mesh_defects.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/util/error.h"

using namespace slicereuse;
using test::error_of;
using test::make_box;

namespace {

Slices slice(const Mesh& m, double thickness) {
  SliceOptions o;
  o.thickness = thickness;
  return slice_layers(m, o);
}

void add_face(Mesh& m, uint32_t a, uint32_t b, uint32_t c) { m.F.insert(m.F.end(), {a, b, c}); }

}  // namespace

TEST(MeshDefects, CleanBoxHasNone) {
  const MeshDefects d = find_mesh_defects(make_box(0, 0, 0, 1, 1, 1, 3));
  EXPECT_TRUE(d.clean());
  EXPECT_EQ(describe_mesh_defects(d), "");
}

TEST(MeshDefects, DuplicatedFacesAreCountedAndGiveFlaggedOpenContours) {
  Mesh m = make_box(0, 0, 0, 1, 1, 1, 4);
  const size_t nf = m.faces();
  for (uint32_t f = 0; f < 5; ++f) add_face(m, m.F[3 * f + 1], m.F[3 * f + 2], m.F[3 * f]);  // rotated copies
  const MeshDefects d = find_mesh_defects(m);
  EXPECT_EQ(d.duplicate_faces, 5u);
  EXPECT_EQ(d.first_duplicate_face, nf);
  EXPECT_GT(d.non_manifold_edges, 0u);
  EXPECT_NE(describe_mesh_defects(d).find("5 duplicated faces (first: face " + std::to_string(nf) + ")"),
            std::string::npos);
  const Slices s = slice(m, 0.1);
  EXPECT_EQ(s.layers(), 10u);
  EXPECT_GT(s.open_contours(), 0u);
}

TEST(MeshDefects, HoleGivesBoundaryEdgesAndOpenContoursOnlyWhereItIs) {
  Mesh m = make_box(0, 0, 0, 1, 1, 1, 4);
  const Slices whole = slice(m, 0.1);
  EXPECT_EQ(whole.open_contours(), 0u);
  // Remove the two triangles of one side quad; find one on a side (not top or bottom).
  size_t f = 0;
  for (; f < m.faces(); ++f) {
    const double z0 = m.V[3 * m.F[3 * f] + 2], z1 = m.V[3 * m.F[3 * f + 1] + 2], z2 = m.V[3 * m.F[3 * f + 2] + 2];
    if (std::min({z0, z1, z2}) == 0.25 && std::max({z0, z1, z2}) == 0.5) break;
  }
  ASSERT_LT(f, m.faces());
  m.F.erase(m.F.begin() + 3 * f, m.F.begin() + 3 * f + 3);
  const MeshDefects d = find_mesh_defects(m);
  EXPECT_EQ(d.boundary_edges, 3u);
  EXPECT_NE(describe_mesh_defects(d).find("3 boundary edges (holes)"), std::string::npos);
  const Slices s = slice(m, 0.1);
  ASSERT_EQ(s.layers(), 10u);
  for (size_t k = 0; k < s.layers(); ++k) {
    size_t open = 0;
    for (size_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c) open += s.contour_open[c];
    const bool through_hole = s.layer_z[k] > 0.25 && s.layer_z[k] < 0.5;
    EXPECT_EQ(open, through_hole ? 1u : 0u) << "layer " << k;
  }
}

TEST(MeshDefects, RepeatedVertexAndZeroAreaFacesAreCountedAndSlicingGoesOn) {
  Mesh m = make_box(0, 0, 0, 1, 1, 1, 2);
  const uint32_t a = m.F[0], b = m.F[1];
  add_face(m, a, a, b);  // names a vertex twice
  const uint32_t n = uint32_t(m.vertices());
  m.V.insert(m.V.end(), {2, 0, 0, 3, 0, 0.5, 4, 0, 1});  // three collinear points
  add_face(m, n, n + 1, n + 2);
  const MeshDefects d = find_mesh_defects(m);
  EXPECT_EQ(d.repeated_vertex_faces, 1u);
  EXPECT_EQ(d.zero_area_faces, 1u);
  const Slices s = slice(m, 0.1);
  EXPECT_EQ(s.layers(), 10u);
  validate_slices(s);
}

TEST(MeshDefects, NonManifoldFinIsCounted) {
  Mesh m = make_box(0, 0, 0, 1, 1, 1, 1);
  const uint32_t n = uint32_t(m.vertices());
  m.V.insert(m.V.end(), {0.5, 2, 0.5});
  add_face(m, m.F[0], m.F[1], n);  // a third face on an existing edge
  const MeshDefects d = find_mesh_defects(m);
  EXPECT_EQ(d.non_manifold_edges, 1u);
  const Slices s = slice(m, 0.1);
  EXPECT_GT(s.points(), 0u);
}

TEST(MeshDefects, NonFiniteVertexIsNamedBySlicing) {
  Mesh m = make_box(0, 0, 0, 1, 1, 1, 2);
  m.V[3 * 5 + 1] = std::numeric_limits<double>::quiet_NaN();
  const MeshDefects d = find_mesh_defects(m);
  EXPECT_EQ(d.non_finite_vertices, 1u);
  EXPECT_EQ(d.first_non_finite_vertex, 5u);
  EXPECT_NE(error_of([&] { slice(m, 0.1); }).find("vertex 5"), std::string::npos);
}

TEST(MeshDefects, EmptyMeshIsRefusedInWords) {
  EXPECT_NE(error_of([] { slice(Mesh{}, 0.1); }).find("no faces"), std::string::npos);
}

TEST(MeshDefects, SingleTriangleGivesOneOpenPolylinePerLayer) {
  const Mesh m{{0, 0, 0, 1, 0, 0, 0, 0, 1}, {0, 1, 2}};
  const MeshDefects d = find_mesh_defects(m);
  EXPECT_EQ(d.boundary_edges, 3u);
  const Slices s = slice(m, 0.25);
  ASSERT_EQ(s.layers(), 4u);
  EXPECT_EQ(s.contours(), 4u);
  EXPECT_EQ(s.open_contours(), 4u);
  EXPECT_EQ(s.points(), 8u);
}

TEST(MeshDefects, MeshInsideOneLayerGivesNoContours) {
  const Slices s = slice(make_box(0, 0, 0, 1, 1, 0.01), 0.1);  // the one plane is at z = 0.05
  EXPECT_EQ(s.layers(), 1u);
  EXPECT_EQ(s.contours(), 0u);
}

TEST(MeshDefects, ExtremeCoordinatesSliceOrAreRefusedWithTheLayerCount) {
  const Mesh m = make_box(-1e6, -1e6, 0, 1e6, 1e6, 1e6);
  const std::string refused = error_of([&] { slice(m, 0.05); });
  EXPECT_NE(refused.find("gives 2e+07 layers"), std::string::npos) << refused;
  EXPECT_NE(refused.find("limit of 10000000"), std::string::npos) << refused;
  const Slices s = slice(m, 1000);
  EXPECT_EQ(s.layers(), 1000u);
  EXPECT_EQ(s.contours(), 1000u);
  EXPECT_EQ(s.open_contours(), 0u);
}

TEST(MeshDefects, TinyThicknessMessagePrintsNumbersAsWritten) {
  const std::string m = error_of([] { slice(make_box(0, 0, 0, 1, 1, 10), 1e-9); });
  EXPECT_NE(m.find("1e-09 mm"), std::string::npos) << m;
  EXPECT_EQ(m.find("0.000000"), std::string::npos) << m;
}
