// The support structure as data (support_structure.h), checked piece by piece: heads and feet
// whose tips lie in the part, pillars vertical and clear of it, every pillar on the pad, a foot
// or a bridge, bridges descending at the critical angle and clear of the part, heads joined to
// neighbouring pillars where that saves resin, tall pillars linked, and a mesh with the volume
// of its pieces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "error_of.h"
#include "family.h"
#include "shapes.h"
#include "slicereuse/crossparam/surface_grid.h"
#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/mesh/vec3.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/supports/generate_support_points.h"
#include "slicereuse/supports/support_tree.h"
#include "support_points_on.h"

using namespace slicereuse;

namespace {

constexpr double kLayer = 0.05;

using test::points_on;

// Points on part's bottom face (z = its lowest) at the given (x, y).
SupportPoints points_under(const Mesh& part, const std::vector<std::array<double, 2>>& xy) {
  SupportPoints p = points_on(part, std::vector<uint32_t>(xy.size(), 0));
  const double z = z_range(part).min;
  for (size_t i = 0; i < xy.size(); ++i) {
    p.xyz[3 * i] = xy[i][0], p.xyz[3 * i + 1] = xy[i][1], p.xyz[3 * i + 2] = z;
    p.normal[3 * i] = p.normal[3 * i + 1] = 0, p.normal[3 * i + 2] = -1;
  }
  return p;
}

Mesh joined(Mesh a, const Mesh& b) {
  test::append_mesh(a, b);
  return a;
}

// The generalised winding number of the closed mesh around p: 1 inside, 0 outside.
double winding(const Mesh& m, const Point3& p) {
  double sum = 0;
  for (size_t f = 0; f < m.faces(); ++f) {
    Vec3 v[3];
    for (int j = 0; j < 3; ++j) v[j] = sub(&m.V[3 * size_t(m.F[3 * f + j])], p);
    const double l0 = norm(v[0]), l1 = norm(v[1]), l2 = norm(v[2]);
    const double num = dot(v[0], cross(v[1], v[2]));
    const double den = l0 * l1 * l2 + dot(v[0], v[1]) * l2 + dot(v[1], v[2]) * l0 + dot(v[2], v[0]) * l1;
    sum += 2 * std::atan2(num, den);
  }
  return sum / (4 * M_PI);
}

bool inside(const Mesh& m, const Point3& p) { return winding(m, p) > 0.5; }

double surface_distance(const SurfaceGrid& grid, const Point3& p) {
  return grid.nearest_on_surface(p.data(), nullptr, 0, INFINITY).distance;
}

// A segment of radius r stays clear of the part: every 0.05 mm along it the part's surface lies
// at least r from the axis, and its middle is outside.
void expect_clear(const Mesh& part, const SurfaceGrid& grid, const Point3& a, const Point3& b, double r,
                  const std::string& what) {
  const int n = std::max(1, int(std::ceil(std::sqrt(squared_distance(a, b)) / 0.05)));
  double nearest = INFINITY;
  for (int i = 0; i <= n; ++i) {
    const double t = double(i) / n;
    nearest = std::min(nearest, surface_distance(grid, {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]),
                                                        a[2] + t * (b[2] - a[2])}));
  }
  EXPECT_GE(nearest, r) << what;
  EXPECT_FALSE(inside(part, {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2})) << what;
}

std::string at(const Point3& p) {
  return "(" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " + std::to_string(p[2]) + ")";
}

