// Slicer properties checked against brute force on meshes with known sections.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

#include "family.h"
#include "shapes.h"
#include "slicereuse/slicing/layer_planes.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/slicing/straddling_faces.h"
#include "slicereuse/util/error.h"

using namespace slicereuse;

namespace {

double signed_area(const Slices& s, size_t c) {
  double a = 0;
  const size_t b = s.contour_begin[c], e = s.contour_begin[c + 1];
  for (size_t i = b; i < e; ++i) {
    const size_t j = i + 1 < e ? i + 1 : b;
    a += s.xyz[3 * i] * s.xyz[3 * j + 1] - s.xyz[3 * j] * s.xyz[3 * i + 1];
  }
  return a / 2;
}

// Undirected edges with one end below z and the other at or above it.
size_t straddling_edges(const Mesh& m, double z) {
  std::set<std::pair<uint32_t, uint32_t>> edges;
  for (size_t f = 0; f < m.faces(); ++f)
    for (int j = 0; j < 3; ++j) {
      uint32_t a = m.F[3 * f + j], b = m.F[3 * f + (j + 1) % 3];
      if ((m.V[3 * a + 2] < z) != (m.V[3 * b + 2] < z)) edges.insert({std::min(a, b), std::max(a, b)});
    }
  return edges.size();
}

// Every point lies on the plane, on the edge its encoding names, which straddles the plane,
// and the encoding reproduces it to 1e-9 relative.
void expect_encoding_consistent(const Mesh& m, const Slices& s) {
  ASSERT_TRUE(s.has_points());
  ASSERT_TRUE(s.has_encoding());
  for (size_t k = 0; k < s.layers(); ++k)
    for (size_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c)
      for (size_t p = s.contour_begin[c]; p < s.contour_begin[c + 1]; ++p) {
        ASSERT_EQ(s.xyz[3 * p + 2], s.layer_z[k]);
        const uint32_t f = s.face[p], j = s.edge[p];
        ASSERT_LT(f, m.faces());
        ASSERT_LE(j, 2u);
        ASSERT_GT(s.t[p], 0.0);
        ASSERT_LE(s.t[p], 1.0);
        const double* a = &m.V[3 * m.F[3 * f + j]];
        const double* b = &m.V[3 * m.F[3 * f + (j + 1) % 3]];
        const double scale = 1 + std::abs(a[0]) + std::abs(a[1]) + std::abs(a[2]) + std::abs(b[0]) +
                             std::abs(b[1]) + std::abs(b[2]);
        for (int d = 0; d < 3; ++d)
          ASSERT_NEAR((1 - s.t[p]) * a[d] + s.t[p] * b[d], s.xyz[3 * p + d], 1e-9 * scale);
        if (!s.contour_open[c]) {
          ASSERT_LT(a[2], s.layer_z[k]);
          ASSERT_GE(b[2], s.layer_z[k]);
        }
      }
}

// The properties every closed manifold mesh must satisfy.
void expect_closed_sections(const Mesh& m, const Slices& s) {
  EXPECT_EQ(s.open_contours(), 0u);
  for (size_t k = 0; k < s.layers(); ++k)
    EXPECT_EQ(s.contour_begin[s.layer_begin[k + 1]] - s.contour_begin[s.layer_begin[k]],
              straddling_edges(m, s.layer_z[k]))
        << "layer " << k;
  expect_encoding_consistent(m, s);
}

Slices slice(const Mesh& m, double h, double z_start = NAN) {
  SliceOptions o;
  o.thickness = h;
  o.z_start = z_start;
  return slice_layers(m, o);
}

}  // namespace

TEST(LayerPlanes, CountIsCeilOfHeightOverThickness) {
  EXPECT_EQ(layer_planes(0, 0.001, 14.484).size(), 14484u);
  EXPECT_EQ(layer_planes(0, 0.1, 1.0).size(), 10u);
  EXPECT_EQ(layer_planes(0, 0.3, 1.0).size(), 4u);
  EXPECT_EQ(layer_planes(-0.125, 0.25, 1.0).size(), 5u);
  const std::vector<double> z = layer_planes(2, 0.5, 3);
  ASSERT_EQ(z.size(), 2u);
  EXPECT_EQ(z[0], 2.25);
  EXPECT_EQ(z[1], 2.75);
  EXPECT_EQ(first_plane_above(z, 2.25), 1u);
  EXPECT_EQ(first_plane_above(z, 2.2499), 0u);
  EXPECT_EQ(first_plane_above(z, 9), 2u);
  EXPECT_THROW(layer_planes(0, 0, 1), Error);
  EXPECT_THROW(layer_planes(0, -1, 1), Error);
  EXPECT_THROW(layer_planes(2, 0.1, 1), Error);
  EXPECT_THROW(layer_planes(0, 1e-12, 1), Error);
}

