// Support points on family parts (sphere, handle, and box: its raised flat bottom is one wide
// island, where the lattice's cover margin shows): every island and far area of every layer is
// covered within the head reach by points of its layer, and every overhang within the support
// radius, in space, by points at or below it, checked on regions computed here with Clipper; the points
// lie on the mesh; the result does not depend on the thread count; transfer keeps, adds, moves
// and drops as its header says; bad input is refused in words; located positions round-trip.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "error_of.h"
#include "family.h"
#include "shapes.h"
#include "slicereuse/crossparam/surface_grid.h"
#include "slicereuse/crossparam/surface_map.h"
#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/supports/generate_support_points.h"
#include "slicereuse/supports/locate_support_points.h"
#include "slicereuse/supports/member_supports.h"
#include "slicereuse/supports/support_keep_out.h"
#include "slicereuse/supports/transfer_support_points.h"

using namespace slicereuse;

namespace {

test::FamilyOptions family_options(const std::string& shape) {
  test::FamilyOptions o;
  o.shape = shape;
  o.faces = 8000;
  o.height = 10;
  o.seed = 3;
  o.z_change = test::ZChange::Everywhere;
  return o;
}

Slices slice(const Mesh& m) {
  SliceOptions o;
  o.thickness = 0.05;
  return slice_layers(m, o);
}

// The parts of layer k's region (outer loop with holes) that rest on layer k-1 with less than
// half their area, and the region minus layer k-1's grown by the larger of the self-supporting
// and the flat distance (overhang) and by the far reach (far): written here from the header's
// words, not from the library's code.
struct Needs {
  std::vector<ClipperLib::Paths> islands;
  ClipperLib::Paths overhang, far;
};

ClipperLib::Paths minus_grown(const ClipperLib::Paths& region, const ClipperLib::Paths& below, double mm) {
  ClipperLib::ClipperOffset grow;
  grow.ArcTolerance = 100;  // 0.1 um: finer than the library's, so the area checked is no smaller
  grow.AddPaths(below, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  ClipperLib::Paths grown, out;
  grow.Execute(grown, mm * kRegionScale);
  ClipperLib::Clipper d;
  d.AddPaths(region, ClipperLib::ptSubject, true);
  d.AddPaths(grown, ClipperLib::ptClip, true);
  d.Execute(ClipperLib::ctDifference, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return out;
}

Needs needs_of(const Slices& s, size_t k, const SupportPointOptions& o) {
  Needs n;
  const ClipperLib::Paths region = layer_region(LayerView(s, k));
  ClipperLib::Clipper c;
  c.AddPaths(region, ClipperLib::ptSubject, true);
  ClipperLib::PolyTree tree;
  c.Execute(ClipperLib::ctUnion, tree);
  ClipperLib::Paths below;
  if (k) below = layer_region(LayerView(s, k - 1));
  for (ClipperLib::PolyNode* node = tree.GetFirst(); node; node = node->GetNext()) {
    if (node->IsHole()) continue;
    ClipperLib::Paths part{node->Contour};
    for (const ClipperLib::PolyNode* hole : node->Childs) part.push_back(hole->Contour);
    if (k == 0) {
      if (o.raised) n.islands.push_back(part);
      continue;
    }
    ClipperLib::Clipper i;
    i.AddPaths(part, ClipperLib::ptSubject, true);
    i.AddPaths(below, ClipperLib::ptClip, true);
    ClipperLib::Paths common;
    i.Execute(ClipperLib::ctIntersection, common, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    if (region_area_mm2(common) < 0.5 * region_area_mm2(part)) n.islands.push_back(part);
  }
  if (k) {
    // Flatter than 15 degrees (or than the critical angle): the slopes between are held by
    // force, not covered.
    const double flat = s.thickness * std::tan(75 * M_PI / 180);
    n.overhang = minus_grown(region, below, std::max(o.self_supporting_mm(s.thickness), flat));
    n.far = minus_grown(region, below, o.far_reach_mm);
  }
  return n;
}

bool inside(const ClipperLib::Paths& region, double x, double y) {
  const ClipperLib::IntPoint p(region_units(x), region_units(y));
  int winding = 0;
  for (const ClipperLib::Path& loop : region) {
    const int in = ClipperLib::PointInPolygon(p, loop);
    if (in == -1) return true;
    if (in) winding += ClipperLib::Orientation(loop) ? 1 : -1;
  }
  return winding != 0;
}

// The sample points of an area: its vertices and a 0.1 mm grid inside it.
std::vector<std::array<double, 2>> samples(const ClipperLib::Paths& area) {
  std::vector<std::array<double, 2>> out;
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const ClipperLib::Path& loop : area)
    for (const ClipperLib::IntPoint& p : loop) {
      const double q[2] = {double(p.X) / kRegionScale, double(p.Y) / kRegionScale};
      out.push_back({q[0], q[1]});
      for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], q[a]), hi[a] = std::max(hi[a], q[a]);
    }
  for (double x = std::floor(lo[0] * 10) / 10; x <= hi[0]; x += 0.1)
    for (double y = std::floor(lo[1] * 10) / 10; y <= hi[1]; y += 0.1)
      if (inside(area, x, y)) out.push_back({x, y});
  return out;
}

// Every island holds a point of its layer (boundary included), every sample of every island
// and far area lies within the head reach of a point of its layer, and every sample of an
// overhang within that (or the support radius, when smaller) of one of its layer or within the
// support radius, in space, of a point at or below it (a point's height: its layer's plane).
// Returns the number of overhang samples checked.
size_t expect_covered(const Slices& s, const SupportPoints& points, const SupportPointOptions& o, const char* what) {
  std::map<size_t, std::vector<std::array<double, 2>>> by_layer;
  for (size_t i = 0; i < points.size(); ++i) by_layer[points.layer[i]].push_back({points.xyz[3 * i], points.xyz[3 * i + 1]});
  const double head = o.point_reach_mm() + 1e-9, support = o.support_radius_mm() + 1e-9;
  // An overhang's point holds the surface within the support radius only, however near a head.
  const double own = std::min(head, support);
  size_t islands = 0, uncovered = 0, without_point = 0, overhang_samples = 0;
  for (size_t k = 0; k < s.layers(); ++k) {
    const Needs n = needs_of(s, k, o);
    const std::vector<std::array<double, 2>>& layer = by_layer[k];
    auto near = [&](const std::array<double, 2>& q, double reach) {
      return std::any_of(layer.begin(), layer.end(),
                         [&](const std::array<double, 2>& p) { return std::hypot(p[0] - q[0], p[1] - q[1]) <= reach; });
    };
    auto held = [&](const std::array<double, 2>& q) {
      for (const auto& [j, pts] : by_layer) {
        const double dz = s.layer_z[k] - s.layer_z[j];
        if (j > k || dz > support) continue;
        for (const std::array<double, 2>& p : pts)
          if (std::hypot(p[0] - q[0], p[1] - q[1], dz) <= support) return true;
      }
      return false;
    };
    for (const ClipperLib::Paths& island : n.islands) {
      ++islands;
      if (std::none_of(layer.begin(), layer.end(), [&](const std::array<double, 2>& p) { return inside(island, p[0], p[1]); }))
        ++without_point;
      for (const std::array<double, 2>& q : samples(island)) uncovered += !near(q, head);
    }
    for (const std::array<double, 2>& q : samples(n.far)) uncovered += !near(q, head);
    for (const std::array<double, 2>& q : samples(n.overhang)) {
      ++overhang_samples;
      uncovered += !near(q, own) && !held(q);
    }
  }
  EXPECT_GT(islands, 0u) << what;
  EXPECT_EQ(without_point, 0u) << what;
  EXPECT_EQ(uncovered, 0u) << what;
  return overhang_samples;
}

// Valid, on the mesh, each on a downward-facing face or a face its layer's plane crosses, none
// on a surface facing up.
void expect_on_mesh(const Mesh& m, const Slices& s, const SupportPoints& points) {
  validate_support_points(points, &m);
  const SurfaceGrid grid(m);
  size_t off = 0, wrong_face = 0, contour = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const SurfacePoint q = grid.nearest_on_surface(&points.xyz[3 * i], nullptr, 0, INFINITY);
    off += q.distance > 1e-9;
    const uint32_t* f = &m.F[3 * size_t(points.face[i])];
    double zlo = INFINITY, zhi = -INFINITY;
    for (int j = 0; j < 3; ++j) zlo = std::min(zlo, m.V[3 * size_t(f[j]) + 2]), zhi = std::max(zhi, m.V[3 * size_t(f[j]) + 2]);
    const double plane = s.layer_z[points.layer[i]];
    if (points.normal[3 * i + 2] < 0) continue;
    ++contour;
    wrong_face += !(zlo < plane && plane <= zhi);
  }
  EXPECT_EQ(off, 0u);
  EXPECT_EQ(wrong_face, 0u);
  size_t up = 0;
  for (size_t i = 0; i < points.size(); ++i) up += faces_up(points, i);
  EXPECT_EQ(up, 0u) << "points whose surface faces up";
  std::cout << "[ support  ] " << contour << " of " << points.size() << " points on contour faces\n";
}

