// Exact transfer must equal direct slicing of every family member, layer by layer.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "error_of.h"
#include "family.h"
#include "sections.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "slicereuse/util/error.h"
#include "unsampled_edge.h"

using namespace slicereuse;

namespace {

Slices slice(const Mesh& m, double h) {
  SliceOptions o;
  o.thickness = h;
  return slice_layers(m, o);
}

// Transfer without the target's encoding gives the same contours, and no encoding; transfer
// through precomputed edge ends gives the same contours and encoding.
void expect_same_points_without_encoding(const Slices& source, const Mesh& member, const Slices& full) {
  const Slices bare = transfer_contours(source, member, TransferOptions(TransferMode::Exact, false));
  EXPECT_TRUE(bare.face.empty() && bare.edge.empty() && bare.t.empty());
  EXPECT_EQ(bare.layer_begin, full.layer_begin);
  EXPECT_EQ(bare.contour_begin, full.contour_begin);
  EXPECT_TRUE(bare.xyz == full.xyz);
  const Slices prepared =
      transfer_contours(source, encoded_edge_ends(source, member), member, TransferOptions(TransferMode::Exact));
  EXPECT_EQ(prepared.layer_begin, full.layer_begin);
  EXPECT_EQ(prepared.contour_begin, full.contour_begin);
  EXPECT_TRUE(prepared.xyz == full.xyz && prepared.face == full.face && prepared.edge == full.edge &&
              prepared.t == full.t);
}

// The ear family the range, layer and progress tests transfer: small, with the given z change;
// its base sliced at 0.05 mm with encoding (the source) and the source's edge ends.
struct EarFamily {
  test::FamilyOptions options;
  Mesh base;
  Slices source;
  Buffer<uint32_t> ends;
};

EarFamily ear_family(test::ZChange z) {
  EarFamily f;
  f.options.shape = "ear";
  f.options.faces = 6000;
  f.options.height = 10;
  f.options.seed = 7;
  f.options.z_change = z;
  f.base = test::make_family_base(f.options);
  f.source = slice(f.base, 0.05);
  f.ends = encoded_edge_ends(f.source, f.base);
  return f;
}

struct FamilyCase {
  std::string shape;
  test::ZChange z_change;
};

class TransferFamily : public ::testing::TestWithParam<FamilyCase> {};

}  // namespace

// Members 1-4 transferred from member 0's encoding equal their direct slicing, and the layer
// counts show which path did it: x-y members transfer every layer; a z change in one band of
// heights re-slices some layers and transfers most; a z change everywhere fails most layers'
// count certificate, so the transfer takes its fallback and slices every layer at once.
TEST_P(TransferFamily, ExactTransferEqualsDirectSlicing) {
  test::FamilyOptions o;
  o.shape = GetParam().shape;
  o.faces = 6000;
  o.height = 10;
  o.seed = 7;
  o.z_change = GetParam().z_change;
  const Mesh base = test::make_family_base(o);
  const Slices source = slice(base, 0.05);
  size_t other_heights = 0;
  for (int i = 1; i <= 4; ++i) {
    SCOPED_TRACE("member " + std::to_string(i));
    const Mesh member = test::make_family_member(base, o, i);
    TransferStats stats;
    const Slices moved = transfer_contours(source, member, TransferOptions(TransferMode::Exact), &stats);
    SliceOptions same_plate;
    same_plate.thickness = source.thickness;
    same_plate.z_start = source.z_start;
    const Slices direct = slice_layers(member, same_plate);
    EXPECT_EQ(stats.transferred_layers + stats.resliced_layers, direct.layers());
    switch (o.z_change) {
      case test::ZChange::None:
        EXPECT_EQ(stats.resliced_layers, 0u);
        break;
      case test::ZChange::Band:
        EXPECT_GT(stats.resliced_layers, 0u);
        EXPECT_GT(stats.transferred_layers, 2 * stats.resliced_layers);
        break;
      case test::ZChange::Everywhere:
        EXPECT_EQ(stats.transferred_layers, 0u);  // the fallback: every layer sliced at once
        break;
    }
    other_heights += direct.layers() != source.layers();
    ASSERT_TRUE(moved.has_encoding());
    EXPECT_EQ(moved.fingerprint, source.fingerprint);
    EXPECT_EQ(moved.points(), direct.points());
    test::expect_same_sections(moved, direct);
    expect_same_points_without_encoding(source, member, moved);
  }
  // Only a change everywhere moves the top: taller and shorter members exercise the top layers.
  if (o.z_change == test::ZChange::Everywhere)
    EXPECT_GT(other_heights, 0u);
  else
    EXPECT_EQ(other_heights, 0u);
}