TEST(SliceLayers, BoxHasOneUnitSquarePerLayer) {
  const Mesh m = test::make_box(0, 0, 0, 1, 1, 1, 3);
  const Slices s = slice(m, 0.1);
  ASSERT_EQ(s.layers(), 10u);
  expect_closed_sections(m, s);
  for (size_t k = 0; k < s.layers(); ++k) {
    ASSERT_EQ(s.layer_begin[k + 1] - s.layer_begin[k], 1u);
    EXPECT_NEAR(signed_area(s, s.layer_begin[k]), 1.0, 1e-12);  // counter-clockwise, exact square
    // per side, n vertical edges and n quad diagonals cross the plane
    EXPECT_EQ(s.contour_begin[s.layer_begin[k] + 1] - s.contour_begin[s.layer_begin[k]], 24u);
  }
}

TEST(SliceLayers, SphereSectionsAreSingleCounterClockwiseLoops) {
  const double r = 2;
  const Mesh m = test::make_sphere(r, 40, 64);
  const Slices s = slice(m, 0.05);
  expect_closed_sections(m, s);
  for (size_t k = 0; k < s.layers(); ++k) {
    ASSERT_EQ(s.layer_begin[k + 1] - s.layer_begin[k], 1u) << "layer " << k;
    const double z = s.layer_z[k], rho2 = r * r - z * z;
    const double area = signed_area(s, s.layer_begin[k]);
    EXPECT_GT(area, 0);
    EXPECT_LT(area, M_PI * rho2 + 1e-12);  // an inscribed polygon
    EXPECT_GT(area, 0.9 * M_PI * rho2 - 0.05);
  }
}

TEST(SliceLayers, TorusHasOuterLoopAndClockwiseHole) {
  const double R = 3, r = 1;
  const Mesh m = test::make_torus(R, r, 64, 32);
  const Slices s = slice(m, 0.1);
  expect_closed_sections(m, s);
  size_t two_loop_layers = 0;
  for (size_t k = 0; k < s.layers(); ++k) {
    const size_t n = s.layer_begin[k + 1] - s.layer_begin[k];
    if (std::abs(s.layer_z[k]) > 0.9 * r) continue;  // near the top the polygonal torus may differ
    ASSERT_EQ(n, 2u) << "layer " << k;
    ++two_loop_layers;
    double a0 = signed_area(s, s.layer_begin[k]), a1 = signed_area(s, s.layer_begin[k] + 1);
    if (a0 < a1) std::swap(a0, a1);
    const double w = std::sqrt(r * r - s.layer_z[k] * s.layer_z[k]);
    EXPECT_GT(a0, 0);
    EXPECT_LT(a1, 0);
    EXPECT_LT(a0, M_PI * (R + w) * (R + w));
    EXPECT_GT(a0 + a1, 0.8 * M_PI * ((R + w) * (R + w) - (R - w) * (R - w)));
  }
  EXPECT_GT(two_loop_layers, 10u);
}

TEST(SliceLayers, VerticesAndFacesExactlyOnPlanes) {
  // Planes at z = 0, .25, .5, .75, 1: the bottom and top faces lie in planes and every side
  // vertex row sits exactly on one. A vertex at the plane counts as above it.
  const Mesh m = test::make_box(0, 0, 0, 1, 1, 1, 4);
  const Slices s = slice(m, 0.25, -0.125);
  ASSERT_EQ(s.layers(), 5u);
  ASSERT_EQ(s.layer_z[0], 0.0);
  ASSERT_EQ(s.layer_z[4], 1.0);
  expect_closed_sections(m, s);
  EXPECT_EQ(s.layer_begin[1], 0u);  // the bottom face is on the plane: nothing is below it
  for (size_t k = 1; k < 5; ++k) {
    ASSERT_EQ(s.layer_begin[k + 1] - s.layer_begin[k], 1u) << "layer " << k;
    EXPECT_NEAR(signed_area(s, s.layer_begin[k]), 1.0, 1e-15);
    for (size_t p = s.contour_begin[s.layer_begin[k]]; p < s.contour_begin[s.layer_begin[k] + 1]; ++p)
      EXPECT_EQ(s.t[p], 1.0);  // every crossing is the upper vertex itself
  }
}

