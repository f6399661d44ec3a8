// Hollowing (cavity.h, hollow_layers.h): the cavity is the part eroded in 3-D by a ball of the
// wall thickness, exactly on the layers' regions; bad options are refused in words.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "error_of.h"
#include "family.h"
#include "region_clearance.h"
#include "region_perimeter.h"
#include "shapes.h"
#include "slicereuse/hollowing/cavity.h"
#include "slicereuse/hollowing/drain_holes.h"
#include "slicereuse/hollowing/hollow_layers.h"
#include "slicereuse/regions/clip_regions.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/regions/layers_mesh.h"
#include "slicereuse/regions/region_triangles.h"
#include "slicereuse/regions/segment_distance.h"
#include "slicereuse/slicing/slice_layers.h"

namespace slicereuse {
namespace {

using ClipperLib::Paths;

// An axis-aligned rectangle as a region (counter-clockwise), in mm.
Paths rectangle(double x0, double y0, double x1, double y1) {
  return {{{region_units(x0), region_units(y0)},
           {region_units(x1), region_units(y0)},
           {region_units(x1), region_units(y1)},
           {region_units(x0), region_units(y1)}}};
}

std::set<std::pair<ClipperLib::cInt, ClipperLib::cInt>> corners(const Paths& region) {
  std::set<std::pair<ClipperLib::cInt, ClipperLib::cInt>> out;
  for (const ClipperLib::Path& p : region)
    for (const ClipperLib::IntPoint& q : p) out.insert({q.X, q.Y});
  return out;
}

// A box 10 x 8 x 6 mm in 60 layers of 0.1 mm, walls of 1 mm: its cavity is exactly the box
// shrunk by 1 mm on every side, z included (layers 10-49), and nothing elsewhere.
TEST(Cavity, OfABoxIsExactlyTheBoxShrunkByTheWall) {
  const std::vector<Paths> box(60, rectangle(0, 0, 10, 8));
  HollowingOptions o;
  o.wall_mm = 1;
  o.closing_mm = 0;
  const std::vector<Paths> cavity = cavity_regions(box, 0.1, o);
  ASSERT_EQ(cavity.size(), 60u);
  for (size_t k = 0; k < 60; ++k) {
    SCOPED_TRACE(k);
    if (k < 10 || k > 49) {
      EXPECT_TRUE(cavity[k].empty());
      continue;
    }
    ASSERT_EQ(cavity[k].size(), 1u);
    EXPECT_EQ(corners(cavity[k]), corners(rectangle(1, 1, 9, 7)));
  }
  EXPECT_NEAR(cavity_volume_mm3(cavity, 0.1), 8 * 6 * 4, 1e-9);
  // PrusaSlicer's closing distance opens the cavity: inside the unclosed one, its vertical edges
  // rounded (radius 0.5 mm: a quarter disk less at each corner, sqrt(0.75) mm below the top).
  o.closing_mm = 0.5;
  const std::vector<Paths> closed = cavity_regions(box, 0.1, o);
  const double corner_loss = (1 - M_PI / 4) * 0.25 * 4;
  // Their round joins' chords lose at most the arc tolerance along the four quarter circles.
  EXPECT_NEAR(region_area_mm2(closed[30]), 8 * 6 - corner_loss, 2 * M_PI * 0.5 * kCavityArcToleranceMm);
  for (size_t k = 0; k < 60; ++k) {
    ClipperLib::Clipper c;
    c.AddPaths(closed[k], ClipperLib::ptSubject, true);
    c.AddPaths(cavity[k], ClipperLib::ptClip, true);
    Paths outside;
    c.Execute(ClipperLib::ctDifference, outside, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    EXPECT_LT(std::abs(region_area_mm2(outside)), 1e-9) << "layer " << k;
  }
}

// The half-width of a square frustum's layer k: 6 mm at the bottom, narrowing by 0.5 mm per mm
// of height (its walls slope 63 degrees from the horizontal).
double frustum_half(size_t k) { return 6 - 0.5 * (0.1 * double(k) + 0.05); }

// The distance from (x, y) inside the frustum's layer j to its outside.
double depth(size_t j, double x, double y) { return frustum_half(j) - std::max(std::abs(x), std::abs(y)); }

// On a sloped part every cavity point lies at least the wall from every point outside, in 3-D:
// its distance to each layer's outside and the height between them; a 2-D offset of each
// layer by the wall (what a per-layer hollowing does) would come closer than that.
TEST(Cavity, KeepsTheWallOnASlopeIn3D) {
  const size_t n = 80;  // 8 mm
  std::vector<Paths> frustum;
  for (size_t k = 0; k < n; ++k) frustum.push_back(rectangle(-frustum_half(k), -frustum_half(k), frustum_half(k), frustum_half(k)));
  HollowingOptions o;
  o.wall_mm = 1.5;
  o.closing_mm = 0;
  const std::vector<Paths> cavity = cavity_regions(frustum, 0.1, o);
  // Points farther than the wall from every layer's outside within it, in 3-D.
  const auto clearance = [&](size_t k, double x, double y) {
    double nearest = INFINITY;
    for (size_t j = 0; j < n; ++j) {
      const double dz = 0.1 * (double(j) - double(k)), d = std::max(0.0, depth(j, x, y));
      nearest = std::min(nearest, std::sqrt(d * d + dz * dz));
    }
    return std::min({nearest, 0.1 * double(k) + 0.05, 0.1 * double(n - k) - 0.05});
  };
  size_t layers = 0;
  for (size_t k = 0; k < n; ++k)
    for (const ClipperLib::Path& p : cavity[k]) {
      layers += &p == &cavity[k][0];
      for (const ClipperLib::IntPoint& q : p)
        EXPECT_GE(clearance(k, double(q.X) / kRegionScale, double(q.Y) / kRegionScale), 1.5 - 1e-6) << "layer " << k;
    }
  EXPECT_EQ(layers, n - 2 * 15);
  // Layer 20's corner on the 2-D offset lies 1.5 mm inside its own layer but nearer to the
  // layers above: the 3-D cavity stops short of it, by the slope.
  const double corner = frustum_half(20) - 1.5;
  EXPECT_LT(clearance(20, corner, 0), 1.5 - 0.1);
  double widest = 0;
  for (const ClipperLib::IntPoint& q : cavity[20][0]) widest = std::max(widest, double(q.X) / kRegionScale);
  EXPECT_LT(widest, corner - 0.1);
}

Paths offset(const Paths& region, double mm) {
  ClipperLib::ClipperOffset o(2, kCavityArcToleranceMm * kRegionScale);
  o.AddPaths(region, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  Paths out;
  o.Execute(out, mm * kRegionScale);
  return out;
}

double perimeter_mm(const Paths& region) { return test::region_perimeter(region) / kRegionScale; }

// The definition, term by term: layer k eroded (grow false) or dilated by a ball of radius r,
// every layer within it offset and intersected (or united), layers beyond the stack empty.
std::vector<Paths> by_ball_naively(const std::vector<Paths>& layers, double h, double r, bool grow) {
  const long n = long(layers.size()), reach = long(std::floor(r / h + 1e-9));
  std::vector<Paths> out(layers.size());
  for (long k = 0; k < n; ++k) {
    if (!grow && (k < reach || k + reach >= n)) continue;
    Paths acc = offset(layers[size_t(k)], grow ? r : -r);
    for (long j = std::max(0L, k - reach); j <= std::min(n - 1, k + reach); ++j) {
      const double dz = double(j - k) * h, radius = std::sqrt(std::max(0.0, r * r - dz * dz));
      acc = clip_regions(acc, offset(layers[size_t(j)], grow ? radius : -radius),
                    grow ? ClipperLib::ctUnion : ClipperLib::ctIntersection);
    }
    out[size_t(k)] = acc;
  }
  return out;
}

// Generated parts of several kinds (a sphere, a torus whose layers have holes, a standing handle
// whose layers split in two), with and without the closing distance: the cavity lies inside the
// definition computed term by term on the unsimplified layers (to the round offsets' arc
// tolerance: the walls are never thinner), and loses at most the simplification's band
// (kCavitySimplifyMm) and the proofs' slack (kCavityProofSlackMm, each way) along its surface.
TEST(Cavity, EqualsTheDefinitionTermByTerm) {
  for (const auto& [shape, height] : {std::pair{"sphere", 6.0}, {"torus", 6.0}, {"handle", 16.0}}) {
    test::FamilyOptions fo;
    fo.shape = shape;
    fo.faces = 2500;
    fo.height = height;
    const Slices s = slice_layers(test::make_family_base(fo), SliceOptions{0.1});
    std::vector<Paths> layers;
    for (size_t k = 0; k < s.layers(); ++k) layers.push_back(layer_region(LayerView(s, k)));
    for (const auto [wall, closing] : {std::pair{0.6, 0.0}, {0.4, 0.3}}) {
      SCOPED_TRACE(std::string(shape) + " wall " + std::to_string(wall) + " closing " + std::to_string(closing));
      HollowingOptions o;
      o.wall_mm = wall;
      o.closing_mm = closing;
      const std::vector<Paths> cavity = cavity_regions(layers, 0.1, o);
      std::vector<Paths> expected = by_ball_naively(layers, 0.1, wall + closing, false);
      if (closing > 0) expected = by_ball_naively(expected, 0.1, closing, true);
      double volume = 0, lost = 0, surface = 0;
      for (size_t k = 0; k < layers.size(); ++k) {
        const double area = region_area_mm2(expected[k]);
        volume += area * 0.1;
        // Round offsets' chords may lie either side of another offset's: no further apart than
        // the arc tolerance along the boundary.
        EXPECT_LE(region_area_mm2(clip_regions(cavity[k], expected[k], ClipperLib::ctDifference)),
                  perimeter_mm(expected[k]) * kCavityArcToleranceMm)
            << "layer " << k;
        lost += region_area_mm2(clip_regions(expected[k], cavity[k], ClipperLib::ctDifference)) * 0.1;
        surface += perimeter_mm(expected[k]) * 0.1 +
                   std::abs(area - (k > 0 ? region_area_mm2(expected[k - 1]) : 0));
      }
      EXPECT_GT(volume, 0.5);
      // The erosion's slack, and the dilation's.
      const double band = kCavitySimplifyMm + kCavityProofSlackMm * (closing > 0 ? 2 : 1);
      EXPECT_LE(lost, surface * band) << "of a cavity of " << volume << " mm3";
    }
  }
}

// Reuse and direct slicing give a member the same contour points, but not always from the same
// point of each loop, nor the loops in the same order: the cavity is the same either way, and
// the same from the contours as from their regions.
TEST(Cavity, DependsOnTheLoopsPointsNotWhereTheyStart) {
  test::FamilyOptions fo;
  fo.shape = "torus";
  fo.faces = 2500;
  fo.height = 6;
  const Slices s = slice_layers(test::make_family_base(fo), SliceOptions{0.1});
  std::vector<Paths> contours = layers_paths(s), turned = contours, regions = layer_regions(s);
  for (Paths& layer : turned) {
    for (size_t i = 0; i < layer.size(); ++i)
      std::rotate(layer[i].begin(), layer[i].begin() + long((7 * i + 3) % layer[i].size()), layer[i].end());
    std::reverse(layer.begin(), layer.end());
  }
  HollowingOptions o;
  o.wall_mm = 0.6;
  o.closing_mm = 0.3;
  const std::vector<Paths> cavity = cavity_regions(contours, 0.1, o);
  double volume = 0;
  for (const Paths& layer : cavity) volume += region_area_mm2(layer) * 0.1;
  EXPECT_GT(volume, 1);
  EXPECT_EQ(cavity_regions(turned, 0.1, o), cavity);
  EXPECT_EQ(cavity_regions(regions, 0.1, o), cavity);
}

// A square 20 mm wide less two square holes and a 64-gon hole: its triangles are counter-clockwise,
// cover it exactly (their union is the region, their areas sum to its area: no overlaps), and its
// slabs, one per layer, enclose the layers' areas times the thickness.
TEST(LayersMesh, TrianglesTileTheRegionAndSlabsHoldItsVolume) {
  Paths region = rectangle(0, 0, 20, 20);
  for (const Paths& hole : {rectangle(2, 2, 6, 6), rectangle(8, 3, 12, 15)}) {
    ClipperLib::Path h = hole[0];
    ClipperLib::ReversePath(h);
    region.push_back(h);
  }
  ClipperLib::Path disc;
  for (int i = 63; i >= 0; --i)  // clockwise: a hole
    disc.push_back({region_units(15 + 3 * std::cos(i * M_PI / 32)), region_units(15 + 3 * std::sin(i * M_PI / 32))});
  region.push_back(disc);
  const std::vector<RegionTriangle> triangles = region_triangles(region);
  double sum = 0;
  Paths tiles;
  for (const RegionTriangle& t : triangles) {
    const ClipperLib::Path tile{t[0], t[1], t[2]};
    EXPECT_GT(ClipperLib::Area(tile), 0);
    sum += region_area_mm2({tile});
    tiles.push_back(tile);
  }
  EXPECT_NEAR(sum, region_area_mm2(region), 1e-9);
  EXPECT_NEAR(region_area_mm2(clip_regions(tiles, {}, ClipperLib::ctUnion)), sum, 1e-9);
  EXPECT_NEAR(std::abs(region_area_mm2(clip_regions(tiles, region, ClipperLib::ctXor))), 0, 1e-9);
  std::vector<Paths> layers{region, {}, rectangle(0, 0, 1, 2), region};
  const Mesh m = layers_mesh(layers, 2, 0.5);
  EXPECT_NEAR(test::signed_volume(m), 0.5 * (2 * region_area_mm2(region) + 2), 1e-6);
  const ZRange z = z_range(m);
  EXPECT_EQ(z.min, 2);
  EXPECT_EQ(z.max, 4);
}

// The 24-gon of radius r's area: 12 r^2 sin 15 degrees.
double disc_area(double r) { return 12 * r * r * 0.25881904510252074; }

// The box's cavity (10 x 8 x 6 mm in 0.1 mm layers, walls of 1 mm): rectangle (1, 1)-(9, 7) on
// layers 10-49, and the layers' mid-planes.
std::vector<Paths> box_cavity() {
  HollowingOptions o;
  o.wall_mm = 1;
  o.closing_mm = 0;
  return cavity_regions(std::vector<Paths>(60, rectangle(0, 0, 10, 8)), 0.1, o);
}
std::vector<double> box_planes() {
  std::vector<double> z;
  for (size_t k = 0; k < 60; ++k) z.push_back(0.1 * (double(k) + 0.5));
  return z;
}

// Three holes per cavity: the first under its middle, the others at the corners of the cavity's
// lowest layer shrunk by the radius farthest from the holes placed; each drilled from layer 0 up
// to the cavity, apart from the others.
TEST(DrainHoles, SpreadOverTheCavitysLowestLayer) {
  std::vector<Paths> cavity = box_cavity();
  const std::vector<DrainHole> holes = add_drain_holes(cavity, 2, 3);
  ASSERT_EQ(holes.size(), 3u);
  EXPECT_NEAR(holes[0].x_mm, 5, 1e-9);
  EXPECT_NEAR(holes[0].y_mm, 4, 1e-9);
  const Paths room = rectangle(2, 2, 8, 6);
  for (const DrainHole& h : holes) {
    EXPECT_EQ(h.layer, 10u);
    EXPECT_EQ(h.first, 0u);
    EXPECT_TRUE(h.automatic);
    EXPECT_TRUE(region_covers(room, {region_units(h.x_mm), region_units(h.y_mm)}));
  }
  // The second at a corner of the room (3.6 mm from the middle), the third at another, as far
  // from both as any corner is (every corner lies 3.6 mm from the middle).
  EXPECT_NEAR(std::hypot(holes[1].x_mm - 5, holes[1].y_mm - 4), std::hypot(3, 2), 1e-9);
  EXPECT_NEAR(std::hypot(holes[2].x_mm - 5, holes[2].y_mm - 4), std::hypot(3, 2), 1e-9);
  EXPECT_GE(std::hypot(holes[2].x_mm - holes[1].x_mm, holes[2].y_mm - holes[1].y_mm), 6 - 1e-9);
  for (size_t k = 0; k < 10; ++k) EXPECT_NEAR(region_area_mm2(cavity[k]), 3 * disc_area(1), 1e-6) << k;
  EXPECT_EQ(test::error_of([&] { add_drain_holes(cavity, 2, 0); }),
            "0 drain holes per cavity: at least 1, or a drain hole diameter of 0 for none");
}

// A hole wider than the part's base under its cavity would cut through the part's side: refused
// in words. One wider than the cavity's floor but inside the base is drilled (a 10 x 8 x 6 mm box,
// walls of 1 mm: its cavity's floor is 8 x 6 mm, its base 10 x 8 mm; a 9 mm 24-gon at its middle
// reaches 0.5 mm beyond two of its sides, 2.55 mm2 in all).
TEST(DrainHoles, AHoleWiderThanThePartsBaseIsRefusedInWords) {
  const Slices box = slice_layers(test::make_box(0, 0, 0, 10, 8, 6), SliceOptions{0.1});
  HollowingOptions o;
  o.wall_mm = 1;
  o.closing_mm = 0;
  for (const double d : {2.0, 7.0}) {
    std::vector<Paths> cavity = layers_cavity(box, o);
    const std::vector<DrainHole> holes = add_drain_holes(cavity, d);
    ASSERT_EQ(holes.size(), 1u);
    EXPECT_NO_THROW(check_drain_holes_fit(holes, d, box)) << d << " mm";
  }
  std::vector<Paths> cavity = layers_cavity(box, o);
  const std::vector<DrainHole> holes = add_drain_holes(cavity, 9);
  EXPECT_EQ(test::error_of([&] { check_drain_holes_fit(holes, 9, box); }),
            "a drain hole of 9 mm at (5.00, 4.00) mm would cut through the part's side on layer 9 (z 0.950 mm): "
            "2.55 mm2 of it lies outside the part there, right under its cavity; make drain_hole_mm smaller");
  // A box on a waist too thin for a cavity, on a base as wide as the box: the hole fits the floor
  // and the base, but would open the waist's sides (a sphere's base, whose layers hold less of
  // the hole the lower they are, passes: PlateJobTest.DrainHolesOpenEveryCavityThroughTheBase).
  Mesh waisted = test::make_box(0, 0, 0.82, 10, 8, 6.82);
  test::append_mesh(waisted, test::make_box(3, 2, 0.38, 7, 6, 0.88));
  test::append_mesh(waisted, test::make_box(0, 0, 0, 10, 8, 0.42));
  const Slices on_waist = slice_layers(waisted, SliceOptions{0.1});
  std::vector<Paths> floor = layers_cavity(on_waist, o);
  const std::vector<DrainHole> wide = add_drain_holes(floor, 5);
  ASSERT_EQ(wide.size(), 1u);
  EXPECT_EQ(test::error_of([&] { check_drain_holes_fit(wide, 5, on_waist); }),
            "a drain hole of 5 mm at (5.00, 4.00) mm would cut through the part's side on layer 4 (z 0.450 mm): "
            "3.91 mm2 of it lies outside the part there, over part of the layer below; make drain_hole_mm smaller");
}

// A user's hole from below is the automatic hole's 24-gon, from 1 mm under the mouth to
// wall + closing + 1 mm above it; one from the side wall runs sideways through it, its layers'
// sections joining the cavity to the outside; one that ends in the wall is refused in words, and
// nothing is drilled when any is.
TEST(DrainHoles, TheUsersRunAlongTheirNormalIntoTheCavity) {
  const std::vector<double> z = box_planes();
  std::vector<Paths> cavity = box_cavity();
  const std::vector<DrainHole> below = add_drain_holes_at(cavity, z, {3, 4, 0}, {0, 0, -1}, 2, 2);
  ASSERT_EQ(below.size(), 1u);
  EXPECT_EQ(below[0].first, 0u);
  EXPECT_EQ(below[0].layer, 20u);  // the prism reaches z = 2
  EXPECT_FALSE(below[0].automatic);
  for (size_t k = 0; k < 10; ++k) EXPECT_NEAR(region_area_mm2(cavity[k]), disc_area(1), 1e-6) << k;
  for (size_t k = 10; k < 50; ++k) EXPECT_NEAR(region_area_mm2(cavity[k]), 8 * 6, 1e-9) << k;

  cavity = box_cavity();
  const std::vector<DrainHole> side = add_drain_holes_at(cavity, z, {0, 4, 3}, {-1, 0, 0}, 2, 2);
  ASSERT_EQ(side.size(), 1u);
  EXPECT_EQ(side[0].first, 20u);  // z from 2 to 4
  EXPECT_EQ(side[0].layer, 40u);
  const Paths& middle = cavity[30];  // z = 3.05: the hole's section is (-1, 2) mm across x
  ASSERT_EQ(middle.size(), 1u);
  EXPECT_TRUE(region_covers(middle, {region_units(-0.9), region_units(4)}));
  EXPECT_TRUE(region_covers(middle, {region_units(0.5), region_units(4.9)}));
  EXPECT_FALSE(region_covers(middle, {region_units(-1.1), region_units(4)}));
  EXPECT_FALSE(region_covers(middle, {region_units(0.5), region_units(5.1)}));

  cavity = box_cavity();
  const std::vector<Paths> before = cavity;
  EXPECT_EQ(test::error_of([&] { add_drain_holes_at(cavity, z, {3, 4, 0, 0.2, 0.2, 6}, {0, 0, -1, 0, 0, 1}, 0.2, 2); }),
            "drain hole 2 at (0.20, 0.20, 6.00) mm reaches no cavity: drilled 2 mm in along its normal (0.00, 0.00, "
            "1.00), it ends in the wall; place it over the cavity (Hollow Mesh shows it)");
  EXPECT_EQ(cavity, before);
}

// subtract_cavity leaves each layer's region less its cavity, exactly Clipper's difference (the
// same point set up to the 1 nm grid: their xor on it is empty), whichever way it takes the cavity
// out: by the layer's own contours where they wind once around it, by its region where the
// cavity lies inside that, else by Clipper. A drained sphere, whose hole opens its two lowest
// layers to the outside; shells whose contours wind twice over some of the cavity: two
// overlapping boxes (across the middle), a box twice (all over), a box inside a box (inside the
// cavity); a cavity given across a box's side but on one layer.
TEST(SubtractCavity, LeavesExactlyClippersDifference) {
  test::FamilyOptions fo;
  fo.shape = "sphere";
  fo.faces = 2500;
  fo.height = 6;
  Mesh boxes = test::make_box(0, 0, 0, 10, 8, 6), twice = boxes, nested = boxes;
  test::append_mesh(boxes, test::make_box(4, 0, 0, 14, 8, 6));
  test::append_mesh(twice, test::make_box(0, 0, 0, 10, 8, 6));
  test::append_mesh(nested, test::make_box(3, 3, 0, 7, 5, 6));
  const Slices box = slice_layers(test::make_box(0, 0, 0, 10, 8, 6), SliceOptions{0.1});
  std::vector<Paths> across(box.layers(), rectangle(8, 2, 12, 6));  // reaches 2 mm out of the box
  across[30] = rectangle(2, 2, 8, 6);                                // inside, as a cavity is
  HollowingOptions o;
  o.wall_mm = 1;
  o.closing_mm = 0;
  const Slices sphere = slice_layers(test::make_family_base(fo), SliceOptions{0.1});
  std::vector<Paths> drained = layers_cavity(sphere, o);
  const std::vector<DrainHole> holes = add_drain_holes(drained, 2);
  ASSERT_EQ(holes.size(), 1u);
  std::vector<std::tuple<std::string, Slices, std::vector<Paths>>> cases{{"drained sphere", sphere, drained}};
  for (const auto& [name, mesh] :
       {std::pair{"overlapping boxes", boxes}, {"a box twice", twice}, {"nested boxes", nested}}) {
    const Slices shells = slice_layers(mesh, SliceOptions{0.1});
    cases.emplace_back(name, shells, layers_cavity(shells, o));
  }
  cases.emplace_back("cavity across the side", box, across);
  // A layer's contours from its first, as points.
  const auto contours = [](const Slices& s, size_t k, size_t count) {
    std::vector<std::vector<double>> out;
    for (uint64_t c = s.layer_begin[k]; c < s.layer_begin[k + 1] && out.size() < count; ++c)
      out.emplace_back(s.xyz.begin() + long(3 * s.contour_begin[c]), s.xyz.begin() + long(3 * s.contour_begin[c + 1]));
    return out;
  };
  for (const auto& [name, part, cavity] : cases) {
    SCOPED_TRACE(name);
    Slices hollowed = part;
    subtract_cavity(hollowed, 0, cavity);
    ASSERT_EQ(hollowed.layers(), part.layers());
    size_t cut = 0, by_loops = 0, by_contours = 0;
    for (size_t k = 0; k < part.layers(); ++k) {
      const Paths walls = layer_region(LayerView(hollowed, k));
      const Paths expected = clip_regions(layer_region(LayerView(part, k)), cavity[k], ClipperLib::ctDifference);
      EXPECT_TRUE(clip_regions(walls, expected, ClipperLib::ctXor).empty()) << "layer " << k;
      EXPECT_NEAR(region_area_mm2(walls), region_area_mm2(expected), 1e-12) << "layer " << k;
      if (cavity[k].empty()) continue;
      ++cut;
      // Taken out by its loops (the layer's last loops are the cavity's, reversed) ...
      const Paths loops = layer_paths(LayerView(hollowed, k));
      bool reversed = loops.size() >= cavity[k].size();
      for (size_t c = 0; c < cavity[k].size() && reversed; ++c) {
        ClipperLib::Path loop = cavity[k][c];
        std::reverse(loop.begin(), loop.end());
        reversed = loops[loops.size() - cavity[k].size() + c] == loop;
      }
      by_loops += reversed;
      // ... exactly where it lies inside the region,
      EXPECT_EQ(reversed, clip_regions(cavity[k], layer_region(LayerView(part, k)), ClipperLib::ctDifference).empty())
          << "layer " << k;
      // and with the layer's own contours before them, as they are, where those wind once.
      const size_t own = part.layer_begin[k + 1] - part.layer_begin[k];
      by_contours += reversed && loops.size() == own + cavity[k].size() &&
                     contours(hollowed, k, own) == contours(part, k, own);
    }
    if (name == "drained sphere") {
      EXPECT_EQ(cut, 50u);
      EXPECT_EQ(by_loops, cut - 2);
      EXPECT_EQ(by_contours, cut - 2);
    } else if (name != "cavity across the side") {
      EXPECT_EQ(cut, 40u);
      EXPECT_EQ(by_loops, cut);
      EXPECT_EQ(by_contours, 0u);
    } else {
      EXPECT_EQ(cut, part.layers());
      EXPECT_EQ(by_loops, 1u);
      EXPECT_EQ(by_contours, 1u);
    }
  }
}

TEST(Cavity, AWallThickerThanThePartLeavesNoCavity) {
  const std::vector<Paths> slab(30, rectangle(0, 0, 20, 20));  // 3 mm thick
  HollowingOptions o;
  o.wall_mm = 1.6;
  o.closing_mm = 0;
  for (const Paths& layer : cavity_regions(slab, 0.1, o)) EXPECT_TRUE(layer.empty());
  o.wall_mm = 0;  // solid
  for (const Paths& layer : cavity_regions(slab, 0.1, o)) EXPECT_TRUE(layer.empty());
}

TEST(Cavity, RefusesBadOptionsInWords) {
  const std::vector<Paths> box(10, rectangle(0, 0, 10, 8));
  HollowingOptions o;
  o.wall_mm = -1;
  EXPECT_EQ(test::error_of([&] { cavity_regions(box, 0.1, o); }),
            "the hollowing wall thickness is -1 mm; it must be a finite, non-negative number (0: solid)");
  o.wall_mm = NAN;
  EXPECT_EQ(test::error_of([&] { cavity_regions(box, 0.1, o); }),
            "the hollowing wall thickness is nan mm; it must be a finite, non-negative number (0: solid)");
  o.wall_mm = 1;
  o.closing_mm = INFINITY;
  EXPECT_EQ(test::error_of([&] { cavity_regions(box, 0.1, o); }),
            "the hollowing closing distance is inf mm; it must be a finite, non-negative number");
  o.closing_mm = 0;
  EXPECT_EQ(test::error_of([&] { cavity_regions(box, 0, o); }), "hollowing needs a positive layer thickness, not 0 mm");
}

// The nearest two segments come: 0 when they meet (exact integer orientations), else the
// nearest an end of one comes to the other.
double segments_apart(const ClipperLib::IntPoint& a, const ClipperLib::IntPoint& b, const ClipperLib::IntPoint& c,
                      const ClipperLib::IntPoint& d) {
  const auto side = [](const ClipperLib::IntPoint& p, const ClipperLib::IntPoint& q, const ClipperLib::IntPoint& r) {
    const __int128 x = __int128(q.X - p.X) * (r.Y - p.Y) - __int128(q.Y - p.Y) * (r.X - p.X);
    return (x > 0) - (x < 0);
  };
  const auto within = [](const ClipperLib::IntPoint& p, const ClipperLib::IntPoint& q, const ClipperLib::IntPoint& r) {
    return std::min(p.X, q.X) <= r.X && r.X <= std::max(p.X, q.X) && std::min(p.Y, q.Y) <= r.Y && r.Y <= std::max(p.Y, q.Y);
  };
  const int o1 = side(a, b, c), o2 = side(a, b, d), o3 = side(c, d, a), o4 = side(c, d, b);
  if ((o1 != o2 && o3 != o4) || (o1 == 0 && within(a, b, c)) || (o2 == 0 && within(a, b, d)) ||
      (o3 == 0 && within(c, d, a)) || (o4 == 0 && within(c, d, b)))
    return 0;
  const auto d2 = [](const ClipperLib::IntPoint& p, const ClipperLib::IntPoint& q, const ClipperLib::IntPoint& r) {
    return segment_distance2(double(p.X), double(p.Y), double(q.X), double(q.Y), double(r.X), double(r.Y));
  };
  return std::sqrt(std::min({d2(a, c, d), d2(b, c, d), d2(c, a, b), d2(d, a, b)}));
}

// boundaries_apart (region_clearance.h), which bounds runs of edges by boxes and capsules before
// comparing their points, against every pair of edges of random loops (crossing, touching, of
// one to many edges), at distances around the nearest pair's.
TEST(RegionClearance, BoundariesApartAgreesWithEveryPairOfEdges) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> loops(1, 3), points(1, 40), coordinate(0, 4000);
  std::uniform_real_distribution<double> scale(0.5, 1.5);
  size_t apart = 0, near = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Paths a, b;
    for (Paths* region : {&a, &b})
      for (int l = loops(rng); l > 0; --l) {
        // A wobbly circle, so that loops lie near each other along their length as a cavity's do.
        const double cx = coordinate(rng), cy = coordinate(rng), r = 50 + coordinate(rng) / 8.0;
        const int n = points(rng);
        ClipperLib::Path loop;
        for (int i = 0; i < n; ++i) {
          const double t = 2 * M_PI * i / n, w = r * scale(rng);
          loop.push_back({ClipperLib::cInt(std::llround(cx + w * std::cos(t))), ClipperLib::cInt(std::llround(cy + w * std::sin(t)))});
        }
        region->push_back(loop);
      }
    double nearest = INFINITY;
    for (const ClipperLib::Path& p : a)
      for (size_t i = 0; i < p.size(); ++i)
        for (const ClipperLib::Path& q : b)
          for (size_t j = 0; j < q.size(); ++j)
            nearest = std::min(nearest, segments_apart(p[i], p[(i + 1) % p.size()], q[j], q[(j + 1) % q.size()]));
    const IndexedRegion ia = index_region(a), ib = index_region(b);
    for (const double distance : {0.0, nearest * 0.5, nearest * 0.999, nearest * 1.001, nearest * 2, nearest + 300}) {
      SCOPED_TRACE("trial " + std::to_string(trial) + ", distance " + std::to_string(distance) + ", nearest " +
                   std::to_string(nearest));
      const bool expected = distance == 0 ? nearest > 0 : nearest >= distance;
      EXPECT_EQ(boundaries_apart(ia, ib, distance), expected);
      EXPECT_EQ(boundaries_apart(ib, ia, distance), expected);
      (expected ? apart : near) += 1;
    }
  }
  // Both answers, many times over.
  EXPECT_GT(apart, 500u);
  EXPECT_GT(near, 500u);
}

}  // namespace
}  // namespace slicereuse
