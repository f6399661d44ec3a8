// The support tree: closed outward shells, pillars that enter the part only at heads and feet,
// supports that form no island of their own, blocked ways down, the pad, and errors in words.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "error_of.h"
#include "family.h"
#include "shapes.h"
#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/supports/support_tree.h"
#include "support_points_on.h"
#include "support_tree_checks.h"

using namespace slicereuse;
using ClipperLib::Paths;

namespace {

constexpr double kLayer = 0.05;

using test::points_on;

// The face of part whose centroid is nearest (x, y, z).
uint32_t face_near(const Mesh& part, double x, double y, double z) {
  uint32_t best = 0;
  double best_d = HUGE_VAL;
  for (uint32_t f = 0; f < part.faces(); ++f) {
    double c[3] = {0, 0, 0};
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[k] += part.V[3 * size_t(part.F[3 * f + j]) + k] / 3;
    const double d = (c[0] - x) * (c[0] - x) + (c[1] - y) * (c[1] - y) + (c[2] - z) * (c[2] - z);
    if (d < best_d) best_d = d, best = f;
  }
  return best;
}

// Faces facing down (unit normal z < -0.5), greedily at least `spacing` mm apart.
std::vector<uint32_t> downward_faces(const Mesh& part, double spacing) {
  std::vector<uint32_t> faces;
  const SupportPoints all = [&] {
    std::vector<uint32_t> f(part.faces());
    std::iota(f.begin(), f.end(), 0u);
    return points_on(part, f);
  }();
  std::vector<std::array<double, 3>> taken;
  for (uint32_t f = 0; f < part.faces(); ++f) {
    if (all.normal[3 * f + 2] >= -0.5) continue;
    const double* c = &all.xyz[3 * size_t(f)];
    if (std::any_of(taken.begin(), taken.end(), [&](const std::array<double, 3>& t) {
          return (t[0] - c[0]) * (t[0] - c[0]) + (t[1] - c[1]) * (t[1] - c[1]) + (t[2] - c[2]) * (t[2] - c[2]) <
                 spacing * spacing;
        }))
      continue;
    taken.push_back({c[0], c[1], c[2]});
    faces.push_back(f);
  }
  return faces;
}

// The mesh's shells: the components of faces joined by shared vertices, each as its own mesh.
std::vector<Mesh> shells_of(const Mesh& m) {
  std::vector<uint32_t> root(m.vertices());
  std::iota(root.begin(), root.end(), 0u);
  auto find = [&](uint32_t v) {
    while (root[v] != v) v = root[v] = root[root[v]];
    return v;
  };
  for (size_t f = 0; f < m.faces(); ++f)
    for (int j = 1; j < 3; ++j) root[find(m.F[3 * f + j])] = find(m.F[3 * f]);
  std::vector<int> shell_of_root(m.vertices(), -1);
  std::vector<Mesh> shells;
  for (size_t f = 0; f < m.faces(); ++f) {
    int& s = shell_of_root[find(m.F[3 * f])];
    // Vertices keep their ids (unused ones are harmless to the edge census and the volume).
    if (s < 0) s = int(shells.size()), shells.push_back(Mesh{m.V, {}});
    Mesh& shell = shells[size_t(s)];
    shell.F.insert(shell.F.end(), &m.F[3 * f], &m.F[3 * f] + 3);
  }
  return shells;
}

void expect_closed_outward_shells(const SupportTree& tree, size_t expected_shells) {
  const std::vector<Mesh> shells = shells_of(tree.mesh);
  EXPECT_EQ(shells.size(), expected_shells);
  for (size_t s = 0; s < shells.size(); ++s) {
    EXPECT_EQ(test::edge_census(shells[s]).bad_edges, 0u) << "shell " << s;
    EXPECT_GT(test::signed_volume(shells[s]), 0) << "shell " << s;
  }
}

Paths region_of(const Slices& s, size_t k) { return layer_region(LayerView(s, k)); }

// The shared checks (support_tree_checks.h) as assertions. Returns the number of layers where
// part and supports overlap.
size_t check_sections(const Mesh& part, const SupportTree& tree) {
  const test::TreeSections t = test::check_tree_sections(part, tree, kLayer);
  EXPECT_EQ(t.open_contours, 0u);
  if (tree.pillars > 0) EXPECT_GT(t.ground_area_mm2, 0);
  EXPECT_LT(t.outside_zones_mm2, 1e-9) << "layer " << t.outside_zones_layer << " at z = " << t.outside_zones_z;
  EXPECT_EQ(t.support_islands, 0u) << "islands of the supports, the first in layer " << t.first_support_island_layer;
  return t.overlapping_layers;
}

// Returns the number of feet.
size_t expect_feet_on_part(const Mesh& part, const SupportTree& tree, const SupportTreeOptions& o) {
  const test::FeetOnPart f = test::check_feet_on_part(part, tree, o);
  EXPECT_EQ(f.in_air, 0u) << "the foot at (" << f.farthest_xy[0] << ", " << f.farthest_xy[1] << ") ends "
                          << f.farthest_mm << " mm from the part";
  return f.feet;
}

test::FamilyOptions shape(const char* name) {
  test::FamilyOptions o;
  o.shape = name;
  o.faces = 10000;
  o.height = 10;
  return o;
}

}  // namespace