// Every property of support_structure.h and support_tree.h a structure must have.
void expect_sound(const Mesh& part, const SupportPoints& points, double ground_z, const SupportTreeOptions& o,
                  const SupportStructure& s) {
  const SurfaceGrid grid(part);
  const double floor = ground_z + (o.pad_enable ? o.pad_wall_thickness_mm : 0);
  const double slope = std::tan(o.critical_angle_deg * M_PI / 180);
  // Heads: vertical, the tip inside the part, penetration above the point.
  for (size_t h = 0; h < s.heads.size(); ++h) {
    const SupportHead& head = s.heads[h];
    const SupportCone& c = head.cone;
    const double* p = &points.xyz[3 * head.point];
    SCOPED_TRACE("head " + std::to_string(h) + " at " + at({p[0], p[1], p[2]}));
    EXPECT_EQ(c.tip[0], p[0]);
    EXPECT_EQ(c.tip[1], p[1]);
    EXPECT_EQ(c.back[0], c.tip[0]);
    EXPECT_EQ(c.back[1], c.tip[1]);
    EXPECT_DOUBLE_EQ(c.tip[2], p[2] + head.penetration);
    EXPECT_GT(head.penetration, 0);
    EXPECT_LE(head.penetration, o.head_penetration_mm);
    EXPECT_LT(c.back[2], c.tip[2]);
    EXPECT_TRUE(inside(part, c.tip)) << "the tip at " << at(c.tip) << " is outside the part";
    EXPECT_DOUBLE_EQ(c.r_tip, o.head_front_diameter_mm / 2);
    switch (head.rest) {
      case HeadRest::Pillar:
        ASSERT_LT(head.pillar, s.pillars.size());
        EXPECT_EQ(s.pillars[head.pillar].head, h);
        EXPECT_EQ(s.pillars[head.pillar].z_top, c.back[2]);
        EXPECT_EQ(s.pillars[head.pillar].x, c.back[0]);
        EXPECT_EQ(s.pillars[head.pillar].y, c.back[1]);
        break;
      case HeadRest::Bridge: {
        const size_t bridges = size_t(std::count_if(s.bridges.begin(), s.bridges.end(), [&](const SupportBridge& b) {
          return s.junctions[b.upper].head == h && s.junctions[b.upper].at == c.back;
        }));
        EXPECT_EQ(bridges, 1u) << "a head resting on a bridge starts one";
        break;
      }
      case HeadRest::Part:
        // In the part below (halfway into a thin wall, not out of its underside), or on the pad.
        EXPECT_TRUE(inside(part, c.back) || c.back[2] == floor) << "the back at " << at(c.back);
        EXPECT_LE(surface_distance(grid, c.back), o.head_penetration_mm * (1 + 1e-12)) << "the back at " << at(c.back);
        break;
    }
  }
  // Pillars: from their head's back down, clear of the part, on the ground, a foot or a bridge.
  std::vector<size_t> head_bridges(s.pillars.size(), 0);
  for (const SupportBridge& b : s.bridges)
    if (!b.link) ++head_bridges[s.junctions[b.lower].pillar];
  for (size_t i = 0; i < s.pillars.size(); ++i) {
    const SupportPillar& p = s.pillars[i];
    SCOPED_TRACE("pillar " + std::to_string(i) + " at (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")");
    ASSERT_LT(p.head, s.heads.size());
    EXPECT_EQ(s.heads[p.head].pillar, i);
    EXPECT_LE(p.z_bottom, p.z_top);
    EXPECT_DOUBLE_EQ(p.radius, o.pillar_diameter_mm / 2);
    EXPECT_LE(head_bridges[i], o.max_bridges_on_pillar);
    if (p.z_bottom < p.z_top) expect_clear(part, grid, {p.x, p.y, p.z_bottom}, {p.x, p.y, p.z_top}, p.radius, "pillar");
    switch (p.end) {
      case PillarEnd::Ground:
        EXPECT_EQ(p.z_bottom, floor);
        EXPECT_EQ(p.base_top, std::min(floor + o.base_height_mm, p.z_top));
        EXPECT_DOUBLE_EQ(p.base_radius, o.base_diameter_mm / 2);
        break;
      case PillarEnd::Foot: {
        ASSERT_LT(p.foot, s.feet.size());
        const SupportFoot& f = s.feet[p.foot];
        EXPECT_EQ(f.pillar, i);
        EXPECT_EQ(f.cone.back, (Point3{p.x, p.y, p.z_bottom}));
        EXPECT_LT(f.cone.tip[2], f.cone.back[2]);
        EXPECT_TRUE(inside(part, f.cone.tip)) << "the foot's tip at " << at(f.cone.tip) << " is outside the part";
        const Point3 touch{f.cone.tip[0], f.cone.tip[1], f.cone.tip[2] + f.penetration};
        EXPECT_LT(surface_distance(grid, touch), 1e-6) << "the foot at " << at(touch) << " ends in the air";
        EXPECT_TRUE(f.penetration == o.head_penetration_mm || f.cone.tip[2] == floor);
        break;
      }
      case PillarEnd::Bridge: {
        const size_t starts = size_t(std::count_if(s.bridges.begin(), s.bridges.end(), [&](const SupportBridge& b) {
          return s.junctions[b.upper].pillar == i && s.junctions[b.upper].at == Point3{p.x, p.y, p.z_bottom};
        }));
        EXPECT_EQ(starts, 1u) << "a pillar ending on a bridge starts it at its bottom";
        break;
      }
    }
  }
  // Feet each belong to the pillar that names them.
  for (size_t f = 0; f < s.feet.size(); ++f) EXPECT_EQ(s.pillars[s.feet[f].pillar].foot, f);
  // Junctions on their pillar's axis (within its span) or at their head's back.
  for (const SupportJunction& j : s.junctions) {
    if (j.pillar != kNoPiece) {
      const SupportPillar& p = s.pillars[j.pillar];
      EXPECT_EQ(j.at[0], p.x);
      EXPECT_EQ(j.at[1], p.y);
      EXPECT_GE(j.at[2], p.end == PillarEnd::Ground ? p.base_top : p.z_bottom);
      EXPECT_LE(j.at[2], p.z_top);
    } else {
      ASSERT_LT(j.head, s.heads.size());
      EXPECT_EQ(j.at, s.heads[j.head].cone.back);
    }
  }
  // Bridges descend at least as steeply as the critical angle, no longer than allowed (heads'),
  // clear of the part.
  for (size_t i = 0; i < s.bridges.size(); ++i) {
    const SupportBridge& b = s.bridges[i];
    SCOPED_TRACE("bridge " + std::to_string(i));
    const Point3 u = s.junctions[b.upper].at, l = s.junctions[b.lower].at;
    const double run = std::hypot(u[0] - l[0], u[1] - l[1]);
    EXPECT_GT(run, 0);
    EXPECT_GE(u[2] - l[2], run * slope * (1 - 1e-12));
    if (!b.link) EXPECT_LE(std::sqrt(squared_distance(u, l)), o.max_bridge_length_mm + 1e-12);
    if (b.link) EXPECT_LE(run, o.max_pillar_link_distance_mm);
    expect_clear(part, grid, u, l, b.radius, "bridge from " + at(u) + " to " + at(l));
  }
  // The pad: under every pillar on the ground, its base within the pad's top.
  const bool on_ground = std::any_of(s.pillars.begin(), s.pillars.end(),
                                     [](const SupportPillar& p) { return p.end == PillarEnd::Ground; });
  EXPECT_EQ(!s.pad.top.empty(), o.pad_enable && on_ground);
  if (!s.pad.top.empty()) {
    EXPECT_EQ(s.pad.z_bottom, ground_z);
    EXPECT_EQ(s.pad.z_top, floor);
    EXPECT_EQ(s.pad.bottom.size(), s.pad.top.size());
    for (const SupportPillar& p : s.pillars) {
      if (p.end != PillarEnd::Ground) continue;
      // The base's 16-gon lies within the top outline (convex, counter-clockwise).
      for (int k = 0; k < 16; ++k) {
        const double a = 2 * M_PI * k / 16, x = p.x + p.base_radius * std::cos(a), y = p.y + p.base_radius * std::sin(a);
        for (size_t e = 0; e < s.pad.top.size(); ++e) {
          const auto& c0 = s.pad.top[e];
          const auto& c1 = s.pad.top[(e + 1) % s.pad.top.size()];
          EXPECT_GE((c1[0] - c0[0]) * (y - c0[1]) - (c1[1] - c0[1]) * (x - c0[0]), -1e-9);
        }
      }
    }
  }
}