TEST(SliceLayers, OpenMeshGivesFlaggedPolylines) {
  Mesh m = test::make_box(0, 0, 0, 1, 1, 1, 4);
  // Remove the side faces touching x = 1 between z = 0.25 and 0.5: a hole in one wall.
  Mesh holed;
  holed.V = m.V;
  for (size_t f = 0; f < m.faces(); ++f) {
    bool on_wall = true, in_band = true;
    for (int c = 0; c < 3; ++c) {
      const double* v = &m.V[3 * m.F[3 * f + c]];
      on_wall &= v[0] == 1.0;
      in_band &= v[2] >= 0.25 && v[2] <= 0.5;
    }
    if (!(on_wall && in_band))
      for (int c = 0; c < 3; ++c) holed.F.push_back(m.F[3 * f + c]);
  }
  ASSERT_EQ(holed.faces(), m.faces() - 8);
  const Slices s = slice(holed, 0.1);
  expect_encoding_consistent(holed, s);
  size_t open_layers = 0;
  for (size_t k = 0; k < s.layers(); ++k) {
    const double z = s.layer_z[k];
    ASSERT_EQ(s.layer_begin[k + 1] - s.layer_begin[k], 1u);
    const size_t c = s.layer_begin[k];
    EXPECT_EQ(s.contour_begin[c + 1] - s.contour_begin[c], straddling_edges(holed, z));
    const bool crosses_hole = z > 0.25 && z < 0.5;
    EXPECT_EQ(bool(s.contour_open[c]), crosses_hole) << "layer " << k;
    open_layers += crosses_hole;
    if (crosses_hole) {  // the polyline runs from the hole's lower-y side round to its other side
      const size_t b = s.contour_begin[c], e = s.contour_begin[c + 1] - 1;
      EXPECT_EQ(s.xyz[3 * b], 1.0);
      EXPECT_EQ(s.xyz[3 * e], 1.0);
    }
  }
  EXPECT_EQ(open_layers, 2u);
  EXPECT_EQ(s.open_contours(), 2u);
}

// Closed shells welded along an edge are sliced closed; a face flipped against its neighbours
// opens the loops it crosses.
TEST(SliceLayers, NonManifoldAndFlippedFacesNeverBreakTheSlicer) {
  // Two boxes welded along the edge x = y = 1, which then has four faces (non-manifold).
  Mesh a = test::make_box(0, 0, 0, 1, 1, 1, 2);
  const Mesh b = test::make_box(1, 1, 0, 2, 2, 1, 2);
  const size_t na = a.vertices();
  std::vector<uint32_t> weld(b.vertices());
  for (size_t i = 0; i < b.vertices(); ++i) {
    weld[i] = uint32_t(a.vertices());
    for (size_t j = 0; j < na; ++j)
      if (a.V[3 * j] == b.V[3 * i] && a.V[3 * j + 1] == b.V[3 * i + 1] && a.V[3 * j + 2] == b.V[3 * i + 2])
        weld[i] = uint32_t(j);
    if (weld[i] == a.vertices()) a.V.insert(a.V.end(), &b.V[3 * i], &b.V[3 * i + 3]);
  }
  for (uint32_t i : b.F) a.F.push_back(weld[i]);
  ASSERT_EQ(a.vertices(), 2 * b.vertices() - 3);
  Slices s = slice(a, 0.1);
  expect_encoding_consistent(a, s);
  ASSERT_EQ(s.layers(), 10u);
  // The shared edge links each box's faces to the other's as often one way as the other: every
  // layer is closed loops, which enclose the two unit squares (an area of 2, counter-clockwise).
  for (size_t k = 0; k < s.layers(); ++k) {
    double area = 0;
    for (uint64_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c) {
      EXPECT_FALSE(s.contour_open[c]) << k;
      const uint64_t b = s.contour_begin[c], n = s.contour_begin[c + 1] - b;
      for (uint64_t i = 0; i < n; ++i) {
        const double* p = &s.xyz[3 * (b + i)];
        const double* q = &s.xyz[3 * (b + (i + 1) % n)];
        area += 0.5 * (p[0] * q[1] - q[0] * p[1]);
      }
    }
    EXPECT_NEAR(area, 2, 1e-12) << k;
  }
  // Flip a wall face against its neighbours' orientation: its layers break into more pieces.
  size_t f = 0;
  while (a.V[3 * a.F[3 * f] + 2] == a.V[3 * a.F[3 * f + 1] + 2] && a.V[3 * a.F[3 * f] + 2] == a.V[3 * a.F[3 * f + 2] + 2]) ++f;
  std::swap(a.F[3 * f], a.F[3 * f + 1]);
  s = slice(a, 0.1);
  expect_encoding_consistent(a, s);
  // The face spans 5 layers; in each, its segment and the rest of its loop are two open pieces.
  EXPECT_EQ(s.open_contours(), 10u);
}