TEST(SupportTree, OnePointOverFlatGroundIsHeadPillarBaseAndPad) {
  const Mesh part = test::make_box(0, 0, 0, 4, 4, 2);
  const SupportPoints pts = points_on(part, {face_near(part, 1, 2, 0)});
  const SupportTree tree = build_support_tree(part, pts, -6, SupportTreeOptions{});
  EXPECT_EQ(tree.pillars, 1u);
  EXPECT_EQ(tree.on_part, 0u);
  EXPECT_EQ(tree.ground_z, -6);
  ASSERT_EQ(tree.head_zones.size(), 1u);
  const HeadZone& h = tree.head_zones[0];
  EXPECT_DOUBLE_EQ(h.z_top, 0.5);
  EXPECT_DOUBLE_EQ(h.z_bottom, -3);
  EXPECT_DOUBLE_EQ(h.r_top, 0.25);
  EXPECT_DOUBLE_EQ(h.r_bottom, 0.5);
  expect_closed_outward_shells(tree, 4);  // head, pillar, base, pad
  const ZRange zr = z_range(tree.mesh);
  EXPECT_EQ(zr.min, -6);
  EXPECT_EQ(zr.max, 0.5);
  // The pad's bottom is exactly ground_z, its top ground_z + the wall thickness; the base on it
  // is 1 mm high, the pillar above it reaches the head's bottom.
  std::vector<double> zs;
  for (size_t v = 0; v < tree.mesh.vertices(); ++v) zs.push_back(tree.mesh.V[3 * v + 2]);
  std::sort(zs.begin(), zs.end());
  zs.erase(std::unique(zs.begin(), zs.end()), zs.end());
  EXPECT_EQ(zs, (std::vector<double>{-6, -5, -4, -3, 0.5}));
  check_sections(part, tree);
}

TEST(SupportTree, PadIsTheHullOfTheBasesSlopingInToThePlate) {
  // Three pillars on a line (the hull's middle corner drops out): the pad's top is the hull of the
  // bases (no brim, raised); its walls slope in at 45 degrees over its 1 mm, so its section just
  // above the ground is a 16-gon of radius base - 1 + 0.025 mm stretched 4 mm.
  const Mesh part = test::make_box(0, 0, 0, 6, 4, 2);
  SupportPoints pts = points_on(part, {face_near(part, 1, 2, 0), face_near(part, 1, 2, 0), face_near(part, 1, 2, 0)});
  for (size_t i = 0; i < 3; ++i) {
    pts.xyz[3 * i] = 1 + 2.0 * double(i);
    pts.xyz[3 * i + 1] = 2;
    pts.xyz[3 * i + 2] = 0;
  }
  const SupportTree tree = build_support_tree(part, pts, -6, SupportTreeOptions{});
  EXPECT_EQ(tree.pillars, 3u);
  expect_closed_outward_shells(tree, 10);
  const Slices s = slice_planes(tree.mesh, {-6 + kLayer / 2}, {}, false);
  const double r = 1.5 - 1 + kLayer / 2;
  // Within the rounding of the section's points to 1 nm along its 27 mm outline.
  EXPECT_NEAR(region_area_mm2(region_of(s, 0)), 8 * r * r * std::sin(M_PI / 8) + 4 * 2 * r, 3e-5);
  check_sections(part, tree);
}