SupportTreeOptions without_joins() {
  SupportTreeOptions o;
  o.max_bridge_length_mm = 0;
  return o;
}

// A family shape turned by tilt degrees about x, standing on z = 0.
Mesh tilted(const char* shape, double tilt) {
  test::FamilyOptions fo;
  fo.shape = shape;
  fo.faces = 10000;
  fo.height = 8.8;
  Mesh part = test::make_family_base(fo);
  const double c = std::cos(tilt * M_PI / 180), s = std::sin(tilt * M_PI / 180);
  for (size_t v = 0; v < part.vertices(); ++v) {
    const double y = part.V[3 * v + 1], z = part.V[3 * v + 2];
    part.V[3 * v + 1] = c * y - s * z, part.V[3 * v + 2] = s * y + c * z;
  }
  const double z0 = z_range(part).min;
  for (size_t v = 0; v < part.vertices(); ++v) part.V[3 * v + 2] -= z0;
  return part;
}

// The points at 300 % density and a critical angle of 60 degrees: enough of them, close enough,
// that heads join their neighbours' pillars.
SupportPoints generated(const Mesh& part) {
  SliceOptions so;
  so.thickness = kLayer;
  so.z_start = 0;
  SupportPointOptions o;
  o.density_relative = 6;  // points close enough that heads join their neighbours' pillars
  o.critical_angle_deg = 60;
  return generate_support_points(part, slice_layers(part, so), o);
}