// Without encoding (the masks' path) the slicer finds the same points as with it.
TEST(SliceLayers, WithoutEncodingGivesTheSamePoints) {
  test::FamilyOptions o;
  o.shape = "arch";
  o.faces = 3000;
  o.height = 5;
  o.seed = 3;
  const Mesh base = test::make_family_base(o);
  SliceOptions s;
  s.thickness = 0.1;
  const Slices encoded = slice_layers(base, s);
  s.encoding = false;
  const Slices bare = slice_layers(base, s);
  ASSERT_GT(encoded.points(), 0u);
  EXPECT_TRUE(bare.face.empty() && bare.edge.empty() && bare.t.empty());
  EXPECT_EQ(bare.layer_begin, encoded.layer_begin);
  EXPECT_EQ(bare.contour_begin, encoded.contour_begin);
  EXPECT_EQ(bare.contour_open, encoded.contour_open);
  EXPECT_TRUE(bare.xyz == encoded.xyz);
}

TEST(SliceLayers, RejectsBadInput) {
  const Mesh box = test::make_box(0, 0, 0, 1, 1, 1);
  EXPECT_THROW(slice(Mesh{}, 0.1), Error);
  EXPECT_THROW(slice(box, 0), Error);
  EXPECT_THROW(slice(box, -0.1), Error);
  EXPECT_THROW(slice(box, 0.1, 5.0), Error);
  Mesh bad = box;
  bad.F[4] = 1000;
  EXPECT_THROW(slice(bad, 0.1), Error);
  bad = box;
  bad.V[5] = NAN;
  EXPECT_THROW(slice(bad, 0.1), Error);
}

TEST(SliceLayers, CancelledRunThrows) {
  const Mesh m = test::make_sphere(1, 20, 20);
  SliceOptions o;
  o.thickness = 0.001;
  EXPECT_THROW(slice_layers(m, o, [](double, const char*) { return false; }), Cancelled);
}

TEST(SliceLayers, LowestVertexZStartMeansNaN) {
  EXPECT_TRUE(std::isnan(z_start_option(kLowestVertexZStart)));
  EXPECT_TRUE(std::isnan(z_start_option(kLowestVertexZStartAtOrBelow)));
  EXPECT_EQ(z_start_option(-1e28), -1e28);
  EXPECT_EQ(z_start_option(0.25), 0.25);
  // The default slices from the lowest vertex, as a NaN z_start does.
  const Mesh box = test::make_box(0, 0, 0.3, 1, 1, 1.3);
  SliceOptions o;
  o.z_start = z_start_option(kLowestVertexZStart);
  EXPECT_EQ(slice_layers(box, o).z_start, 0.3);
}

// straddling_face_counts equals a face-by-face count by the slicer's rule (a corner below the
// plane, a corner at or above it): on evenly spaced planes, with vertices exactly on planes, and
// on uneven planes (looked up by search, not arithmetic); on a closed mesh each count is the
// number of points the slicer gives that layer.
TEST(StraddlingFaces, CountsEqualAFaceByFaceCountAndTheSlicersPoints) {
  test::FamilyOptions o;
  o.shape = "ear";
  o.faces = 6000;
  o.height = 10;
  Mesh m = test::make_family_base(o);
  SliceOptions so;
  so.thickness = 0.25;
  so.encoding = false;
  const Slices s = slice_layers(m, so);
  // Some vertices exactly on planes.
  for (size_t v = 0; v < m.vertices(); v += 7) m.V[3 * v + 2] = s.layer_z[(v / 7) % s.layers()];
  std::vector<double> uneven;
  for (size_t k = 0; k < s.layers(); k += 1 + k % 3) uneven.push_back(s.layer_z[k] + (k % 2 ? 0.01 : 0));
  for (const std::vector<double>& planes : {s.layer_z, uneven}) {
    const std::vector<uint64_t> counts = straddling_face_counts(m, planes);
    ASSERT_EQ(counts.size(), planes.size());
    for (size_t k = 0; k < planes.size(); ++k) {
      uint64_t expected = 0;
      for (size_t f = 0; f < m.faces(); ++f) {
        bool below = false, above = false;
        for (int j = 0; j < 3; ++j) {
          const double z = m.V[3 * size_t(m.F[3 * f + j]) + 2];
          below |= z < planes[k];
          above |= z >= planes[k];
        }
        expected += below && above;
      }
      EXPECT_EQ(counts[k], expected) << "plane " << k;
    }
  }
  const Slices sliced = slice_planes(m, s.layer_z, {}, false);
  const std::vector<uint64_t> counts = straddling_face_counts(m, s.layer_z);
  for (size_t k = 0; k < sliced.layers(); ++k) {
    ASSERT_EQ(sliced.open_contours(), 0u);
    EXPECT_EQ(counts[k], sliced.contour_begin[sliced.layer_begin[k + 1]] - sliced.contour_begin[sliced.layer_begin[k]]);
  }
}