INSTANTIATE_TEST_SUITE_P(Shapes, TransferFamily,
                         ::testing::Values(FamilyCase{"arch", test::ZChange::None},
                                           FamilyCase{"ear", test::ZChange::None},
                                           FamilyCase{"handle", test::ZChange::None},
                                           FamilyCase{"torus", test::ZChange::None},
                                           FamilyCase{"arch", test::ZChange::Band},
                                           FamilyCase{"ear", test::ZChange::Band},
                                           FamilyCase{"handle", test::ZChange::Band},
                                           FamilyCase{"torus", test::ZChange::Band},
                                           FamilyCase{"arch", test::ZChange::Everywhere}),
                         [](const auto& info) {
                           const test::ZChange z = info.param.z_change;
                           return info.param.shape + (z == test::ZChange::None   ? ""
                                                      : z == test::ZChange::Band ? "_z_band"
                                                                                 : "_z_everywhere");
                         });

TEST(TransferContours, BarycentricEqualsExactWhenZIsUnchanged) {
  test::FamilyOptions o;
  o.faces = 5000;
  o.height = 8;
  const Mesh base = test::make_family_base(o);
  const Mesh member = test::make_family_member(base, o, 2);
  const Slices source = slice(base, 0.05);
  TransferStats st;
  const Slices bary = transfer_contours(source, member, TransferOptions(TransferMode::Barycentric), &st);
  const Slices exact = transfer_contours(source, member, TransferOptions(TransferMode::Exact));
  EXPECT_LT(st.max_plane_deviation, 1e-12);
  ASSERT_EQ(bary.xyz.size(), exact.xyz.size());
  for (size_t i = 0; i < bary.xyz.size(); ++i) ASSERT_NEAR(bary.xyz[i], exact.xyz[i], 1e-12) << i;
}

TEST(TransferContours, BarycentricReportsPointsLeavingThePlane) {
  test::FamilyOptions o;
  o.faces = 5000;
  o.height = 8;
  o.z_change = test::ZChange::Everywhere;
  const Mesh base = test::make_family_base(o);
  const Mesh member = test::make_family_member(base, o, 1);
  TransferStats st;
  const Slices bary =
      transfer_contours(slice(base, 0.05), member, TransferOptions(TransferMode::Barycentric), &st);
  double worst = 0;
  for (size_t k = 0; k < bary.layers(); ++k)
    for (size_t p = bary.contour_begin[bary.layer_begin[k]]; p < bary.contour_begin[bary.layer_begin[k + 1]]; ++p)
      worst = std::max(worst, std::abs(bary.xyz[3 * p + 2] - bary.layer_z[k]));
  EXPECT_GT(worst, 1e-3);
  EXPECT_EQ(st.max_plane_deviation, worst);
}