// PrusaSlicer's defaults: critical angle 45 degrees, density 100 %.
SupportPointOptions options() { return {}; }

struct Part {
  test::FamilyOptions options;
  Mesh mesh;
  Slices slicing;
  SupportPoints points;
};

Part part(const std::string& shape, const SupportPointOptions& o = options()) {
  Part p;
  p.options = family_options(shape);
  p.mesh = test::make_family_base(p.options);
  p.slicing = slice(p.mesh);
  p.points = generate_support_points(p.mesh, p.slicing, o);
  size_t islands = 0;
  for (uint8_t k : p.points.kind) islands += k == uint8_t(SupportKind::Island);
  std::cout << "[ support  ] " << shape << ", " << p.mesh.faces() << " faces, " << p.slicing.layers()
            << " layers: " << p.points.size() << " points (" << islands << " island)\n";
  return p;
}

class SupportPointsOn : public ::testing::TestWithParam<std::string> {};

TEST_P(SupportPointsOn, CoverIslandsAndOverhangsAndLieOnTheMesh) {
  const SupportPointOptions o = options();
  const Part p = part(GetParam(), o);
  EXPECT_EQ(p.points.fingerprint, mesh_fingerprint(p.mesh));
  const size_t overhang_samples = expect_covered(p.slicing, p.points, o, "source");
  // The box has none: its walls are vertical and its bottom one island.
  if (GetParam() != "box") EXPECT_GT(overhang_samples, 0u);
  expect_on_mesh(p.mesh, p.slicing, p.points);
  for (size_t i = 1; i < p.points.size(); ++i) EXPECT_LE(p.points.layer[i - 1], p.points.layer[i]);
}