TEST(SupportTree, NoPadStandsOnTheGround) {
  const Mesh part = test::make_box(0, 0, 0, 4, 4, 2);
  SupportTreeOptions o;
  o.pad_enable = false;
  const SupportTree tree = build_support_tree(part, points_on(part, {face_near(part, 1, 2, 0)}), -5, o);
  expect_closed_outward_shells(tree, 3);  // head, pillar, base
  EXPECT_EQ(z_range(tree.mesh).min, -5);
}

TEST(SupportTree, NoPointsNoStructure) {
  const Mesh part = test::make_box(0, 0, 0, 4, 4, 2);
  const SupportTree tree = build_support_tree(part, points_on(part, {}), -5, SupportTreeOptions{});
  EXPECT_EQ(tree.mesh.faces(), 0u);
  EXPECT_TRUE(tree.head_zones.empty());
  EXPECT_EQ(tree.ground_z, -5);
}

TEST(SupportTree, BlockedPillarEndsOnThePartWithAFoot) {
  // A wide slab above a small block: under the block the way down is blocked, beside it clear.
  Mesh part = test::make_box(0, 0, 0, 10, 10, 2);
  const Mesh slab = test::make_box(0, 0, 8, 20, 10, 10);
  test::append_mesh(part, slab);
  const SupportPoints pts = points_on(part, {face_near(part, 5, 5, 8), face_near(part, 15, 5, 8)});
  ASSERT_LT(pts.xyz[0], 10);
  ASSERT_GT(pts.xyz[3], 10);
  const SupportTree tree = build_support_tree(part, pts, -5, SupportTreeOptions{});
  EXPECT_EQ(tree.pillars, 1u);
  EXPECT_EQ(tree.on_part, 1u);
  ASSERT_EQ(tree.head_zones.size(), 3u);  // two heads and the foot
  const HeadZone& foot = tree.head_zones[1];
  EXPECT_DOUBLE_EQ(foot.z_bottom, 2 - 0.5);
  EXPECT_DOUBLE_EQ(foot.z_top, 2 + 1);
  EXPECT_DOUBLE_EQ(foot.r_bottom, 0.25);
  EXPECT_DOUBLE_EQ(foot.r_top, 0.5);
  // head, pillar, foot; head, pillar, base; pad
  expect_closed_outward_shells(tree, 7);
  EXPECT_GT(check_sections(part, tree), 0u);
}

// A pillar whose axis passes beside a block (0.4 mm out) but whose rim meets it: the foot stands
// on the block, not in the air beside it.
TEST(SupportTree, FootUnderABlockedRimStandsOnThePart) {
  Mesh part = test::make_box(0, 0, 0, 10, 10, 2);
  const Mesh slab = test::make_box(0, 0, 8, 20, 10, 10);
  test::append_mesh(part, slab);
  SupportPoints pts = points_on(part, {face_near(part, 15, 5, 8)});
  pts.xyz[0] = 10.4, pts.xyz[1] = 5, pts.xyz[2] = 8;
  const SupportTree tree = build_support_tree(part, pts, -5, SupportTreeOptions{});
  EXPECT_EQ(tree.on_part, 1u);
  EXPECT_EQ(expect_feet_on_part(part, tree, SupportTreeOptions{}), 1u);
  check_sections(part, tree);
}