TEST(TransferContours, RefusesAMeshWithOtherFaces) {
  test::FamilyOptions o;
  o.faces = 2000;
  const Mesh base = test::make_family_base(o);
  const Slices source = slice(base, 0.1);
  Mesh other = base;
  std::swap(other.F[0], other.F[1]);
  try {
    transfer_contours(source, other, TransferOptions(TransferMode::Exact));
    FAIL() << "a target with other faces was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("faces differ"), std::string::npos) << e.what();
  }
  other = base;
  other.F.resize(other.F.size() - 3);
  EXPECT_THROW(transfer_contours(source, other, TransferOptions(TransferMode::Exact)), Error);
  Slices contours_only = source;
  contours_only.face.clear();
  EXPECT_THROW(transfer_contours(contours_only, base, TransferOptions(TransferMode::Exact)), Error);
  Buffer<uint32_t> ends = encoded_edge_ends(source, base);
  EXPECT_THROW(encoded_edge_ends(source, other), Error);
  ends.pop_back();
  EXPECT_THROW(transfer_contours(source, ends, base, TransferOptions(TransferMode::Exact)), Error);
}

TEST(TransferContours, LocalZEditReslicesOnlyTheLayersItTouches) {
  test::FamilyOptions o;
  o.shape = "ear";
  o.faces = 6000;
  o.height = 10;
  const Mesh base = test::make_family_base(o);
  const double h = 0.05;
  const Slices source = slice(base, h);
  Mesh member = test::make_family_member(base, o, 3);
  // Raise the top vertex by 3.2 layers (the part grows by 3 or 4 layers) and nudge one vertex
  // at mid height: only the layers near those vertices may change.
  size_t top = 0, mid = 0;
  for (size_t v = 0; v < member.vertices(); ++v) {
    if (member.V[3 * v + 2] > member.V[3 * top + 2]) top = v;
    if (std::abs(member.V[3 * v + 2] - 5) < std::abs(member.V[3 * mid + 2] - 5)) mid = v;
  }
  member.V[3 * top + 2] += 3.2 * h;
  member.V[3 * mid + 2] += 0.7 * h;
  TransferStats stats;
  const Slices moved = transfer_contours(source, member, TransferOptions(TransferMode::Exact), &stats);
  SliceOptions same_plate;
  same_plate.thickness = h;
  same_plate.z_start = source.z_start;
  const Slices direct = slice_layers(member, same_plate);
  EXPECT_GE(direct.layers(), source.layers() + 3);
  EXPECT_GT(stats.resliced_layers, direct.layers() - source.layers());
  EXPECT_LT(stats.resliced_layers, 30u);
  EXPECT_EQ(stats.transferred_layers + stats.resliced_layers, direct.layers());
  test::expect_same_sections(moved, direct);
  expect_same_points_without_encoding(source, member, moved);
}