TEST_P(SupportPointsOn, DoNotDependOnTheThreadCount) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const Part one = part(GetParam());
  omp_set_num_threads(2);
  const Part two = part(GetParam());
  omp_set_num_threads(threads);
  EXPECT_EQ(one.points.face, two.points.face);
  EXPECT_EQ(one.points.bary, two.points.bary);
  EXPECT_EQ(one.points.kind, two.points.kind);
  EXPECT_EQ(one.points.layer, two.points.layer);
}

TEST_P(SupportPointsOn, TransferOntoTheSourceKeepsThemAll) {
  const Part p = part(GetParam());
  SupportTransferStats stats;
  const SupportPoints out = transfer_support_points(p.points, p.mesh, p.slicing, options(), &stats);
  EXPECT_EQ(stats.transferred, p.points.size());
  EXPECT_EQ(stats.kept, p.points.size());
  EXPECT_EQ(stats.added + stats.moved + stats.dropped, 0u);
  EXPECT_EQ(out.face, p.points.face);
  EXPECT_EQ(out.bary, p.points.bary);
  EXPECT_EQ(out.layer, p.points.layer);
}

TEST_P(SupportPointsOn, TransferOntoMembersCoversTheirOwnNeeds) {
  const SupportPointOptions o = options();
  const Part p = part(GetParam(), o);
  for (int index = 1; index <= 3; ++index) {
    const Mesh member = test::make_family_member(p.mesh, p.options, index);
    const Slices slicing = slice(member);
    SupportTransferStats stats;
    const SupportPoints out = transfer_support_points(p.points, member, slicing, o, &stats);
    std::cout << "[ support  ] member " << index << ": " << stats.kept << " kept, " << stats.moved << " moved, "
              << stats.added << " added, " << stats.dropped << " dropped of " << stats.transferred << "\n";
    EXPECT_EQ(stats.transferred, p.points.size());
    EXPECT_EQ(stats.kept + stats.moved + stats.dropped, stats.transferred);
    EXPECT_EQ(out.size(), stats.kept + stats.moved + stats.added);
    EXPECT_GT(stats.kept, 0u);
    expect_covered(slicing, out, o, ("member " + std::to_string(index)).c_str());
    validate_support_points(out, &member);
  }
}

