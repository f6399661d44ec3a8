// Transfer through a map onto a target of other connectivity, with maps known exactly: the
// target is the source (or a family member) with its vertices renumbered and its faces
// reordered and rotated, and the map sends each source vertex to its renumbered self.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include "error_of.h"
#include "family.h"
#include "sections.h"
#include "shuffle_mesh.h"
#include "slicereuse/crossparam/cross_parameterize.h"
#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/raster/rasterize_layer.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/transfer/transfer_through_map.h"
#include "slicereuse/util/error.h"

using namespace slicereuse;

namespace {

struct Shuffled {
  Mesh target;
  SurfaceMap map;  // source vertex i -> its renumbered self on target
};

// `mesh` (a member with the faces of `source`) shuffled, and the exact map onto it.
Shuffled shuffle(const Mesh& source, const Mesh& mesh, uint64_t seed) {
  test::ShuffledMesh shuffled = test::shuffle_mesh(mesh, seed);
  Shuffled s;
  s.map = test::map_onto_shuffled(source, shuffled);
  s.target = std::move(shuffled.mesh);
  return s;
}

Slices slice(const Mesh& m, double h, double z_start = std::nan("")) {
  SliceOptions o;
  o.thickness = h;
  o.z_start = z_start;
  return slice_layers(m, o);
}

// Per layer, the points with their encoding as a sorted list: equal lists mean the same
// points on the same faces and edges with the same t, bit for bit.
using Encoded = std::tuple<uint32_t, uint8_t, double, double, double>;
std::vector<Encoded> encoded_layer(const Slices& s, size_t k) {
  std::vector<Encoded> out;
  for (size_t p = s.contour_begin[s.layer_begin[k]]; p < s.contour_begin[s.layer_begin[k + 1]]; ++p)
    out.emplace_back(s.face[p], s.edge[p], s.t[p], s.xyz[3 * p], s.xyz[3 * p + 1]);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<uint8_t> raster(const Slices& s, size_t k) {
  const PrinterProfile p;  // 1024 x 768, 75 um
  std::vector<uint8_t> img(size_t(p.width_px) * p.height_px);
  rasterize_layer(s, k, p, img.data());
  return img;
}

double similarity(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  size_t same = 0;
  for (size_t i = 0; i < a.size(); ++i) same += a[i] == b[i];
  return double(same) / double(a.size());
}

test::FamilyOptions family(const std::string& shape, test::ZChange z_change = test::ZChange::None) {
  test::FamilyOptions o;
  o.shape = shape;
  o.faces = 6000;
  o.height = 10;
  o.seed = 11;
  o.z_change = z_change;
  return o;
}

// Exact transfer of `source`'s slicing through the map equals direct slicing of the target on
// the same plate: same loops, same encoding, identical masks. Returns the stats.
TransferStats expect_exact_equals_direct(const Slices& source, const Shuffled& s) {
  TransferStats st;
  const Slices moved = transfer_through_map(source, s.map, s.target, TransferOptions(TransferMode::Exact), &st);
  const Slices direct = slice(s.target, source.thickness, source.z_start);
  EXPECT_EQ(st.transferred_layers + st.resliced_layers, direct.layers());
  EXPECT_EQ(moved.fingerprint, mesh_fingerprint(s.target));
  EXPECT_EQ(moved.points(), direct.points());
  test::expect_same_sections(moved, direct);
  for (size_t k = 0; k < std::min(moved.layers(), direct.layers()); ++k) {
    EXPECT_EQ(encoded_layer(moved, k), encoded_layer(direct, k)) << "layer " << k;
    EXPECT_TRUE(raster(moved, k) == raster(direct, k)) << "layer " << k;
  }
  // Without the encoding: the same points.
  const Slices bare = transfer_through_map(source, s.map, s.target, TransferOptions(TransferMode::Exact, false));
  EXPECT_TRUE(bare.face.empty() && bare.edge.empty() && bare.t.empty());
  EXPECT_EQ(bare.contour_begin, moved.contour_begin);
  EXPECT_TRUE(bare.xyz == moved.xyz);
  return st;
}

class ThroughMapShapes : public ::testing::TestWithParam<std::string> {};

}  // namespace

TEST_P(ThroughMapShapes, ExactEqualsDirectSlicingOfAShuffledCopy) {
  const Mesh base = test::make_family_base(family(GetParam()));
  const Slices source = slice(base, 0.05);
  const Shuffled s = shuffle(base, base, 3);
  ASSERT_NE(s.map.target, s.map.source);  // really other connectivity
  const TransferStats st = expect_exact_equals_direct(source, s);
  EXPECT_EQ(st.transferred_layers, source.layers());
  EXPECT_EQ(st.resliced_layers, 0u);
}

TEST_P(ThroughMapShapes, ExactEqualsDirectSlicingOfAShuffledMember) {
  const test::FamilyOptions o = family(GetParam());
  const Mesh base = test::make_family_base(o);
  const Slices source = slice(base, 0.05);
  for (int i = 1; i <= 2; ++i) {
    const Shuffled s = shuffle(base, test::make_family_member(base, o, i), 10 + i);
    const TransferStats st = expect_exact_equals_direct(source, s);
    EXPECT_EQ(st.resliced_layers, 0u) << "member " << i;
  }
}

TEST_P(ThroughMapShapes, BarycentricMatchesDirectSlicingMasks) {
  const test::FamilyOptions o = family(GetParam());
  const Mesh base = test::make_family_base(o);
  const Slices source = slice(base, 0.05);
  const Shuffled s = shuffle(base, test::make_family_member(base, o, 1), 5);
  TransferStats st;
  const Slices bary =
      transfer_through_map(source, s.map, s.target, TransferOptions(TransferMode::Barycentric, false), &st);
  const Slices direct = slice(s.target, source.thickness, source.z_start);
  ASSERT_EQ(bary.layers(), direct.layers());
  EXPECT_EQ(st.transferred_layers, bary.layers());
  EXPECT_LT(st.max_plane_deviation, 1e-9);  // the member keeps every vertex's height
  EXPECT_TRUE(bary.face.empty());
  for (size_t k = 0; k < bary.layers(); ++k) {
    EXPECT_EQ(bary.layer_z[k], direct.layer_z[k]);
    EXPECT_GE(similarity(raster(bary, k), raster(direct, k)), 0.9999) << "layer " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, ThroughMapShapes, ::testing::Values("arch", "ear", "handle"),
                         [](const auto& info) { return info.param; });

// Members changed in z (in a band of heights, or everywhere) still give direct slicing exactly.
// Tracing does not need the source's edges to straddle the same way, so most layers are traced
// even where z changed; a taller member's top layers have no seeds and are re-sliced.
TEST(TransferThroughMap, ZChangedMembersMixTracedAndReslicedLayers) {
  for (test::ZChange change : {test::ZChange::Band, test::ZChange::Everywhere}) {
    const test::FamilyOptions o = family("ear", change);
    const Mesh base = test::make_family_base(o);
    const Slices source = slice(base, 0.05);
    size_t transferred = 0, resliced = 0, layers = 0;
    for (int i = 1; i <= 3; ++i) {
      const Mesh member = test::make_family_member(base, o, i);
      const TransferStats st = expect_exact_equals_direct(source, shuffle(base, member, 20 + i));
      transferred += st.transferred_layers;
      resliced += st.resliced_layers;
      layers += st.transferred_layers + st.resliced_layers;
    }
    EXPECT_GT(transferred, layers / 2) << int(change);
    if (change == test::ZChange::Everywhere) EXPECT_GT(resliced, 0u);
  }
}

TEST(TransferThroughMap, LocalZEditLeavesMostLayersCertified) {
  const test::FamilyOptions o = family("arch");
  const Mesh base = test::make_family_base(o);
  const double h = 0.05;
  const Slices source = slice(base, h);
  Mesh member = test::make_family_member(base, o, 2);
  // Raise the top vertex by 3.2 layers: the member grows by 3 or 4 layers, which have no seeds
  // in the source's slicing and are re-sliced; every other layer is traced and certified.
  size_t top = 0;
  for (size_t v = 0; v < member.vertices(); ++v)
    if (member.V[3 * v + 2] > member.V[3 * top + 2]) top = v;
  member.V[3 * top + 2] += 3.2 * h;
  const Shuffled s = shuffle(base, member, 7);
  const TransferStats st = expect_exact_equals_direct(source, s);
  EXPECT_GE(st.resliced_layers, 3u);
  EXPECT_LE(st.resliced_layers, 4u);
  EXPECT_EQ(st.transferred_layers, source.layers());
  // Barycentric mode has the same layers: the source's are carried, the extra ones re-sliced.
  TransferStats bt;
  const Slices bary =
      transfer_through_map(source, s.map, s.target, TransferOptions(TransferMode::Barycentric, false), &bt);
  const Slices direct = slice(s.target, h, source.z_start);
  ASSERT_EQ(bary.layers(), direct.layers());
  EXPECT_EQ(bt.transferred_layers, source.layers());
  EXPECT_EQ(bt.resliced_layers, direct.layers() - source.layers());
  for (size_t k = source.layers(); k < direct.layers(); ++k)
    EXPECT_TRUE(raster(bary, k) == raster(direct, k)) << "layer " << k;
}

TEST(TransferThroughMap, BarycentricReportsPlaneDeviationWithinTheHeightChange) {
  const test::FamilyOptions o = family("arch", test::ZChange::Everywhere);
  const Mesh base = test::make_family_base(o);
  const Mesh member = test::make_family_member(base, o, 1);
  double dz = 0;
  for (size_t v = 0; v < base.vertices(); ++v) dz = std::max(dz, std::abs(member.V[3 * v + 2] - base.V[3 * v + 2]));
  TransferStats st;
  const Slices bary = transfer_through_map(slice(base, 0.05), shuffle(base, member, 9).map,
                                           shuffle(base, member, 9).target,
                                           TransferOptions(TransferMode::Barycentric, false), &st);
  EXPECT_GT(st.max_plane_deviation, 1e-3);
  EXPECT_LE(st.max_plane_deviation, dz);
  for (size_t k = 0; k < bary.layers(); ++k)  // every point is placed on its plane
    for (size_t p = bary.contour_begin[bary.layer_begin[k]]; p < bary.contour_begin[bary.layer_begin[k + 1]]; ++p)
      ASSERT_EQ(bary.xyz[3 * p + 2], bary.layer_z[k]);
}

namespace {

// Distance in xy from (x, y) to the nearest segment of layer k's contours.
double distance_to_section(const Slices& s, size_t k, double x, double y) {
  double best = HUGE_VAL;
  for (size_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c)
    for (size_t p = s.contour_begin[c]; p < s.contour_begin[c + 1]; ++p) {
      const size_t q = p + 1 < s.contour_begin[c + 1] ? p + 1 : s.contour_begin[c];
      const double ax = s.xyz[3 * p], ay = s.xyz[3 * p + 1], ux = s.xyz[3 * q] - ax, uy = s.xyz[3 * q + 1] - ay;
      const double len2 = ux * ux + uy * uy;
      const double t = len2 > 0 ? std::clamp(((x - ax) * ux + (y - ay) * uy) / len2, 0.0, 1.0) : 0.0;
      best = std::min(best, std::hypot(x - ax - t * ux, y - ay - t * uy));
    }
  return best;
}

}  // namespace

// A real map (cross_parameterize) between two tessellations of the arch (8000 and 11000 faces),
// the target a deformed member. Barycentric transfer carries each source point and places it on
// the target's own section at its layer's height: every point lies on a segment of direct
// slicing's contours (to rounding), in the source's contours, one per source point; and the
// masks come closer to direct slicing's than the carried points themselves (the chords between
// vertex images, off the surface), which miss it most on the domes' nearly flat tops.
TEST(TransferThroughMap, BarycentricThroughACrossParameterizationLiesOnTheTargetsSection) {
  test::FamilyOptions o = family("arch");
  o.faces = 8000;
  const Mesh source_mesh = test::make_family_base(o);
  o.faces = 11000;
  const Mesh target = test::make_family_member(test::make_family_base(o), o, 1);
  ASSERT_NE(source_mesh.vertices(), target.vertices());
  const CrossParamResult r = cross_parameterize(source_mesh, target, {});
  const Slices source = slice(source_mesh, 0.1);
  TransferStats st;
  const Slices bary =
      transfer_through_map(source, r.map, target, TransferOptions(TransferMode::Barycentric, false), &st);
  const Slices direct = slice(target, source.thickness, source.z_start);
  ASSERT_EQ(bary.layers(), direct.layers());
  ASSERT_EQ(bary.layers(), source.layers());  // the same heights: z is not deformed
  EXPECT_EQ(st.unplaced_points, 0u);
  // One point per source point, in the source's contours and order, less the contours dropped
  // where the target has no surface at their height (tiny loops at domes' tops that are lower on
  // the target): per layer, the kept contours' lengths are a subsequence of the source's.
  EXPECT_EQ(bary.contours() + st.dropped_contours, source.contours());
  for (size_t k = 0; k < bary.layers(); ++k) {
    size_t c = source.layer_begin[k];
    for (size_t b = bary.layer_begin[k]; b < bary.layer_begin[k + 1]; ++b, ++c) {
      const auto length = [](const Slices& s, size_t i) { return s.contour_begin[i + 1] - s.contour_begin[i]; };
      while (c < source.layer_begin[k + 1] && length(source, c) != length(bary, b)) ++c;
      ASSERT_LT(c, source.layer_begin[k + 1]) << "layer " << k << ": contour " << b << " is no source contour";
    }
  }
  Slices chords = source;  // the carried points before placing: (1-t) Gamma(a) + t Gamma(b)
  for (size_t p = 0; p < source.points(); ++p) {
    const uint32_t* f = &source_mesh.F[3 * size_t(source.face[p])];
    double ga[3], gb[3];
    map_point(r.map, target, f[source.edge[p]], ga);
    map_point(r.map, target, f[(source.edge[p] + 1) % 3], gb);
    for (int j = 0; j < 3; ++j) chords.xyz[3 * p + j] = (1 - source.t[p]) * ga[j] + source.t[p] * gb[j];
  }
  double worst_bary = 1, worst_chords = 1;
  for (size_t k = 0; k < bary.layers(); ++k) {
    for (size_t p = bary.contour_begin[bary.layer_begin[k]]; p < bary.contour_begin[bary.layer_begin[k + 1]]; ++p) {
      ASSERT_EQ(bary.xyz[3 * p + 2], bary.layer_z[k]);
      ASSERT_LT(distance_to_section(direct, k, bary.xyz[3 * p], bary.xyz[3 * p + 1]), 1e-9) << "layer " << k;
    }
    const std::vector<uint8_t> reference = raster(direct, k);
    worst_bary = std::min(worst_bary, similarity(raster(bary, k), reference));
    worst_chords = std::min(worst_chords, similarity(raster(chords, k), reference));
  }
  EXPECT_GT(worst_bary, worst_chords);
  std::printf("arch 8000 -> 11000 faces: worst layer S = %.6f on the section, %.6f on the chords\n", worst_bary,
              worst_chords);
}

// A target a little shorter than the source (z scaled by 0.992: its top is below the source's
// top layer's slab) has one layer fewer. The source's top layer is not carried, so its contours
// are not counted as dropped: the contours carried and dropped are exactly those of the layers
// the target has (contours are dropped there too: near the top the lower target's domes do not
// reach the source's heights).
TEST(TransferThroughMap, BarycentricOntoAShorterTargetCountsOnlyCarriedLayers) {
  const Mesh base = test::make_family_base(family("arch"));
  Mesh lower = base;
  for (size_t v = 0; v < lower.vertices(); ++v) lower.V[3 * v + 2] *= 0.992;
  const Slices source = slice(base, 0.05);
  const Shuffled s = shuffle(base, lower, 4);
  TransferStats st;
  const Slices bary =
      transfer_through_map(source, s.map, s.target, TransferOptions(TransferMode::Barycentric, false), &st);
  const Slices direct = slice(s.target, source.thickness, source.z_start);
  ASSERT_EQ(direct.layers(), source.layers() - 1);
  ASSERT_EQ(bary.layers(), direct.layers());
  ASSERT_GT(source.layer_begin[source.layers()], source.layer_begin[direct.layers()]);  // the top has contours
  EXPECT_EQ(bary.contours() + st.dropped_contours, source.layer_begin[direct.layers()]);
}

TEST(TransferThroughMap, AMapWithoutUsefulSeedsStillGivesDirectSlicing) {
  const Mesh base = test::make_family_base(family("handle"));
  const Slices source = slice(base, 0.05);
  Shuffled s = shuffle(base, base, 4);
  std::fill(s.map.face.begin(), s.map.face.end(), 0u);  // every image on one face: seeds fail
  const TransferStats st = expect_exact_equals_direct(source, s);
  EXPECT_EQ(st.resliced_layers, source.layers());
}

TEST(TransferThroughMap, RefusesMismatchedInputWithClearMessages) {
  const test::FamilyOptions o = family("arch");
  const Mesh base = test::make_family_base(o);
  const Slices source = slice(base, 0.1);
  const Shuffled s = shuffle(base, base, 1);
  const TransferOptions exact(TransferMode::Exact);
  // The map's target is the shuffled copy, not the base.
  EXPECT_ERROR(transfer_through_map(source, s.map, base, exact), "not the map's target");
  // An encoding of another mesh (other faces) than the map's source.
  const Shuffled other = shuffle(base, base, 2);
  const Slices other_source = slice(other.target, 0.1);
  EXPECT_ERROR(transfer_through_map(other_source, s.map, s.target, exact), "other faces than the map's source");
  // Barycentric points are not on the target's edges: no target encoding.
  EXPECT_ERROR(transfer_through_map(source, s.map, s.target, TransferOptions(TransferMode::Barycentric, true)),
               "no target encoding");
  // A map that is not consistent (face id out of range).
  SurfaceMap broken = s.map;
  broken.face[5] = uint32_t(s.target.faces());
  EXPECT_ERROR(transfer_through_map(source, broken, s.target, exact),
               "source vertex 5 maps to target face " + std::to_string(s.target.faces()) + " but the target has " +
                   std::to_string(s.target.faces()) + " faces");
  Slices contours_only = source;
  contours_only.face.clear();
  EXPECT_ERROR(transfer_through_map(contours_only, s.map, s.target, exact), "needs an encoding");
}