// ExactTransfer, a range of layers at a time (as a build plate transfers a member), gives every
// range's layers as direct slicing of the member on those planes does, re-sliced layers and the
// layers above the source's top included; for a member transferred on every layer, the same
// points, bit for bit and in the same order, as the whole transfer. Both ways of finding the
// edges (the faces, the edge ends) agree, and a range beyond the member's layers is refused.
TEST(TransferContours, ExactTransferInRangesEqualsTheWholeTransfer) {
  for (const test::ZChange z : {test::ZChange::None, test::ZChange::Band, test::ZChange::Everywhere}) {
    SCOPED_TRACE(int(z));
    const auto [o, base, source, ends] = ear_family(z);
    const TransferOptions bare(TransferMode::Exact, false);
    for (int i = 1; i <= 4; ++i) {
      SCOPED_TRACE("member " + std::to_string(i));
      const Mesh member = test::make_family_member(base, o, i);
      TransferStats whole_stats;
      const Slices whole = transfer_contours(source, member, bare, &whole_stats);
      const ExactTransfer by_faces(source, member), by_ends(source, ends, member);
      ASSERT_EQ(by_faces.layers(), whole.layers());
      ASSERT_EQ(by_ends.layers(), whole.layers());
      const size_t L = whole.layers();
      // A one-layer range, a short one, and the rest in ranges of 64 (the last one shorter).
      std::vector<size_t> first{0, 1, 8};
      while (first.back() + 64 < L) first.push_back(first.back() + 64);
      first.push_back(L);
      size_t transferred = 0, resliced = 0;
      for (size_t r = 0; r + 1 < first.size(); ++r) {
        const size_t a = first[r], b = first[r + 1];
        SCOPED_TRACE("layers " + std::to_string(a) + " to " + std::to_string(b));
        TransferStats st;
        const Slices part = by_ends.layers(a, b, &st);
        transferred += st.transferred_layers;
        resliced += st.resliced_layers;
        EXPECT_EQ(st.transferred_layers + st.resliced_layers, b - a);
        EXPECT_FALSE(part.has_encoding());
        EXPECT_DOUBLE_EQ(part.z_start, source.z_start + double(a) * source.thickness);
        const Slices direct =
            slice_planes(member, {whole.layer_z.begin() + long(a), whole.layer_z.begin() + long(b)}, {}, false);
        test::expect_same_sections(part, direct);
        const Slices other = by_faces.layers(a, b);
        EXPECT_TRUE(other.xyz == part.xyz && other.contour_begin == part.contour_begin);
        if (whole_stats.resliced_layers == 0) {
          const uint64_t p0 = whole.contour_begin[whole.layer_begin[a]];
          const uint64_t p1 = whole.contour_begin[whole.layer_begin[b]];
          ASSERT_EQ(part.points(), p1 - p0);
          EXPECT_TRUE(std::equal(part.xyz.begin(), part.xyz.end(), whole.xyz.begin() + long(3 * p0)));
          for (size_t k = 0; k <= b - a; ++k)
            EXPECT_EQ(part.contour_begin[part.layer_begin[k]] + p0, whole.contour_begin[whole.layer_begin[a + k]]);
        }
      }
      EXPECT_EQ(transferred + resliced, L);
      if (z == test::ZChange::None) EXPECT_EQ(resliced, 0u);
      if (z == test::ZChange::Band) EXPECT_GT(resliced, 0u);
      EXPECT_EQ(by_ends.layers(L, L).layers(), 0u);
      try {
        by_ends.layers(2, L + 1);
        ADD_FAILURE() << "a range beyond the member's layers was accepted";
      } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("the target has " + std::to_string(L)), std::string::npos) << e.what();
      }
    }
  }
}