TEST_P(SupportPointsOn, LocatingTheirPositionsGivesThemBack) {
  const Part p = part(GetParam());
  const SupportPoints located = locate_support_points(p.mesh, p.points.xyz, p.points.kind);
  ASSERT_EQ(located.size(), p.points.size());
  validate_support_points(located, &p.mesh);
  EXPECT_EQ(located.kind, p.points.kind);
  for (size_t i = 0; i < p.points.xyz.size(); ++i) EXPECT_NEAR(located.xyz[i], p.points.xyz[i], 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Shapes, SupportPointsOn, ::testing::Values("sphere", "handle", "box"));

// Another connectivity: every face's corners rotated, and a map that takes each vertex to
// itself; the points carried through it land where they were.
TEST(SupportPoints, TransferThroughAMapCarriesThePositions) {
  const Part p = part("sphere");
  Mesh rotated = p.mesh;
  for (size_t f = 0; f < rotated.faces(); ++f) std::rotate(&rotated.F[3 * f], &rotated.F[3 * f + 1], &rotated.F[3 * f + 3]);
  SurfaceMap map;
  map.source = mesh_fingerprint(p.mesh);
  map.target = mesh_fingerprint(rotated);
  map.source_vertices = map.target_vertices = p.mesh.vertices();
  map.source_faces = p.mesh.F;
  map.face.assign(p.mesh.vertices(), 0);
  map.bary.assign(3 * p.mesh.vertices(), 0);
  for (size_t f = 0; f < rotated.faces(); ++f)
    for (int j = 0; j < 3; ++j) {
      const uint32_t v = rotated.F[3 * f + j];
      map.face[v] = uint32_t(f);
      std::fill(&map.bary[3 * size_t(v)], &map.bary[3 * size_t(v) + 3], 0.0);
      map.bary[3 * size_t(v) + j] = 1;
    }
  validate_surface_map(map);
  const Slices slicing = slice(rotated);
  SupportTransferStats stats;
  const SupportPoints out = transfer_support_points(p.points, rotated, slicing, options(), &stats, &map);
  EXPECT_EQ(stats.kept, p.points.size());
  EXPECT_EQ(stats.added + stats.moved + stats.dropped, 0u);
  ASSERT_EQ(out.size(), p.points.size());
  for (size_t i = 0; i < out.xyz.size(); ++i) EXPECT_NEAR(out.xyz[i], p.points.xyz[i], 1e-9);
  EXPECT_ERROR(transfer_support_points(p.points, rotated, slicing, {}), "and no map between them was given");
}

TEST(SupportPoints, RefuseSlicingsOfOtherMeshesTooManyPointsAndBadPositions) {
  const Part p = part("sphere");
  const Mesh other = test::make_family_base(family_options("handle"));
  EXPECT_ERROR(generate_support_points(other, p.slicing, {}),
               "the slicing is of a mesh of " + describe_fingerprint(p.slicing.fingerprint) + ", this one has " +
                   describe_fingerprint(mesh_fingerprint(other)));
  SupportPointOptions few = options();
  few.max_points = p.points.size() - 1;
  EXPECT_EQ(test::error_of([&] { generate_support_points(p.mesh, p.slicing, few); }),
            "the part needs " + std::to_string(p.points.size()) + " support points, more than the limit of " +
                std::to_string(few.max_points));
  SupportPointOptions headless = options();
  headless.head_front_diameter_mm = -3;
  EXPECT_ERROR(generate_support_points(p.mesh, p.slicing, headless),
               "the heads' front diameter must be a number of mm that leaves a point some reach, not -3 mm");
  Slices bare = p.slicing;
  bare.face.clear();
  EXPECT_ERROR(generate_support_points(p.mesh, bare, {}), "support points need the slicing's encoding");
  bare = p.slicing;
  bare.xyz.clear();
  EXPECT_ERROR(generate_support_points(p.mesh, bare, {}), "support points need the slicing's contour points");
  EXPECT_ERROR(locate_support_points(p.mesh, {0, 0}), "3 numbers a point; 2 is not a multiple of 3");
  EXPECT_ERROR(locate_support_points(p.mesh, {0, 0, 0}, {7}), "support point 1 has kind 7");
}

}  // namespace