// The volume of a loft between two outlines (corners paired): the prismatoid's, exact for it.
double loft_volume(const std::vector<std::array<double, 2>>& bottom, const std::vector<std::array<double, 2>>& top,
                   double height) {
  auto area = [](const std::vector<std::array<double, 2>>& o) {
    double a = 0;
    for (size_t i = 0; i < o.size(); ++i) {
      const auto& p = o[i];
      const auto& q = o[(i + 1) % o.size()];
      a += p[0] * q[1] - p[1] * q[0];
    }
    return a / 2;
  };
  std::vector<std::array<double, 2>> mid(bottom.size());
  for (size_t i = 0; i < bottom.size(); ++i) mid[i] = {(bottom[i][0] + top[i][0]) / 2, (bottom[i][1] + top[i][1]) / 2};
  return height / 6 * (area(bottom) + 4 * area(mid) + area(top));
}

}  // namespace

TEST(SupportStructure, GeneratedSupportsOnTiltedShapesAreSound) {
  for (const char* name : {"ear", "sphere", "handle"}) {
    SCOPED_TRACE(name);
    const Mesh part = tilted(name, std::string(name) == "ear" ? 60 : 30);
    const SupportPoints pts = generated(part);
    ASSERT_GT(pts.size(), 5u);
    const SupportTreeOptions o;
    const double ground_z = support_ground_z(0, kLayer, o);
    const SupportTree tree = build_support_tree(part, pts, ground_z, o);
    expect_sound(part, pts, ground_z, o, tree.structure);
    EXPECT_EQ(tree.pillars + tree.on_part + tree.bridged + tree.up_facing + tree.unroutable, pts.size());
    EXPECT_EQ(tree.structure.heads.size() + tree.up_facing + tree.unroutable, pts.size());
  }
}

// A pillar whose axis passes beside a block (0.4 mm out) but whose rim meets it: the foot's tip
// lies in the block, under where the rim met it (issue #35, item 2).
TEST(SupportStructure, FootUnderABlockedRimEndsInThePart) {
  const Mesh part = joined(test::make_box(0, 0, 0, 10, 10, 2), test::make_box(0, 0, 8, 20, 10, 10));
  SupportPoints pts = points_on(part, {0});
  pts.xyz[0] = 10.4, pts.xyz[1] = 5, pts.xyz[2] = 8;
  pts.normal[0] = pts.normal[1] = 0, pts.normal[2] = -1;
  const SupportTreeOptions o;
  const SupportStructure s = build_support_structure(part, pts, -5, o);
  ASSERT_EQ(s.feet.size(), 1u);
  EXPECT_EQ(s.feet[0].cone.tip[2], 2 - o.head_penetration_mm);
  EXPECT_LT(s.feet[0].cone.tip[0], 10);
  expect_sound(part, pts, -5, o, s);
}

// Two points 2 mm apart under a box 10 mm up: the second (in order of height, then of points)
// joins the first's pillar by a bridge at 45 degrees from its head's back, which takes less resin
// than its own pillar and base.
TEST(SupportStructure, AHeadJoinsItsNeighboursPillarByABridge) {
  const Mesh part = test::make_box(0, 0, 10, 10, 4, 12);
  const SupportPoints pts = points_under(part, {{3, 2}, {5, 2}});
  const SupportTreeOptions o;
  const SupportTree tree = build_support_tree(part, pts, -6, o);
  const SupportStructure& s = tree.structure;
  expect_sound(part, pts, -6, o, s);
  EXPECT_EQ(tree.pillars, 1u);
  EXPECT_EQ(tree.bridged, 1u);
  ASSERT_EQ(s.pillars.size(), 1u);
  ASSERT_EQ(s.bridges.size(), 1u);
  EXPECT_EQ(s.heads[1].rest, HeadRest::Bridge);
  const SupportJunction& u = s.junctions[s.bridges[0].upper];
  const SupportJunction& l = s.junctions[s.bridges[0].lower];
  EXPECT_EQ(u.at, (Point3{5, 2, 7}));
  EXPECT_EQ(l.at[0], 3);
  EXPECT_DOUBLE_EQ(l.at[2], 5);
  EXPECT_EQ(l.pillar, 0u);
  const SupportTree apart = build_support_tree(part, pts, -6, without_joins());
  EXPECT_EQ(apart.pillars, 2u);
  EXPECT_LT(test::signed_volume(tree.mesh), test::signed_volume(apart.mesh) - 3);
}

