// Slices <-> edge mesh with per-vertex attributes (the form of a contour layer in MeshLab):
// exact round trips with and without an encoding, and refusal of meshes that are not contours.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "slicereuse/formats/contour_mesh.h"
#include "slicereuse/util/error.h"
#include "test_files.h"

using namespace slicereuse;
using namespace slicereuse::test;

namespace {

void expect_identical(const Slices& a, const Slices& b) {
  expect_same_structure(a, b);
  EXPECT_TRUE(same_bits(a.xyz, b.xyz));
  EXPECT_EQ(a.fingerprint, b.fingerprint);
  EXPECT_TRUE(same_bits(a.face, b.face));
  EXPECT_TRUE(same_bits(a.edge, b.edge));
  EXPECT_TRUE(same_bits(a.t, b.t));
}

// Every contour open or closed, 1- and 2-point contours of both kinds, empty layers.
Slices sample(size_t open_every = 3) {
  return make_slices({5, 1, 2, 1, 2, 4, -1, -1, 7, 2, 1, -1, 30, 3, 3, 9, -1}, 11, open_every);
}

}  // namespace

TEST(ContourMesh, RoundTripWithEncodingIsExact) {
  for (size_t open_every : {2, 3, 1000}) {
    const Slices s = sample(open_every);
    const ContourMesh m = contour_mesh_from_slices(s);
    expect_identical(s, slices_from_contour_mesh(m));
  }
}

TEST(ContourMesh, RoundTripWithoutEncodingIsExact) {
  Slices s = sample();
  s.face.clear();
  s.edge.clear();
  s.t.clear();
  s.fingerprint = {};
  const ContourMesh m = contour_mesh_from_slices(s);
  EXPECT_FALSE(m.has_encoding());
  expect_identical(s, slices_from_contour_mesh(m));
}

TEST(ContourMesh, VerticesEdgesAndAttributesAreAsDocumented) {
  const Slices s = sample();
  const ContourMesh m = contour_mesh_from_slices(s);
  ASSERT_EQ(m.vertices(), s.points());
  EXPECT_EQ(m.edges.size(), 2 * (s.points() - s.open_contours()));
  EXPECT_TRUE(same_bits(m.position, s.xyz));
  EXPECT_EQ(m.layer_z, s.layer_z);
  for (size_t k = 0; k < s.layers(); ++k)
    for (uint64_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c)
      for (uint64_t p = s.contour_begin[c]; p < s.contour_begin[c + 1]; ++p) {
        EXPECT_EQ(m.layer[p], k);
        EXPECT_EQ(m.contour[p], c);
        EXPECT_EQ(m.face[p], s.face[p]);
        // The method's area coordinates: 1 - t on corner j, t on corner j+1, 0 on the third.
        const unsigned j = s.edge[p];
        EXPECT_EQ(m.area[3 * p + j], 1 - s.t[p]);
        EXPECT_EQ(m.area[3 * p + (j + 1) % 3], s.t[p]);
        EXPECT_EQ(m.area[3 * p + (j + 2) % 3], 0.0);
      }
  // A closed one-point contour has the edge (v, v); a closed two-point one two edges.
  size_t loops = 0;
  for (size_t e = 0; e < m.edges.size(); e += 2) loops += m.edges[e] == m.edges[e + 1];
  size_t closed_singletons = 0;
  for (size_t c = 0; c < s.contours(); ++c)
    closed_singletons += !s.contour_open[c] && s.contour_begin[c + 1] - s.contour_begin[c] == 1;
  EXPECT_EQ(loops, closed_singletons);
  EXPECT_GT(loops, 0u);
}

TEST(ContourMesh, EdgeOrderAndDirectionDoNotMatter) {
  const Slices s = sample();
  ContourMesh m = contour_mesh_from_slices(s);
  // MeshLab may store edges in any order and either direction.
  for (size_t e = 0; e < m.edges.size(); e += 2) std::swap(m.edges[e], m.edges[e + 1]);
  for (size_t e = 0, f = m.edges.size() - 2; e < f; e += 2, f -= 2) {
    std::swap(m.edges[e], m.edges[f]);
    std::swap(m.edges[e + 1], m.edges[f + 1]);
  }
  expect_identical(s, slices_from_contour_mesh(m));
}