// A 2.5 mm ledge (a slab over a narrower column): wider than the masks' rule at every critical
// angle, so it gets points at every one, even where it does not overhang (at 1 degree the
// self-supporting distance, 0.05 / tan(1 degree) = 2.86 mm, exceeds it), and its far area is
// covered within the head reach.
TEST(SupportPoints, WideLedgeGetsPointsAtEveryCriticalAngle) {
  Mesh ledge = test::make_box(0, 0, 0, 5, 5, 4);
  const Mesh slab = test::make_box(0, 0, 3, 7.5, 5, 5);
  test::append_mesh(ledge, slab);
  const Slices s = slice(ledge);
  for (const double angle : {1.0, 5.0, 20.0, 45.0, 70.0, 89.0}) {
    SCOPED_TRACE(angle);
    SupportPointOptions o = options();
    o.critical_angle_deg = angle;
    const SupportPoints pts = generate_support_points(ledge, s, o);
    size_t on_ledge = 0;
    for (size_t i = 0; i < pts.size(); ++i) on_ledge += pts.xyz[3 * i + 2] > 2.9 && pts.xyz[3 * i] > 5;
    std::cout << "[ support  ] ledge at " << angle << " degrees: " << on_ledge << " points on it\n";
    EXPECT_GT(on_ledge, 0u);
    expect_covered(s, pts, o, "ledge");
  }
}

// A column raised off the plate and leaning 30 degrees from the vertical, at a critical angle
// of 70 degrees: every layer above the first overhangs on a slope (0.029 mm a layer, beyond
// the 0.018 mm it holds itself, short of the flat 0.187 mm), and its base's points hold its 16
// mm2 many times over, so the slope gets none.
TEST(SupportPoints, ALeaningColumnHeldAtItsBaseGetsNoPointsOnItsSlope) {
  Mesh column = test::make_box(0, 0, 0, 4, 4, 5, 4);
  for (size_t v = 0; v < column.vertices(); ++v) column.V[3 * v] += column.V[3 * v + 2] * std::tan(M_PI / 6);
  const Slices s = slice(column);
  SupportPointOptions o = options();
  o.critical_angle_deg = 70;
  const SupportPoints pts = generate_support_points(column, s, o);
  size_t above = 0;
  for (size_t i = 0; i < pts.size(); ++i) above += pts.layer[i] > 0;
  std::cout << "[ support  ] leaning column: " << pts.size() << " points, " << above << " above its base\n";
  EXPECT_GT(pts.size(), 2u);
  EXPECT_EQ(above, 0u);
  expect_covered(s, pts, o, "leaning column");
}