// A head higher than its neighbour's pillar's top by more than the bridge drops: its own pillar
// down to where a 45 degree bridge reaches the neighbour's head's back.
TEST(SupportStructure, AHigherHeadComesDownOnAPillarOfItsOwnToItsBridge) {
  const Mesh part = joined(test::make_box(0, 0, 5, 4, 4, 6), test::make_box(4, 0, 12, 8, 4, 13));
  SupportPoints both = points_under(part, {{2, 2}, {6, 2}});
  both.xyz[5] = 12;  // the second on the upper box
  const SupportTreeOptions o;
  const SupportStructure s = build_support_structure(part, both, -6, o);
  expect_sound(part, both, -6, o, s);
  ASSERT_EQ(s.pillars.size(), 2u);
  EXPECT_EQ(s.pillars[0].end, PillarEnd::Ground);
  EXPECT_EQ(s.pillars[1].end, PillarEnd::Bridge);
  EXPECT_EQ(s.pillars[1].z_top, 9);
  EXPECT_DOUBLE_EQ(s.pillars[1].z_bottom, 2 + 4);  // the lower head's back, plus the 4 mm run
  ASSERT_EQ(s.bridges.size(), 1u);
  EXPECT_DOUBLE_EQ(s.junctions[s.bridges[0].lower].at[2], 2);
}

// A fin (its own block, below the slab) between two heads blocks the bridge that would join them: each gets its pillar.
TEST(SupportStructure, NoBridgeThroughThePart) {
  const Mesh slab = test::make_box(0, 0, 10, 10, 4, 12);
  const Mesh part = joined(slab, test::make_box(4.8, 0, 4, 5.2, 4, 9));
  const SupportPoints pts = points_under(slab, {{3, 2}, {7, 2}});
  SupportPoints on_part = pts;
  on_part.fingerprint = mesh_fingerprint(part);
  const SupportTreeOptions o;
  const SupportStructure s = build_support_structure(part, on_part, -6, o);
  expect_sound(part, on_part, -6, o, s);
  EXPECT_TRUE(s.bridges.empty());
  EXPECT_EQ(s.pillars.size(), 2u);
  const SupportStructure open = build_support_structure(slab, pts, -6, o);
  EXPECT_EQ(open.bridges.size(), 1u);
}

// Pillars taller than 15 mm, 8 mm apart (too far for a head's bridge of at most 10 mm at 45
// degrees), are linked by bridges zig-zagging down between them at 45 degrees; short ones not.
TEST(SupportStructure, TallPillarsAreLinkedShortOnesNot) {
  const Mesh part = test::make_box(0, 0, 20, 10, 4, 22);
  const SupportPoints pts = points_under(part, {{1, 2}, {9, 2}});
  const SupportTreeOptions o;
  const SupportStructure s = build_support_structure(part, pts, -6, o);
  expect_sound(part, pts, -6, o, s);
  ASSERT_EQ(s.pillars.size(), 2u);
  // From 17 (the heads' backs) down by 8 mm at a time while above the bases' tops at -4.
  ASSERT_EQ(s.bridges.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_TRUE(s.bridges[i].link);
    EXPECT_EQ(s.junctions[s.bridges[i].upper].pillar, i);
    EXPECT_EQ(s.junctions[s.bridges[i].lower].pillar, 1 - i);
    EXPECT_DOUBLE_EQ(s.junctions[s.bridges[i].upper].at[2], 17 - 8.0 * double(i));
  }
  EXPECT_EQ(s.bridges[1].upper, s.bridges[0].lower);  // the zig-zag turns on the pillar
  const Mesh low = test::make_box(0, 0, 5, 10, 4, 7);
  const SupportStructure short_pillars = build_support_structure(low, points_under(low, {{1, 2}, {9, 2}}), -6, o);
  EXPECT_TRUE(short_pillars.bridges.empty());
}