// A slab (z 8-10) on two legs (z 2-8) with a groove of `width` between them at x = 10, running
// along y (0-10): one closed surface (a U extruded), so that what lies inside it is told by its
// faces. The pillar's rim (0.65 mm out) starts inside the legs wherever a head in the groove ends.
Mesh grooved_slab(double width) {
  const double a = 10 - width / 2, b = 10 + width / 2;
  // The U's corners counter-clockwise in x-z, and its rectangles (corners of the U only, so that
  // no edge ends on another).
  const double xz[12][2] = {{4, 2}, {a, 2}, {a, 8}, {b, 8}, {b, 2}, {16, 2},
                            {16, 8}, {16, 10}, {b, 10}, {a, 10}, {4, 10}, {4, 8}};
  const int quads[5][4] = {{0, 1, 2, 11}, {4, 5, 6, 3}, {11, 2, 9, 10}, {2, 3, 8, 9}, {3, 6, 7, 8}};
  Mesh m;
  for (const double y : {0.0, 10.0})
    for (const auto& v : xz) m.V.insert(m.V.end(), {v[0], y, v[1]});
  for (const auto& q : quads)  // the cap at y = 0 faces -y: counter-clockwise in x-z; at y = 10 reversed
    for (const uint32_t o : {0u, 12u}) {
      const uint32_t c[4] = {o + uint32_t(q[0]), o + uint32_t(q[1]), o + uint32_t(q[2]), o + uint32_t(q[3])};
      if (o == 0) m.F.insert(m.F.end(), {c[0], c[1], c[2], c[0], c[2], c[3]});
      else m.F.insert(m.F.end(), {c[0], c[2], c[1], c[0], c[3], c[2]});
    }
  for (uint32_t i = 0; i < 12; ++i) {
    const uint32_t j = (i + 1) % 12;
    m.F.insert(m.F.end(), {i, j + 12, j, i, i + 12, j + 12});
  }
  return m;
}

// Points at the given (x, z), y = 5, each held by the face nearest it.
SupportPoints points_at(const Mesh& part, const std::vector<std::array<double, 2>>& xz) {
  std::vector<uint32_t> faces;
  for (const auto& p : xz) faces.push_back(face_near(part, p[0], 5, p[1]));
  SupportPoints pts = points_on(part, faces);
  for (size_t i = 0; i < xz.size(); ++i) pts.xyz[3 * i] = xz[i][0], pts.xyz[3 * i + 1] = 5, pts.xyz[3 * i + 2] = xz[i][1];
  return pts;
}

// A point on the ceiling of a groove narrower than the pillar: no pillar fits, and the head's
// back lies against the legs: it rests on them (before, the rim rays started inside the legs and
// met only their undersides: the pillar ran in a leg, its foot hung below it; the sweep's arch
// 703 3 54.5 69.5 2.2 8.5 6000).
TEST(SupportTree, HeadInAGrooveNarrowerThanThePillarRestsOnItsWalls) {
  const Mesh part = grooved_slab(0.9);
  ASSERT_EQ(test::edge_census(part).bad_edges, 0u);
  ASSERT_NEAR(test::signed_volume(part), 10 * (12 * 2 + (12 - 0.9) * 6), 1e-9);
  const SupportPoints pts = points_at(part, {{10, 8}});
  ASSERT_EQ(pts.normal[2], -1);
  const SupportTree tree = build_support_tree(part, pts, -5, SupportTreeOptions{});
  EXPECT_EQ(tree.on_part, 1u);
  EXPECT_EQ(tree.pillars, 0u);
  EXPECT_EQ(tree.structure.feet.size(), 0u);
  ASSERT_EQ(tree.structure.heads.size(), 1u);
  EXPECT_EQ(tree.structure.heads[0].rest, HeadRest::Part);
  EXPECT_DOUBLE_EQ(tree.structure.heads[0].cone.back[2], 5);
  expect_closed_outward_shells(tree, 1);
  EXPECT_GT(check_sections(part, tree), 0u);
}