// A cone widening 45 degrees from a 0.5 mm foot to 5 mm at 4.5 mm, at a critical angle of 60
// degrees: its foot's point holds 10 mm2, so as its sections outgrow what its points hold the
// slope gets one more, up to its 78.5 mm2 top: 8 points (the foot's, then one on each of 7
// layers), or 9 or 10 should a layer's shortfall ask for two.
TEST(SupportPoints, AWideningConeGetsPointsAsItsAreaOutgrowsThem) {
  const int segments = 96;
  Mesh cone;
  cone.V = {0, 0, 0};
  for (const double r : {0.5, 5.0})
    for (int i = 0; i < segments; ++i) {
      const double a = 2 * M_PI * i / segments, z = r == 0.5 ? 0 : 4.5;
      cone.V.insert(cone.V.end(), {r * std::cos(a), r * std::sin(a), z});
    }
  cone.V.insert(cone.V.end(), {0, 0, 4.5});
  cone.F = test::pole_grid_faces(3, segments);
  test::orient_outward(cone);
  const Slices s = slice(cone);
  SupportPointOptions o = options();
  o.critical_angle_deg = 60;
  const SupportPoints pts = generate_support_points(cone, s, o);
  std::map<uint32_t, size_t> layers;
  for (size_t i = 0; i < pts.size(); ++i) ++layers[pts.layer[i]];
  std::cout << "[ support  ] widening cone: " << pts.size() << " points on " << layers.size() << " layers\n";
  EXPECT_GE(pts.size(), 8u);
  EXPECT_LE(pts.size(), 10u);
  EXPECT_GE(layers.size(), 7u);
  expect_covered(s, pts, o, "widening cone");
}

// The raised flat bottom of a 10 x 8 mm box is covered (every point of it within the point reach
// of a point) by at most 2.5 times the points of a hexagonal cover of its 80 mm2 at that reach
// (the densest cover of open ground; its edges ask more): 42 against 21.4 here. Taking each
// candidate not yet held, as the cover did before, took 179 points at its reach of 1 mm, 5.8
// times its hexagonal cover's.
TEST(SupportPoints, AFlatBottomIsCoveredByFewPoints) {
  const Mesh box = test::make_box(0, 0, 1, 10, 8, 3);
  SliceOptions so;
  so.thickness = 0.05;
  so.z_start = 1;
  const Slices s = slice_layers(box, so);
  const SupportPointOptions o = options();
  const SupportPoints pts = generate_support_points(box, s, o);
  const double reach = o.point_reach_mm(), hexagonal = 80 / (1.5 * std::sqrt(3.0) * reach * reach);
  std::cout << "[ support  ] flat bottom: " << pts.size() << " points, a hexagonal cover " << hexagonal << "\n";
  EXPECT_LE(double(pts.size()), 2.5 * hexagonal);
  EXPECT_GT(double(pts.size()), hexagonal);
  expect_covered(s, pts, o, "flat bottom");
}

// Densities past 1840 %, where the support radius (0.42 mm there) falls below the lattice's
// cover margin for the head reach: every overhang is still held within the support radius.
TEST(SupportPoints, HighDensitiesHoldOverhangsWithinTheirRadius) {
  size_t previous = 0;
  for (const double density : {1.0, 20.0, 50.0}) {
    SCOPED_TRACE(density);
    SupportPointOptions o = options();
    o.density_relative = density;
    const Part p = part("sphere", o);
    expect_covered(p.slicing, p.points, o, "dense");
    EXPECT_GT(p.points.size(), previous);
    previous = p.points.size();
  }
}