// ExactTransfer a layer at a time (as a plate's masks make each member's layers): every layer it
// lets through (transferable) and certifies equals that layer of the ranges, bit for bit, into
// the same reused Slices, also from the vertices in the order the points use them (VertexOrder);
// the others are refused in words. A layer whose sample and counts pass
// but whose whole certificate fails (a vertex moved across an unsampled edge; in z-changed
// members, a few layers) is reported, by certified as well, and the ranges re-slice it.
TEST(TransferContours, ExactTransferALayerAtATimeEqualsItsRanges) {
  for (const test::ZChange z : {test::ZChange::None, test::ZChange::Band, test::ZChange::Everywhere}) {
    SCOPED_TRACE(int(z));
    const auto [o, base, source, ends] = ear_family(z);
    Mesh member = test::make_family_member(base, o, 2);
    size_t broken = SIZE_MAX;
    if (z == test::ZChange::None) ASSERT_TRUE(test::move_vertex_across_unsampled_edge(source, member, &broken));
    const VertexOrder order = vertex_order(ends);
    const ExactTransfer by_ends(source, ends, member), by_faces(source, member), by_order(source, ends, member, &order);
    Slices one, ordered;
    size_t transferable = 0, certified = 0;
    for (size_t k = 0; k < by_ends.layers(); ++k) {
      SCOPED_TRACE("layer " + std::to_string(k));
      TransferStats st;
      const Slices range = by_ends.layers(k, k + 1, &st);
      ASSERT_EQ(by_faces.transferable(k), by_ends.transferable(k));
      if (!by_ends.transferable(k)) {
        EXPECT_EQ(st.resliced_layers, 1u);
        const std::string e = test::error_of([&] { by_ends.layer_into(k, one); });
        EXPECT_NE(e.find("layer " + std::to_string(k) + " cannot be transferred alone"), std::string::npos) << e;
        continue;
      }
      ++transferable;
      const bool whole = by_ends.layer_into(k, one);
      Slices other;
      EXPECT_EQ(by_faces.layer_into(k, other), whole);
      EXPECT_EQ(by_ends.certified(k), whole);
      EXPECT_EQ(by_faces.certified(k), whole);
      EXPECT_EQ(by_order.certified(k), whole);
      EXPECT_EQ(by_order.layer_into(k, ordered), whole);
      // A member changed in z fails the whole certificate on some layers that pass the sample.
      if (z == test::ZChange::None) EXPECT_EQ(whole, k != broken);
      if (!whole) {
        EXPECT_EQ(st.resliced_layers, 1u);
        continue;
      }
      ++certified;
      EXPECT_EQ(st.transferred_layers, 1u);
      EXPECT_EQ(one.layer_z, range.layer_z);
      EXPECT_EQ(one.layer_begin, range.layer_begin);
      EXPECT_EQ(one.contour_begin, range.contour_begin);
      EXPECT_EQ(one.contour_open, range.contour_open);
      EXPECT_TRUE(one.xyz == range.xyz && other.xyz == range.xyz && ordered.xyz == range.xyz);
      EXPECT_DOUBLE_EQ(one.z_start, range.z_start);
      EXPECT_EQ(one.thickness, source.thickness);
      EXPECT_FALSE(one.has_encoding());
    }
    // Every vertex a point uses, once, numbered in the order of first use.
    std::vector<uint32_t> sorted = order.vertex;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
    for (size_t i = 0; i < ends.size(); ++i) ASSERT_EQ(order.vertex[order.ends[i]], ends[i]);
    uint32_t next = 0;  // a point's vertex is one numbered before, or the next number
    for (uint32_t v : order.ends) {
      ASSERT_LE(v, next);
      next = std::max(next, v + 1);
    }
    EXPECT_EQ(next, order.vertex.size());
    Buffer<uint32_t> fewer = ends;
    fewer.resize(ends.size() - 2);
    const VertexOrder other_order = vertex_order(fewer);
    EXPECT_NE(test::error_of([&] { ExactTransfer(source, ends, member, &other_order); })
                  .find("a vertex order was made for another encoding"),
              std::string::npos);
    const std::string beyond = test::error_of([&] { by_ends.layer_into(by_ends.layers(), one); });
    EXPECT_NE(beyond.find("the target has " + std::to_string(by_ends.layers()) + " layers"), std::string::npos)
        << beyond;
    if (z == test::ZChange::None) {  // every layer but the broken one
      EXPECT_EQ(transferable, by_ends.layers());
      EXPECT_EQ(certified, by_ends.layers() - 1);
    }
    if (z == test::ZChange::Band) EXPECT_LT(transferable, by_ends.layers());
    EXPECT_GT(certified, 0u);
  }
}


// The progress a transfer reports never goes back, whichever way it goes: every layer
// transferred, some re-sliced and spliced in (a z change in a band), every layer sliced (a z
// change everywhere); and it ends at 1.
TEST(TransferContours, ProgressNeverGoesBack) {
  for (const test::ZChange z : {test::ZChange::None, test::ZChange::Band, test::ZChange::Everywhere}) {
    SCOPED_TRACE(int(z));
    const auto [o, base, source, ends] = ear_family(z);
    const Mesh member = test::make_family_member(base, o, 2);
    std::vector<double> seen;
    TransferStats st;
    transfer_contours(source, member, TransferOptions(TransferMode::Exact), &st, [&](double f, const char*) {
      seen.push_back(f);
      return true;
    });
    ASSERT_FALSE(seen.empty());
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_EQ(seen.back(), 1.0);
    if (z == test::ZChange::Band) EXPECT_GT(st.resliced_layers, 0u);
    if (z == test::ZChange::Band) EXPECT_GT(st.transferred_layers, 0u);
  }
}