// Wider than the pillar, narrower than its rim's clearance: the rim rays start inside the legs,
// and only what lies below the legs counts; there is nothing: the pillar runs down the groove to
// the pad (before, the legs' undersides were taken for a floor, and its foot hung below them).
TEST(SupportTree, PillarInAGrooveNarrowerThanItsClearanceRunsDownIt) {
  const Mesh part = grooved_slab(1.2);
  const SupportTree tree = build_support_tree(part, points_at(part, {{10, 8}}), -5, SupportTreeOptions{});
  EXPECT_EQ(tree.pillars, 1u);
  EXPECT_EQ(tree.on_part, 0u);
  EXPECT_EQ(tree.structure.feet.size(), 0u);
  check_sections(part, tree);
}

// Wider than the head's back, narrower than the pillar and its margin: no pillar fits, and the
// head's back would hang between the legs: the point is dropped, as PrusaSlicer drops the heads
// it cannot route (the ceiling is a 1.08 mm bridge between the legs); one under a leg is built.
TEST(SupportTree, HeadInAGrooveThatHoldsNeitherPillarNorHeadIsDropped) {
  const Mesh part = grooved_slab(1.08);
  const SupportPoints pts = points_at(part, {{10, 8}, {6, 2}});
  ASSERT_EQ(pts.normal[5], -1);
  const SupportTree tree = build_support_tree(part, pts, -5, SupportTreeOptions{});
  EXPECT_EQ(tree.unroutable, 1u);
  EXPECT_EQ(tree.pillars, 1u);
  ASSERT_EQ(tree.structure.heads.size(), 1u);
  EXPECT_EQ(tree.structure.heads[0].point, 1u);
  check_sections(part, tree);
}

// A point on a wall that leans out towards its foot (its surface facing sideways and 14 degrees
// up, far from PrusaSlicer's 30 degrees from straight up): the part lies right under it.
// A vertical head went down through the part, met its underside as "the part below", and ended
// under it, hanging (the sweep's arch 234 3 20.5 11.5 2.55 6.5 6000); now the point is dropped,
// the part holding it, and counted.
TEST(SupportTree, PointWithThePartRightUnderItIsDropped) {
  // A frustum: the 4 mm square at z = 0, the 3 mm one at z = 2 (its sides face 14 degrees up).
  Mesh part;
  part.V = {0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4, 0, 0.5, 0.5, 2, 3.5, 0.5, 2, 3.5, 3.5, 2, 0.5, 3.5, 2};
  part.F = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
  ASSERT_EQ(test::edge_census(part).bad_edges, 0u);
  ASSERT_GT(test::signed_volume(part), 0);
  SupportPoints pts = points_on(part, {face_near(part, 3.8, 2, 0.4), face_near(part, 2, 2, 0)});
  ASSERT_GT(pts.normal[2], 0);
  ASSERT_LT(pts.normal[2], 0.5);
  pts.xyz[0] = 3.85, pts.xyz[1] = 2, pts.xyz[2] = 0.6;  // on the side x = 4 - z / 4
  const SupportTree tree = build_support_tree(part, pts, -6, SupportTreeOptions{});
  EXPECT_EQ(tree.unroutable, 1u);
  EXPECT_EQ(tree.up_facing, 0u);
  ASSERT_EQ(tree.structure.heads.size(), 1u);
  EXPECT_EQ(tree.structure.heads[0].point, 1u);
  check_sections(part, tree);
}

// A pillar blocked by a plate thinner than twice the penetration: its foot goes halfway into the
// plate, not out of its underside, where its tip hung as an island of the supports (the sweep's
// arch 402 2 34.5 16 2.7 9.5 6000).
TEST(SupportTree, FootOnAThinPlateStaysInsideIt) {
  Mesh part = test::make_box(0, 0, 2, 10, 10, 2.4);
  test::append_mesh(part, test::make_box(0, 0, 8, 20, 10, 10));
  const SupportTree tree = build_support_tree(part, points_on(part, {face_near(part, 5, 5, 8)}), -5, {});
  ASSERT_EQ(tree.structure.feet.size(), 1u);
  EXPECT_NEAR(tree.structure.feet[0].cone.tip[2], 2.2, 1e-12);
  EXPECT_NEAR(tree.structure.feet[0].penetration, 0.2, 1e-12);
  EXPECT_EQ(expect_feet_on_part(part, tree, SupportTreeOptions{}), 1u);
  check_sections(part, tree);
}