// A user's point is moved onto the surface from within the cap only: beyond it, refused in
// words naming the point and its distance.
TEST(SupportPoints, LocatingRefusesPointsFartherThanTheCap) {
  const Mesh box = test::make_box(0, 0, 0, 4, 4, 2);
  const SupportPoints near = locate_support_points(box, {1, 2, -0.5, 2, 2, 0.5}, {}, kUserPointReachMm);
  ASSERT_EQ(near.size(), 2u);
  EXPECT_EQ(near.xyz, (std::vector<double>{1, 2, 0, 2, 2, 0}));
  EXPECT_ERROR(locate_support_points(box, {1, 2, -0.5, 2, 2, -2.5}, {}, kUserPointReachMm),
               "support point 2 at (2, 2, -2.5) mm is 2.5 mm from the mesh's surface, farther than the 1 mm a point "
               "may be moved onto it: the points are not this mesh's, or were moved off it");
}

// A box raised off the plate whose walls lean out by 1e-7 mm over its 2 mm (a mesh's rounding):
// its first layer's contour lies a hair outside the bottom face, on the walls' slivers, and
// the rays from below must still find the bottom face, not the walls (within 30 degrees of
// straight down, the only surface here that needs support).
TEST(SupportPoints, BottomPointsStayOffNearlyVerticalWalls) {
  Mesh box = test::make_box(0, 0, 0, 4, 4, 2);
  for (size_t v = 0; v < box.vertices(); ++v)
    if (box.V[3 * v + 2] == 2)
      for (int a = 0; a < 2; ++a) box.V[3 * v + a] += box.V[3 * v + a] == 0 ? -1e-7 : 1e-7;
  const Slices s = slice(box);
  const SupportPoints pts = generate_support_points(box, s, options());
  size_t on_walls = 0;
  for (size_t i = 0; i < pts.size(); ++i) on_walls += !(pts.normal[3 * i + 2] < -std::cos(M_PI / 6));
  std::cout << "[ support  ] leaning box: " << on_walls << " of " << pts.size() << " points on its walls\n";
  EXPECT_GT(pts.size(), 0u);
  EXPECT_EQ(on_walls, 0u);
  expect_covered(s, pts, options(), "leaning box");
}

// Heads keep clear of drain holes (#36): a raised box's points on its base (its first layer is an
// island), with a 4 mm hole up its middle: exactly those within the hole's radius plus the head's
// of its axis are dropped, the others kept in order, and the tree is built from those kept.
TEST(SupportKeepOut, DropsThePointsWhoseHeadsWouldReachIntoAHole) {
  const Mesh box = test::make_box(0, 0, 0, 20, 16, 10, 8);
  SliceOptions slicing;
  slicing.thickness = 0.1;
  const Slices s = slice_layers(box, slicing);
  MemberSupportOptions o;
  o.points.raised = true;
  const MemberSupports all = make_member_supports(box, s, 0, 0.1, o);
  o.keep_out = {{{10, 8, -1}, {10, 8, 3}, 2}};
  const MemberSupports clear = make_member_supports(box, s, 0, 0.1, o);
  const double reach = 2 + 0.5 * o.tree.head_front_diameter_mm;
  size_t near = 0;
  SupportPoints expected;
  expected.fingerprint = all.points.fingerprint;
  for (size_t i = 0; i < all.points.size(); ++i) {
    const double* p = &all.points.xyz[3 * i];
    const bool in = std::hypot(p[0] - 10, p[1] - 8) < reach && p[2] >= -1 && p[2] <= 3;
    near += in;
    if (!in) expected.push_back_from(all.points, i);
  }
  ASSERT_GT(near, 0u);
  EXPECT_EQ(clear.kept_out, near);
  EXPECT_EQ(clear.points.xyz, expected.xyz);
  EXPECT_EQ(clear.points.face, expected.face);
  EXPECT_EQ(all.kept_out, 0u);
  EXPECT_LT(clear.tree.mesh.faces(), all.tree.mesh.faces());
}
