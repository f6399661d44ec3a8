// Supported prints (issue #30): members of shapes with overhangs, their supports generated on
// each member or transferred from the family's source, exported on the SL1S preset, and every
// mask stack checked layer on layer (support_checks.h): no island, no lit pixel more than 1 mm
// from the layer below. By reuse and by direct slicing, the same support structure gives the
// same masks. Elephant-foot compensation shrinks the plate's first layer only, alike in binary
// and anti-aliased masks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "error_of.h"
#include "family.h"
#include "mask_layers.h"
#include "shapes.h"
#include "slicereuse/plates/arrange_plates.h"
#include "slicereuse/plates/placement.h"
#include "slicereuse/plates/plate_job.h"
#include "slicereuse/printer/printer_presets.h"
#include "slicereuse/printfiles/compare_mask_stacks.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/supports/member_supports.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "support_checks.h"
#include "temp_folder.h"

using namespace slicereuse;

namespace {

constexpr double kThickness = 0.05;
constexpr double kZStart = 0;  // every family member's lowest vertex

test::FamilyOptions family_of(const std::string& shape) {
  test::FamilyOptions o;
  o.shape = shape;
  o.faces = 12000;
  o.height = 9;
  return o;
}

PrinterProfile sl1s(bool antialiasing) {
  PrinterProfile p = printer_preset("prusa_sl1s_speed").profile;
  p.antialiasing = antialiasing;
  return p;
}

SliceOptions slicing() {
  SliceOptions so;
  so.thickness = kThickness;
  so.z_start = kZStart;
  return so;
}

// Members placed apart on the SL1S plate, far enough for their pads.
std::vector<Mesh> placed_on_plate(const std::vector<Mesh>& members) {
  std::vector<const Mesh*> ptrs;
  std::vector<std::string> names;
  for (const Mesh& m : members) {
    ptrs.push_back(&m);
    names.push_back("m" + std::to_string(ptrs.size()));
  }
  ArrangeOptions ao;
  ao.spacing_mm = 8;
  const Arrangement a = arrange_plates(ptrs, names, printer_platform(sl1s(false)), ao);
  EXPECT_EQ(a.members.size(), 1u) << "the test wants one plate";
  std::vector<Mesh> placed;
  for (size_t m = 0; m < members.size(); ++m) placed.push_back(place_mesh(members[m], a.placement[m]));
  return placed;
}

// A plate's members with their supports: generated on each (source null) or transferred from
// the source's points, each member sliced directly or by the encoding's transfer.
struct SupportedPlate {
  std::vector<MemberSupports> supports;
  PlateJobOptions options;
};

SupportedPlate supported(const std::vector<Mesh>& placed, const Slices* encoding, const SupportPoints* source) {
  SupportedPlate s;
  for (const Mesh& m : placed) {
    const Slices own = encoding ? transfer_contours(*encoding, m, TransferOptions()) : slice_layers(m, slicing());
    s.supports.push_back(make_member_supports(m, own, kZStart, kThickness, {}, source));
  }
  for (const MemberSupports& ms : s.supports) {
    s.options.supports.push_back(&ms.tree.mesh);
    EXPECT_EQ(ms.layers_below, s.supports[0].layers_below);
  }
  s.options.layers_below = s.supports[0].layers_below;
  s.options.encoding = encoding;
  s.options.slicing = slicing();
  return s;
}

// The stack at path passes the supports' acceptance; its figures printed.
void expect_supported(const std::string& path, const PrinterProfile& profile, const std::string& what) {
  const test::StackSupport c = test::check_stack_support(path, profile);
  std::printf("%s: %zu layers, %zu islands, farthest lit pixel %.3f mm from the layer below (layer %zu)\n",
              what.c_str(), c.lit.size(), c.islands, c.max_distance_mm, c.max_distance_layer);
  EXPECT_EQ(c.islands, 0u) << what << ": first on layer " << c.first_island_layer;
  EXPECT_LE(c.max_distance_mm, 1.0) << what << ": layer " << c.max_distance_layer;
}

class SupportedPrintTest : public test::TempFolderTest {};

}  // namespace