// PrusaSlicer builds no head under a point whose surface faces up (its normal within 30 degrees
// of +z): such a point (a user's, on the top face) is dropped and counted; one on the bottom
// face beside it is built.
TEST(SupportTree, PointsFacingUpAreDropped) {
  const Mesh part = test::make_box(0, 0, 0, 4, 4, 2);
  const SupportPoints pts = points_on(part, {face_near(part, 1, 2, 2), face_near(part, 1, 2, 0)});
  ASSERT_EQ(pts.normal[2], 1);
  ASSERT_EQ(pts.normal[5], -1);
  const SupportTree tree = build_support_tree(part, pts, -6, SupportTreeOptions{});
  EXPECT_EQ(tree.up_facing, 1u);
  EXPECT_EQ(tree.pillars, 1u);
  EXPECT_EQ(tree.on_part, 0u);
  EXPECT_EQ(tree.head_zones.size(), 1u);
  check_sections(part, tree);
}

TEST(SupportTree, HeadReachingThePartBelowEndsInIt) {
  Mesh part = test::make_box(0, 0, 0, 10, 10, 2);
  const Mesh slab = test::make_box(0, 0, 4, 10, 10, 6);
  test::append_mesh(part, slab);
  const SupportTree tree = build_support_tree(part, points_on(part, {face_near(part, 5, 5, 4)}), -5, {});
  EXPECT_EQ(tree.pillars, 0u);
  EXPECT_EQ(tree.on_part, 1u);
  ASSERT_EQ(tree.head_zones.size(), 1u);
  EXPECT_DOUBLE_EQ(tree.head_zones[0].z_bottom, 1.5);
  expect_closed_outward_shells(tree, 1);  // no pillar reaches the ground: no pad either
  check_sections(part, tree);
}

// Where the part below is thinner than twice the penetration (a shell's rim), the head ends
// halfway into it rather than out of its underside, where its tip would hang under the part: an
// island (the support sweep's arch 234 3 20.5 11.5 2.55 6.5 6000).
TEST(SupportTree, HeadEndingInAThinPartBelowStaysInsideIt) {
  Mesh part = test::make_box(0, 0, 1.7, 10, 10, 2);
  const Mesh slab = test::make_box(0, 0, 4, 10, 10, 6);
  test::append_mesh(part, slab);
  const SupportTree tree = build_support_tree(part, points_on(part, {face_near(part, 5, 5, 4)}), -5, {});
  EXPECT_EQ(tree.on_part, 1u);
  ASSERT_EQ(tree.head_zones.size(), 1u);
  EXPECT_NEAR(tree.head_zones[0].z_bottom, 1.85, 1e-12);
  check_sections(part, tree);
}

// Under a wall thinner than twice the penetration (a shell's), the head goes halfway into it and
// does not come out of its other side; under a thick one, the full penetration.
TEST(SupportTree, HeadsStayInsideThinWalls) {
  const Mesh thin = test::make_box(0, 0, 4, 10, 10, 4.4);
  const SupportTree in_thin = build_support_tree(thin, points_on(thin, {face_near(thin, 5, 5, 4)}), -5, {});
  ASSERT_EQ(in_thin.head_zones.size(), 1u);
  EXPECT_NEAR(in_thin.head_zones[0].z_top, 4.2, 1e-12);
  const Mesh thick = test::make_box(0, 0, 4, 10, 10, 6);
  const SupportTree in_thick = build_support_tree(thick, points_on(thick, {face_near(thick, 5, 5, 4)}), -5, {});
  ASSERT_EQ(in_thick.head_zones.size(), 1u);
  EXPECT_NEAR(in_thick.head_zones[0].z_top, 4.5, 1e-12);
  check_sections(thin, in_thin);
}