TEST(ContourMesh, DeletedContoursAreRenumbered) {
  const Slices s = sample();
  ContourMesh m = contour_mesh_from_slices(s);
  // Delete contour 0 (5 points, vertices 0..4) the way MeshLab compacts a mesh.
  const uint32_t gone = uint32_t(s.contour_begin[1]);
  ContourMesh d = m;
  d.position.assign(m.position.begin() + 3 * gone, m.position.end());
  d.layer.assign(m.layer.begin() + gone, m.layer.end());
  d.contour.assign(m.contour.begin() + gone, m.contour.end());
  d.face.assign(m.face.begin() + gone, m.face.end());
  d.area.assign(m.area.begin() + 3 * gone, m.area.end());
  d.edges.clear();
  for (size_t e = 0; e < m.edges.size(); e += 2)
    if (m.edges[e] >= gone) {
      d.edges.push_back(m.edges[e] - gone);
      d.edges.push_back(m.edges[e + 1] - gone);
    }
  const Slices r = slices_from_contour_mesh(d);
  EXPECT_EQ(r.contours(), s.contours() - 1);
  EXPECT_EQ(r.points(), s.points() - gone);
  EXPECT_EQ(r.layer_begin[1], s.layer_begin[1] - 1);
  EXPECT_EQ(r.layer_begin.back(), s.contours() - 1);
  EXPECT_TRUE(std::equal(r.contour_open.begin(), r.contour_open.end(), s.contour_open.begin() + 1));
}

TEST(ContourMesh, MeshesThatAreNotContoursAreRefused) {
  const Slices s = sample();
  const ContourMesh m = contour_mesh_from_slices(s);
  {
    ContourMesh d = m;
    d.edges.erase(d.edges.begin(), d.edges.begin() + 2);  // edge 0-1 of contour 0
    EXPECT_ERROR(slices_from_contour_mesh(d), "contour 0 is broken: no edge between vertices 0 and 1");
  }
  {
    ContourMesh d = m;
    d.edges.push_back(0);
    d.edges.push_back(2);
    EXPECT_ERROR(slices_from_contour_mesh(d), "(vertices 0, 2) is not a segment of contour 0");
  }
  {
    ContourMesh d = m;
    d.edges.push_back(0);
    d.edges.push_back(uint32_t(s.contour_begin[1]));
    EXPECT_ERROR(slices_from_contour_mesh(d), "of different contours");
  }
  {
    ContourMesh d = m;
    d.edges.push_back(0);
    d.edges.push_back(uint32_t(m.vertices()));
    EXPECT_ERROR(slices_from_contour_mesh(d), "names vertex");
  }
  {
    ContourMesh d = m;
    std::swap(d.contour[0], d.contour[d.vertices() - 1]);
    EXPECT_ERROR(slices_from_contour_mesh(d), "vertex 1: contour indices decrease");
  }
  {
    ContourMesh d = m;
    d.layer[d.vertices() - 1] = uint32_t(m.layer_z.size());
    EXPECT_ERROR(slices_from_contour_mesh(d), "but there are only");
  }
  {
    ContourMesh d = m;
    d.layer[1] = 1;
    EXPECT_ERROR(slices_from_contour_mesh(d), "vertex 1: contour 0 spans layers 0 and 1");
  }
  {
    ContourMesh d = m;
    d.area[3 * 4 + 0] = d.area[3 * 4 + 1] = d.area[3 * 4 + 2] = 0.25;
    EXPECT_ERROR(slices_from_contour_mesh(d), "vertex 4: point not on a face edge");
  }
  {
    ContourMesh d = m;
    d.face[3] = uint32_t(s.fingerprint.faces);
    EXPECT_ERROR(slices_from_contour_mesh(d), "face[3]");
  }
  {
    ContourMesh d = m;
    d.contour.pop_back();
    EXPECT_ERROR(slices_from_contour_mesh(d), "disagree in size");
  }
}

TEST(ContourMesh, HashTellsChangedMeshesApart) {
  const ContourMesh m = contour_mesh_from_slices(sample());
  const uint64_t h = contour_mesh_hash(m);
  EXPECT_EQ(contour_mesh_hash(contour_mesh_from_slices(sample())), h);
  ContourMesh d = m;
  d.position[7] = std::nextafter(d.position[7], 1e300);
  EXPECT_NE(contour_mesh_hash(d), h);
  d = m;
  d.edges.pop_back();
  d.edges.pop_back();
  EXPECT_NE(contour_mesh_hash(d), h);
  d = m;
  d.layer_z.push_back(9);
  EXPECT_NE(contour_mesh_hash(d), h);
  d = m;
  d.area[5] = 0.5;
  EXPECT_NE(contour_mesh_hash(d), h);
}