TEST(StackSupport, FindsIslandsAndTheFarthestPixelExactly) {
  // 200 x 200 pixels of 100 um: layer 1 reaches 2 mm beyond layer 0 along x and 0.5 mm along y;
  // layer 2 adds a square resting on nothing.
  const PrinterProfile p = test::small_display();
  const Slices s = test::make_slices({{test::rect(-1, -1, 1, 1)},
                                      {test::rect(-1, -1, 3, 1.5)},
                                      {test::rect(-1, -1, 3, 1.5), test::rect(6, 6, 7, 7)}});
  std::vector<MaskImage> layers(3);
  for (size_t k = 0; k < 3; ++k) {
    layers[k].width = 200;
    layers[k].height = 200;
    layers[k].pixels = test::raster(s, k, p);
  }
  const test::StackSupport c = test::check_stack_support(layers, p);
  EXPECT_EQ(c.islands, 1u);
  EXPECT_EQ(c.first_island_layer, 2u);
  EXPECT_EQ(c.lit, (std::vector<size_t>{400, 1000, 1100}));
  // From the square's far corner pixel centre (6.95, 6.95) to layer 1's nearest, (2.95, 1.45).
  EXPECT_DOUBLE_EQ(c.max_distance_mm, std::hypot(6.95 - 2.95, 6.95 - 1.45));
  EXPECT_EQ(c.max_distance_layer, 2u);
  layers.pop_back();
  // Layer 1's pixel centre (2.95, 1.45) from layer 0's (0.95, 0.95).
  EXPECT_DOUBLE_EQ(test::check_stack_support(layers, p).max_distance_mm, std::hypot(2.0, 0.5));
}

TEST_F(SupportedPrintTest, GeneratedSupportsLeaveNoIslandsAndNoFarReach) {
  for (const std::string shape : {"sphere", "handle"}) {
    const test::FamilyOptions o = family_of(shape);
    const Mesh base = test::make_family_base(o);
    for (int i : {1, 2}) {
      const std::vector<Mesh> placed = placed_on_plate({test::make_family_member(base, o, i)});
      const SupportedPlate s = supported(placed, nullptr, nullptr);
      EXPECT_GT(s.supports[0].points.size(), 0u);
      for (bool aa : {false, true}) {
        const std::string what = shape + " member " + std::to_string(i) + (aa ? " anti-aliased" : " binary");
        const std::string out = path(shape + std::to_string(i) + (aa ? "_aa" : "_bin") + ".sl1s");
        const PlateJobStats st = export_plate(placed, s.options, sl1s(aa), out);
        EXPECT_GT(st.support_layers, s.options.layers_below);
        EXPECT_EQ(st.layers, s.options.layers_below + st.resliced_layers);
        expect_supported(out, sl1s(aa), what);
      }
    }
  }
}

TEST_F(SupportedPrintTest, TransferredSupportsByReuseGiveTheMasksOfDirectSlicing) {
  for (const std::string shape : {"sphere", "handle"}) {
    const test::FamilyOptions o = family_of(shape);
    const Mesh base = test::make_family_base(o);
    const Slices encoding = slice_layers(base, slicing());
    const SupportPoints source = make_member_supports(base, encoding, kZStart, kThickness, {}).points;
    for (int i : {1, 2}) {
      const std::vector<Mesh> placed = placed_on_plate({test::make_family_member(base, o, i)});
      SupportedPlate s = supported(placed, &encoding, &source);
      EXPECT_TRUE(s.supports[0].transferred);
      EXPECT_EQ(s.supports[0].transfer.transferred, source.size());
      const std::string what = shape + " member " + std::to_string(i) + " by reuse";
      const std::string reused = path(shape + std::to_string(i) + "_reuse.sl1s");
      const PlateJobStats r = export_plate(placed, s.options, sl1s(true), reused);
      EXPECT_GT(r.transferred_layers, 0u);
      expect_supported(reused, sl1s(true), what);
      // The same support structure on the member sliced directly: the same masks.
      s.options.encoding = nullptr;
      const std::string direct = path(shape + std::to_string(i) + "_direct.sl1s");
      export_plate(placed, s.options, sl1s(true), direct);
      const StackComparison c = compare_mask_stacks(reused, direct, "");
      EXPECT_EQ(c.max_grey_difference, 0) << what << ": layer " << c.max_grey_difference_layer;
    }
  }
}

TEST_F(SupportedPrintTest, APlateOfTwoSupportedMembersEachWay) {
  for (const std::string shape : {"sphere", "handle"}) {
    const test::FamilyOptions o = family_of(shape);
    const Mesh base = test::make_family_base(o);
    const Slices encoding = slice_layers(base, slicing());
    const SupportPoints source = make_member_supports(base, encoding, kZStart, kThickness, {}).points;
    const std::vector<Mesh> placed =
        placed_on_plate({test::make_family_member(base, o, 1), test::make_family_member(base, o, 2)});
    const std::string direct = path(shape + "_plate_direct.sl1s"), reused = path(shape + "_plate_reuse.sl1s");
    export_plate(placed, supported(placed, nullptr, nullptr).options, sl1s(false), direct);
    expect_supported(direct, sl1s(false), shape + " plate, generated, direct");
    const SupportedPlate s = supported(placed, &encoding, &source);
    const PlateJobStats r = export_plate(placed, s.options, sl1s(true), reused);
    EXPECT_EQ(r.ranges, 0u);  // made where drawn
    expect_supported(reused, sl1s(true), shape + " plate, transferred, by reuse");
  }
}