TEST(SupportTree, SphereAndHandleEnterThePartOnlyAtHeads) {
  for (const char* name : {"sphere", "handle"}) {
    SCOPED_TRACE(name);
    const Mesh part = test::make_family_base(shape(name));
    const SupportPoints pts = points_on(part, downward_faces(part, 1.5));
    ASSERT_GT(pts.size(), 10u);
    const double ground_z = support_ground_z(0, kLayer, SupportTreeOptions{});
    const SupportTree tree = build_support_tree(part, pts, ground_z, SupportTreeOptions{});
    EXPECT_EQ(tree.pillars + tree.on_part + tree.bridged + tree.unroutable, pts.size());
    // One point of the handle's has a wall within the pillar's margin and none its head meets.
    EXPECT_EQ(tree.unroutable, std::string(name) == "handle" ? 1u : 0u);
    if (std::string(name) == "handle") EXPECT_GT(tree.on_part, 0u);
    expect_feet_on_part(part, tree, SupportTreeOptions{});
    EXPECT_GT(tree.pillars, 0u);
    const std::vector<Mesh> shells = shells_of(tree.mesh);
    for (size_t s = 0; s < shells.size(); ++s) {
      EXPECT_EQ(test::edge_census(shells[s]).bad_edges, 0u);
      EXPECT_GT(test::signed_volume(shells[s]), 0);
    }
    EXPECT_GT(check_sections(part, tree), 0u);
  }
}

// Heads joined to their neighbours' pillars by bridges, and tall pillars linked by zig-zags:
// every bridge's section rests on the layer below and stays out of the part.
// The shared sections check fails where a piece of the supports rests on nothing: a block
// floating 1 mm above the ground beside a pillar is found in the layer where it begins.
TEST(SupportTree, SectionsCheckFindsAPieceRestingOnNothing) {
  SupportTree tree;
  tree.mesh = test::make_box(0, 0, 0, 1, 1, 3);
  test::append_mesh(tree.mesh, test::make_box(3, 0, 1, 4, 1, 2));
  const Mesh part = test::make_box(0, 0, 3, 4, 1, 4);
  const test::TreeSections t = test::check_tree_sections(part, tree, kLayer);
  EXPECT_EQ(t.support_islands, 1u);
  EXPECT_EQ(t.first_support_island_layer, 20u);  // the plane at 1.025 mm
  EXPECT_NEAR(t.first_support_island_xy[0], 3.5, 1e-9);
  EXPECT_NEAR(t.first_support_island_xy[1], 0.5, 1e-9);
}

TEST(SupportTree, BridgesAndLinksLeaveNoIslands) {
  for (const double z : {5.0, 20.0}) {
    SCOPED_TRACE(z);
    const Mesh part = test::make_box(0, 0, z, 12, 4, z + 2);
    // On its bottom face, at x = 1, 3 and 11 (the second bridged to the first, the third too far).
    SupportPoints pts = points_on(part, std::vector<uint32_t>(3, face_near(part, 6, 2, z)));
    for (size_t i = 0; i < 3; ++i) pts.xyz[3 * i] = i == 2 ? 11 : 1 + 2.0 * double(i), pts.xyz[3 * i + 1] = 2;
    const SupportTree tree = build_support_tree(part, pts, -6, SupportTreeOptions{});
    EXPECT_EQ(tree.bridged, 1u);
    EXPECT_EQ(tree.pillars, 2u);
    const size_t links = size_t(std::count_if(tree.structure.bridges.begin(), tree.structure.bridges.end(),
                                              [](const SupportBridge& b) { return b.link; }));
    EXPECT_EQ(links > 0, z == 20.0);
    check_sections(part, tree);
  }
}