// The mesh has the volume of the structure's pieces: each cone, cylinder and bridge a 16-gon
// prism or frustum (its circle's area times 8 sin(pi / 8) / pi), the pad its outlines' loft.
TEST(SupportStructure, MeshHasTheVolumeOfItsPieces) {
  const Mesh part = tilted("ear", 60);
  const SupportPoints pts = generated(part);
  const SupportTreeOptions o;
  const SupportStructure s = build_support_structure(part, pts, support_ground_z(0, kLayer, o), o);
  ASSERT_FALSE(s.bridges.empty());
  auto cone = [](double r0, double r1, double h) { return M_PI * h * (r0 * r0 + r0 * r1 + r1 * r1) / 3; };
  double round = 0;  // the pieces' volumes with true circles
  for (const SupportHead& h : s.heads) round += cone(h.cone.r_back, h.cone.r_tip, h.cone.tip[2] - h.cone.back[2]);
  for (const SupportFoot& f : s.feet) round += cone(f.cone.r_tip, f.cone.r_back, f.cone.back[2] - f.cone.tip[2]);
  for (const SupportPillar& p : s.pillars) {
    const double base = p.end == PillarEnd::Ground ? p.base_top : p.z_bottom;
    if (base > p.z_bottom) round += cone(p.base_radius, p.radius, base - p.z_bottom);
    round += M_PI * p.radius * p.radius * (p.z_top - base);
  }
  for (const SupportBridge& b : s.bridges)
    round += M_PI * b.radius * b.radius * std::sqrt(squared_distance(s.junctions[b.upper].at, s.junctions[b.lower].at));
  ASSERT_FALSE(s.pad.top.empty());
  const double pad = loft_volume(s.pad.bottom, s.pad.top, s.pad.z_top - s.pad.z_bottom);
  const double polygon = 8 * std::sin(M_PI / 8) / M_PI;
  const double mesh = test::signed_volume(mesh_support_structure(s));
  EXPECT_NEAR(mesh, round * polygon + pad, 1e-9 * mesh);
}

// The same points give the same structure and mesh, byte for byte.
TEST(SupportStructure, SamePointsSameMesh) {
  const Mesh part = tilted("ear", 60);
  const SupportPoints pts = generated(part);
  const SupportTree a = build_support_tree(part, pts, -6, SupportTreeOptions{});
  const SupportTree b = build_support_tree(part, pts, -6, SupportTreeOptions{});
  EXPECT_EQ(a.mesh.V, b.mesh.V);
  EXPECT_EQ(a.mesh.F, b.mesh.F);
}

// Joining heads to their neighbours' pillars takes less resin on a hearing-aid shell.
TEST(SupportStructure, JoiningHeadsSavesResinOnAnEarShell) {
  const Mesh part = tilted("ear", 60);
  const SupportPoints pts = generated(part);
  const SupportTree joined_tree = build_support_tree(part, pts, -6, SupportTreeOptions{});
  const SupportTree apart = build_support_tree(part, pts, -6, without_joins());
  EXPECT_GT(joined_tree.bridged, 0u);
  EXPECT_EQ(apart.bridged, 0u);
  EXPECT_LT(test::signed_volume(joined_tree.mesh), test::signed_volume(apart.mesh));
}

TEST(SupportStructure, BridgeOptionsInWords) {
  const Mesh part = test::make_box(0, 0, 10, 10, 4, 12);
  const SupportPoints pts = points_under(part, {{3, 2}});
  SupportTreeOptions flat;
  flat.critical_angle_deg = 90;
  EXPECT_ERROR(build_support_structure(part, pts, -6, flat),
               "the supports' critical angle is 90 degrees; it must be more than 0 and less than 90");
  SupportTreeOptions negative;
  negative.max_bridge_length_mm = -1;
  EXPECT_ERROR(build_support_structure(part, pts, -6, negative),
               "the support option max_bridge_length_mm is -1 mm; it must be a finite, non-negative number");
}