TEST_F(SupportedPrintTest, WithoutSupportsTheCheckFindsIslands) {
  // The sphere's member on the plate: its first layer is a speck of its widest, and every layer
  // rests on the one below. Raised as its supports would raise it, but without them, its first
  // layer rests on nothing.
  const test::FamilyOptions o = family_of("sphere");
  const std::vector<Mesh> placed =
      placed_on_plate({test::make_family_member(test::make_family_base(o), o, 1)});
  PlateJobOptions on_plate;
  on_plate.slicing = slicing();
  export_plate(placed, on_plate, sl1s(false), path("standing.sl1s"));
  const test::StackSupport standing = test::check_stack_support(path("standing.sl1s"), sl1s(false));
  const size_t widest = *std::max_element(standing.lit.begin(), standing.lit.end());
  std::printf("sphere standing, unsupported: first layer %zu lit pixels of the widest %zu; %zu islands, farthest "
              "%.3f mm\n",
              standing.lit[0], widest, standing.islands, standing.max_distance_mm);
  EXPECT_LT(standing.lit[0] * 50, widest);
  EXPECT_EQ(standing.islands, 0u);
  PlateJobOptions raised = on_plate;
  raised.layers_below = support_layers_below(SupportTreeOptions(), kThickness);
  export_plate(placed, raised, sl1s(false), path("raised.sl1s"));
  const test::StackSupport c = test::check_stack_support(path("raised.sl1s"), sl1s(false));
  std::printf("sphere raised, unsupported: %zu islands (first on layer %zu)\n", c.islands, c.first_island_layer);
  EXPECT_GT(c.islands, 0u);
  EXPECT_EQ(c.first_island_layer, raised.layers_below);
}

// The SL1S's 0.2 mm elephant-foot compensation fades over its 10 faded layers from the pad's
// bottom, as PrusaSlicer's does (faded_layers.h): each of the plate's layers 0 to 8 lights fewer
// pixels than uncompensated, by less on each layer up, and layers 9 and above are untouched. The
// box's flat bottom takes many points, so its pad is broad: a pad under one or two pillars is
// small enough that its sloping walls lengthen its outline faster than the fade thins the band.
TEST_F(SupportedPrintTest, ElephantFootShrinksThePlatesFadedLayersAlikeBinaryAndAntiAliased) {
  const test::FamilyOptions o = family_of("box");
  const std::vector<Mesh> placed =
      placed_on_plate({test::make_family_member(test::make_family_base(o), o, 1)});
  const SupportedPlate s = supported(placed, nullptr, nullptr);
  PrinterProfile plain = sl1s(false);
  plain.elephant_foot_mm = 0;
  ASSERT_EQ(sl1s(false).elephant_foot_mm, 0.2);
  ASSERT_EQ(sl1s(false).faded_layers, 10);
  export_plate(placed, s.options, plain, path("plain.sl1s"));
  export_plate(placed, s.options, sl1s(false), path("binary.sl1s"));
  PrinterProfile threshold = sl1s(true);
  threshold.gamma = 0;  // anti-aliased at gamma 0: the binary threshold
  export_plate(placed, s.options, threshold, path("gamma0.sl1s"));
  const StackComparison c = compare_mask_stacks(path("plain.sl1s"), path("binary.sl1s"), "");
  const test::StackSupport before = test::check_stack_support(path("plain.sl1s"), plain);
  const test::StackSupport after = test::check_stack_support(path("binary.sl1s"), plain);
  ASSERT_GT(s.options.layers_below, 9u);  // the faded layers are the pad's
  std::vector<size_t> fewer;
  for (size_t k = 0; k < 9; ++k) {
    ASSERT_LT(after.lit[k], before.lit[k]) << "layer " << k;
    fewer.push_back(before.lit[k] - after.lit[k]);
    if (k > 0) EXPECT_LT(fewer[k], fewer[k - 1]) << "layer " << k;
  }
  std::printf("elephant foot 0.2 mm: plate layer 0 %zu -> %zu lit pixels, layer 8 %zu -> %zu\n", before.lit[0],
              after.lit[0], before.lit[8], after.lit[8]);
  for (size_t k = 9; k < c.layers.size(); ++k) EXPECT_EQ(c.layers[k].max_grey_difference, 0) << "layer " << k;
  EXPECT_EQ(compare_mask_stacks(path("binary.sl1s"), path("gamma0.sl1s"), "").max_grey_difference, 0);
}