// The part stands elevation above the pad's top (PrusaSlicer's support_object_elevation).
TEST(SupportTree, LayersBelow) {
  auto raised = [](double elevation, bool pad = false) {
    SupportTreeOptions o;
    o.object_elevation_mm = elevation;
    o.pad_enable = pad;
    return o;
  };
  EXPECT_EQ(support_layers_below(raised(5), 0.05), 100u);
  EXPECT_EQ(support_layers_below(raised(5, true), 0.05), 120u);  // and the pad's 1 mm
  EXPECT_EQ(support_layers_below(raised(0), 0.05), 0u);
  EXPECT_EQ(support_layers_below(raised(5.02), 0.05), 100u);
  EXPECT_EQ(support_layers_below(raised(5.03), 0.05), 101u);
  EXPECT_DOUBLE_EQ(support_ground_z(1, 0.05, raised(5)), -4);
  EXPECT_DOUBLE_EQ(support_ground_z(1, 0.05, raised(5, true)), -5);
  EXPECT_ERROR(support_layers_below(raised(-1), 0.05), "the object's elevation is -1 mm");
  EXPECT_ERROR(support_layers_below(raised(NAN), 0.05), "the object's elevation is nan mm");
  EXPECT_ERROR(support_layers_below(raised(5), 0), "the layer thickness is 0 mm");
  EXPECT_ERROR(support_layers_below(raised(1e9), 1e-3), "more than 10000000");
}

// The pad's top never reaches the part's first plane: elevation 0 with the pad (the part sunk
// into it, not modelled) is refused in words, and a thin pad under a tiny elevation is not
// rounded up into the part.
TEST(SupportTree, PadTopStaysBelowThePart) {
  SupportTreeOptions o;
  o.pad_wall_thickness_mm = 0.07;
  o.object_elevation_mm = 0;
  EXPECT_ERROR(support_layers_below(o, 0.05),
               "an object elevation of 0 mm with the pad on needs the part sunk into its pad (PrusaSlicer's zero "
               "elevation), which the supports do not model: the pad's top (0.07 mm thick) would lie in the part; "
               "raise the part (an elevation above 0) or turn the pad off");
  o.pad_enable = false;
  EXPECT_EQ(support_layers_below(o, 0.05), 0u);
  o.pad_enable = true;
  for (const double elevation : {0.001, 0.01, 0.02, 0.5}) {
    SCOPED_TRACE(elevation);
    o.object_elevation_mm = elevation;
    EXPECT_LT(support_ground_z(0, 0.05, o) + o.pad_wall_thickness_mm, 0);
  }
}

TEST(SupportTree, BadInputInWords) {
  const Mesh part = test::make_box(0, 0, 0, 4, 4, 2);
  const SupportPoints pts = points_on(part, {face_near(part, 1, 2, 0)});
  EXPECT_ERROR(build_support_tree(part, pts, -0.5, {}), "support point 1 at z = 0 mm is below the pad's top at 0.5 mm");
  SupportTreeOptions no_pad;
  no_pad.pad_enable = false;
  EXPECT_ERROR(build_support_tree(part, pts, 0, no_pad), "support point 1 at z = 0 mm is below the ground at 0 mm");
  SupportTreeOptions low;
  low.max_height_mm = 5;
  EXPECT_ERROR(build_support_tree(part, pts, -5, low),
               "support point 1 needs a pillar of 5.5 mm (from the ground at z = -5 mm to its head's top), taller "
               "than the printer's 5 mm");
  EXPECT_ERROR(build_support_tree(part, pts, NAN, {}), "the supports' ground is at z = nan mm, not a finite height");
  SupportTreeOptions bad;
  bad.head_width_mm = -1;
  EXPECT_ERROR(build_support_tree(part, pts, -5, bad),
               "the support option head_width_mm is -1 mm; it must be a finite, positive number");
  SupportTreeOptions steep;
  steep.pad_wall_slope_deg = 10;
  EXPECT_ERROR(build_support_tree(part, pts, -5, steep), "the pad would have no bottom");
  SupportPoints nan_point = pts;
  nan_point.xyz[2] = NAN;
  EXPECT_ERROR(build_support_tree(part, nan_point, -5, {}), "support point 1 has a position or normal that is not a finite number");
}