TEST_F(SupportedPrintTest, SupportsJoinThePlateBelowTheirMembersAlikeInEveryWayOfMakingIt) {
  // Two members of a family (z edited in a band, so transfer re-slices some layers), each on a
  // column standing 7 layers below z_start and reaching 0.3 mm into it: the plate gains the 7
  // layers, the supports are sliced directly, and reuse (made where drawn and in ranges) and
  // direct slicing (whole and in ranges) give the same masks, with the faded layers compensated.
  test::FamilyOptions o;
  o.faces = 1500;
  o.height = 4;
  o.z_change = test::ZChange::Band;
  const Mesh base = test::make_family_base(o);
  const std::vector<Mesh> placed =
      placed_on_plate({test::make_family_member(base, o, 1), test::make_family_member(base, o, 2)});
  SliceOptions so = slicing();
  so.thickness = 0.1;
  const Slices encoding = slice_layers(base, so);
  constexpr size_t below = 7;
  std::vector<Mesh> columns;
  size_t member_layers = 0, column_layers = 0;
  for (const Mesh& m : placed) {
    double x = 0, y = 0;
    for (size_t v = 0; v < m.vertices(); ++v) x += m.V[3 * v], y += m.V[3 * v + 1];
    x /= double(m.vertices()), y /= double(m.vertices());
    columns.push_back(test::make_box(x - 1, y - 1, kZStart - below * so.thickness, x + 1, y + 1, kZStart + 0.3));
    member_layers += slice_layers(m, so).layers();
    column_layers += below + 3;
  }
  PlateJobOptions reuse;
  reuse.encoding = &encoding;
  reuse.supports = {&columns[0], &columns[1]};
  reuse.layers_below = below;
  PlateJobOptions reuse_ranges = reuse, direct = reuse;
  reuse_ranges.range_budget_bytes = 2000;
  direct.encoding = nullptr;
  direct.slicing = so;
  PlateJobOptions direct_ranges = direct;
  direct_ranges.range_budget_bytes = 2000;
  for (bool aa : {false, true}) {
    const PrinterProfile profile = sl1s(aa);
    std::vector<std::string> outputs;
    for (const PlateJobOptions* job : {&reuse, &reuse_ranges, &direct, &direct_ranges}) {
      outputs.push_back(path("plate" + std::to_string(outputs.size()) + (aa ? "_aa" : "_bin")));
      const PlateJobStats st = export_plate(placed, *job, profile, outputs.back());
      EXPECT_EQ(st.layers, below + slice_layers(placed[0], so).layers());
      EXPECT_EQ(st.transferred_layers + st.resliced_layers, member_layers);
      EXPECT_EQ(st.support_layers, column_layers);
      EXPECT_EQ(st.ranges == 0, job == &reuse);
      if (job == &reuse_ranges || job == &direct_ranges) EXPECT_GT(st.ranges, 2u);
    }
    for (size_t i = 1; i < outputs.size(); ++i)
      EXPECT_EQ(compare_mask_stacks(outputs[0], outputs[i], "").max_grey_difference, 0) << outputs[i];
    // Below z_start only the columns: each layer lit on two 2 x 2 mm squares (40 x 40 pixels),
    // shrunk by the SL1S's 0.2 mm on layer 0, fading by a ninth a layer (faded_layers.h).
    const test::StackSupport c = test::check_stack_support(outputs[0], profile);
    ASSERT_EQ(profile.faded_layers, 10);
    for (size_t k = 0; k < below; ++k) {
      const double side = (2 - 2 * double(9 - k) * 0.2 / 9) / 0.05;
      EXPECT_NEAR(double(c.lit[k]), 2 * side * side, 2 * 4 * 41) << "layer " << k;
      if (k > 0) EXPECT_LT(c.lit[k - 1], c.lit[k]) << "layer " << k;
    }
  }
  PlateJobOptions one = direct;
  one.supports.pop_back();
  EXPECT_EQ(test::error_of([&] { export_plate(placed, one, sl1s(false), path("refused")); }),
            "a plate of 2 members was given 1 supports: one (or none) per member");
}
