// Labels on a side (#36): a box's front, back, left and right, each upright and readable from
// outside; only the layers the label's box spans change, each by the letters' section (computed
// here from the font's loops, apart from the product's Clipper cut) times the depth, nothing
// outside the side's band; a member turned on the plate keeps its label on its own side; the
// same masks by reuse as by direct slicing; no fit reported in words, and allow_unlabelled
// prints the member without it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "error_of.h"
#include "shapes.h"
#include "slicereuse/plates/placement.h"
#include "slicereuse/plates/plate_job.h"
#include "slicereuse/printfiles/compare_mask_stacks.h"
#include "slicereuse/regions/clip_regions.h"
#include "slicereuse/regions/label_region.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/slicing/slice_layers.h"
#include "temp_folder.h"

using namespace slicereuse;
using ClipperLib::Paths;

namespace {

PrinterProfile display() {
  PrinterProfile p;
  p.width_px = 600;  // 60 x 50 mm at 100 um
  p.height_px = 500;
  p.pixel_size_x_um = p.pixel_size_y_um = 100;
  return p;
}

Paths rect(double x0, double y0, double x1, double y1) {
  return {{{region_units(x0), region_units(y0)}, {region_units(x1), region_units(y0)},
           {region_units(x1), region_units(y1)}, {region_units(x0), region_units(y1)}}};
}

// The total length of the horizontal line at height y inside a region (mm, the region in
// Clipper units, its loops not crossing): its crossings with the loops' edges, paired in order.
double section_mm(const Paths& region, double y) {
  std::vector<double> xs;
  for (const ClipperLib::Path& loop : region)
    for (size_t i = 0; i < loop.size(); ++i) {
      const double ay = double(loop[i].Y) / kRegionScale, by = double(loop[(i + 1) % loop.size()].Y) / kRegionScale;
      if ((ay <= y) == (by <= y)) continue;
      const double ax = double(loop[i].X) / kRegionScale, bx = double(loop[(i + 1) % loop.size()].X) / kRegionScale;
      xs.push_back(ax + (y - ay) / (by - ay) * (bx - ax));
    }
  std::sort(xs.begin(), xs.end());
  double length = 0;
  for (size_t i = 0; i + 1 < xs.size(); i += 2) length += xs[i + 1] - xs[i];
  return length;
}

class SideLabelTest : public test::TempFolderTest {
 protected:
  // A plate's options: 0.1 mm layers, the members so named, labelled (when `labels`) on `side`.
  static PlateJobOptions options(std::vector<std::string> names, std::vector<std::string> labels = {},
                                 LabelSide side = LabelSide::Front) {
    PlateJobOptions o;
    o.slicing.thickness = 0.1;
    o.names = std::move(names);
    o.labels = std::move(labels);
    o.label.side = side;
    return o;
  }
  const std::vector<Mesh> box{test::make_box(-20, -10, 0, 20, 10, 12, 4)};  // 40 x 20 x 12 mm

  // Each layer's region of the one member's part as the plate job cuts it (before the elephant
  // foot), the plate written to `name`.
  std::vector<Paths> regions(const std::vector<Mesh>& placed, const PlateJobOptions& options, const std::string& name) {
    PlateJobOptions o = options;
    std::vector<Paths> out;
    o.whole_stack = [&](const std::vector<SlicePart>& parts) {
      const Slices& s = parts.at(0).slices;
      for (size_t k = 0; k < s.layers(); ++k) out.push_back(layer_region(LayerView(s, k)));
    };
    last = export_plate(placed, o, display(), path(name));
    return out;
  }
  PlateJobStats last;
};

}  // namespace

// A 40 x 20 x 12 mm box, "CASE1" on its front (-y) side at 7.5 mm (31.7 mm long, 33.7 with its
// margins: the 40 mm face holds it), on 0.1 mm layers: its box from layer 22's bottom (of the
// bottoms 1 mm clear of the box's ends, the nearest the middle, the lower of two) up 7.5 mm,
// over the planes of layers 22 to 96. Each of those loses the letters' section times 3 mm, in
// the band 3 mm deep behind the front; no other layer changes.
TEST_F(SideLabelTest, CutsTheLettersSectionTimesTheDepthOnlyInTheLayersItsBoxSpans) {
  const std::vector<Paths> plain = regions(box, options({"box"}), "plain");
  const std::vector<Paths> cut = regions(box, options({"box"}, {"CASE1"}), "front");
  ASSERT_EQ(last.label_heights_mm, std::vector<double>{7.5});
  EXPECT_NEAR(last.label_places[0][0], 0, 1e-6);
  EXPECT_NEAR(last.label_places[0][1], -10, 1e-6);
  EXPECT_NEAR(last.label_places[0][2], 2.2 + 3.75, 1e-9);
  ASSERT_EQ(cut.size(), 120u);
  const Paths letters = label_region("CASE1", 7.5, false);
  const double half = 0.5 * label_box_mm("CASE1", 7.5)[0];
  for (size_t k = 0; k < cut.size(); ++k) {
    const double plane = (double(k) + 0.5) * 0.1;
    if (k < 22 || k > 96) {
      EXPECT_EQ(cut[k], plain[k]) << "layer " << k;
      continue;
    }
    const double width = section_mm(letters, plane - 5.95);
    ASSERT_GT(width, 0) << "layer " << k;  // the E's upright spans the whole height
    const Paths taken = clip_regions(plain[k], cut[k], ClipperLib::ctDifference);
    EXPECT_NEAR(region_area_mm2(taken), 3 * width, 1e-4) << "layer " << k;
    EXPECT_TRUE(clip_regions(taken, rect(-half - 1e-6, -10 - 1e-6, half + 1e-6, -7 + 1e-6), ClipperLib::ctDifference)
                    .empty())
        << "layer " << k;
    EXPECT_TRUE(clip_regions(cut[k], plain[k], ClipperLib::ctDifference).empty()) << "layer " << k;  // only cut
  }
  // The masks: exactly the layers of the box differ.
  const StackComparison c = compare_mask_stacks(path("plain"), path("front"), "");
  ASSERT_EQ(c.layers.size(), 120u);
  for (size_t k = 0; k < c.layers.size(); ++k)
    EXPECT_EQ(c.layers[k].max_grey_difference > 0, k >= 22 && k <= 96) << "layer " << k;
}

// Each side reads from outside: "L"'s upright is on the reader's left. High in the box only the
// upright is cut (the foot is at the bottom), so the cut lies left of the face's middle as seen
// from that side: front (seen from -y) at x < 0, back at x > 0, left (seen from -x) at y > 0,
// right at y < 0. A member turned a quarter on the plate has its own front facing +x.
TEST_F(SideLabelTest, EachSideReadsFromOutsideAndATurnedMemberKeepsItsOwnSide) {
  const std::vector<Paths> plain = regions(box, options({"box"}), "plain");
  PlateJobOptions o = options({"box"}, {"L"});
  struct Expected {
    LabelSide side;
    double x, y;      // the label's centre on the face
    double left[2];   // a point of the upright's cut: x, y
  };
  // "L" at 7.5 mm: strokes 0.9 mm, unit 1.1 mm; the upright is 2.2 mm left of the glyph's middle.
  for (const Expected& e : {Expected{LabelSide::Front, 0, -10, {-2.2, -9}}, Expected{LabelSide::Back, 0, 10, {2.2, 9}},
                            Expected{LabelSide::Left, -20, 0, {-19, 2.2}}, Expected{LabelSide::Right, 20, 0, {19, -2.2}}}) {
    o.label.side = e.side;
    const std::vector<Paths> cut = regions(box, o, "side");
    ASSERT_EQ(last.label_heights_mm, std::vector<double>{7.5});
    EXPECT_NEAR(last.label_places[0][0], e.x, 1e-6);
    EXPECT_NEAR(last.label_places[0][1], e.y, 1e-6);
    const size_t high = 90;  // plane 9.05 mm: 3.1 mm above the label's middle, above the foot
    const Paths taken = clip_regions(plain[high], cut[high], ClipperLib::ctDifference);
    EXPECT_NEAR(region_area_mm2(taken), 0.9 * 3, 1e-4);  // the upright's stroke, 3 mm deep
    EXPECT_TRUE(region_covers(taken, {region_units(e.left[0]), region_units(e.left[1])})) << int(e.side);
    EXPECT_FALSE(region_covers(taken, {region_units(-e.left[0]), region_units(-e.left[1])})) << int(e.side);
  }
  // Turned a quarter (its front now faces +x), the member's own front holds the label.
  const std::vector<Mesh> turned{place_mesh(box[0], {90, 0, 0})};
  o.label.side = LabelSide::Front;
  o.label_turns_deg = {90};
  regions(turned, o, "turned");
  EXPECT_NEAR(last.label_places[0][0], 10, 1e-6);
  EXPECT_NEAR(last.label_places[0][1], 0, 1e-6);
}

// Two boxes of one family (the same faces, the second longer and moved): labelled on their fronts
// by reuse, made where drawn, equal to direct slicing's, whole and in ranges of layers.
TEST_F(SideLabelTest, ReuseGivesDirectSlicingsMasks) {
  const Mesh a = test::make_box(-20, -18, 0, 20, -6, 12, 4);
  Mesh b = a;
  for (size_t v = 0; v < b.vertices(); ++v) {
    b.V[3 * v] *= 1.05;
    b.V[3 * v + 1] += 20;
  }
  PrinterProfile profile = display();
  profile.antialiasing = true;
  profile.elephant_foot_mm = 0.2;
  PlateJobOptions direct = options({"a", "b"}, {"CASE1", "CASE2"});
  const Slices encoding = slice_layers(a, direct.slicing);
  direct.slicing.z_start = encoding.z_start;
  const PlateJobStats d = export_plate({a, b}, direct, profile, path("direct"));
  EXPECT_EQ(d.label_heights_mm, (std::vector<double>{7.5, 7.5}));
  PlateJobOptions reuse = direct;
  reuse.encoding = &encoding;
  const PlateJobStats r = export_plate({a, b}, reuse, profile, path("reuse"));
  EXPECT_EQ(r.ranges, 0u);
  EXPECT_EQ(r.label_places, d.label_places);
  direct.range_budget_bytes = 20000;
  EXPECT_GT(export_plate({a, b}, direct, profile, path("direct_ranges")).ranges, 2u);
  for (const char* made : {"reuse", "direct_ranges"})
    EXPECT_EQ(compare_mask_stacks(path("direct"), path(made), "").max_grey_difference, 0) << made;
}

// A label that fits on no side is refused naming the member, the side and the sizes, or with
// allow_unlabelled left off; a hollowed member's letters keep 1 mm from the cavity, as on the base.
TEST_F(SideLabelTest, NoFitIsReportedInWordsAndAllowUnlabelledPrintsWithout) {
  const std::vector<Mesh> placed{test::make_box(-20, -18, 0, -14, -12, 12, 2), test::make_box(-20, 0, 0, 20, 15, 12, 4)};
  PlateJobOptions o = options({"tiny", "big"}, {"CASE12", "CASE13"}, LabelSide::Back);
  const std::string message = test::error_of([&] { export_plate(placed, o, display(), path("p.sl1")); });
  EXPECT_NE(message.find("the label 'CASE12' fits nowhere on the back side of tiny: even 2.5 mm high it is "),
            std::string::npos)
      << message;
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  o.allow_unlabelled = true;
  const PlateJobStats st = export_plate(placed, o, display(), path("p.sl1"));
  ASSERT_EQ(st.label_heights_mm.size(), 2u);
  EXPECT_EQ(st.label_heights_mm[0], 0);
  EXPECT_GT(st.label_heights_mm[1], 0);
  EXPECT_TRUE(std::filesystem::exists(path("p.sl1")));
  o.hollowing.wall_mm = 3;
  EXPECT_ERROR(export_plate(placed, o, display(), path("s.sl1")),
               "labels 3 mm deep would come within 1 mm of the cavity behind walls of 3 mm");
}

// A face is flat enough when its outermost points over the label's box (and margins) lie within
// half the depth of a plane, across the layers and along each: a front leaning back 10 degrees
// (1.32 mm over 7.5 mm) takes the label whole, on the plane of its lowest layer's front; one
// leaning 45 degrees, or with a groove 2 mm deep down its middle, takes none; a groove 1 mm deep
// is within the tolerance. Behind it, the part must be solid for the depth and 1 mm more.
TEST_F(SideLabelTest, OnlyAFaceFlatWithinHalfTheDepthAndSolidBehindTakesTheLabel) {
  const PlateJobOptions o = options({"part"}, {"CASE1"});
  const auto leaning = [](double degrees) {
    Mesh m = test::make_box(-20, -10, 0, 20, 10, 12, 4);
    const double t = std::tan(degrees * M_PI / 180);
    for (size_t v = 0; v < m.vertices(); ++v) m.V[3 * v + 1] += m.V[3 * v + 2] * t * (10 - m.V[3 * v + 1]) / 20;
    return m;
  };
  regions({leaning(10)}, o, "ten");
  EXPECT_EQ(last.label_heights_mm, std::vector<double>{7.5});
  EXPECT_NEAR(last.label_places[0][1], -10 + 2.25 * std::tan(10 * M_PI / 180), 1e-6);
  EXPECT_ERROR(export_plate({leaning(45)}, o, display(), path("steep.sl1")),
               "the label 'CASE1' fits nowhere on the front side of part");
  const auto grooved = [](double depth) {
    Mesh m = test::make_box(-20, -10, 0, -1, 10, 12, 4);
    for (const Mesh& other : {test::make_box(1, -10, 0, 20, 10, 12, 4), test::make_box(-1, -10 + depth, 0, 1, 10, 12, 4)}) {
      const uint32_t base = uint32_t(m.vertices());
      m.V.insert(m.V.end(), other.V.begin(), other.V.end());
      for (uint32_t f : other.F) m.F.push_back(base + f);
    }
    return m;
  };
  EXPECT_ERROR(export_plate({grooved(2)}, o, display(), path("groove2.sl1")),
               "the label 'CASE1' fits nowhere on the front side of part");
  regions({grooved(1)}, o, "groove1");
  EXPECT_EQ(last.label_heights_mm, std::vector<double>{7.5});
  // Behind the face, the part must be solid for the depth and a millimetre more: a slab 3.5 mm
  // thick would be cut nearly through, one 4.5 mm thick holds the label.
  EXPECT_ERROR(export_plate({test::make_box(-20, -10, 0, 20, -6.5, 12, 4)}, o, display(), path("thin.sl1")),
               "with every point within 1.5 mm of a plane and 4 mm of solid part behind the innermost");
  regions({test::make_box(-20, -10, 0, 20, -5.5, 12, 4)}, o, "slab");
  EXPECT_EQ(last.label_heights_mm, std::vector<double>{7.5});
}

// Hollowed with 4 mm walls, a 40 x 20 x 20 mm box's front label 3 mm deep keeps 1 mm from the
// cavity: what it takes from each layer, grown by just under 1 mm, meets none of the layer's
// cavity.
TEST_F(SideLabelTest, OnAHollowedMemberTheLettersKeepAMillimetreFromTheCavity) {
  const std::vector<Mesh> tall{test::make_box(-20, -10, 0, 20, 10, 20, 4)};
  PlateJobOptions o = options({"box"});
  o.hollowing.wall_mm = 4;
  const std::vector<Paths> plain = regions(tall, o, "plain");
  ASSERT_GT(last.cavity_mm3.at(0), 0);
  o.labels = {"CASE1"};
  const std::vector<Paths> cut = regions(tall, o, "front");
  ASSERT_EQ(last.label_heights_mm, std::vector<double>{7.5});
  size_t near_cavity = 0;
  const size_t first = size_t(std::llround((last.label_places[0][2] - 3.75) / 0.1));
  for (size_t k = first; k < first + 75; ++k) {
    Paths cavity;  // the layer's holes, as regions
    for (const ClipperLib::Path& loop : plain[k])
      if (!ClipperLib::Orientation(loop)) cavity.push_back(ClipperLib::Path(loop.rbegin(), loop.rend()));
    near_cavity += !cavity.empty();
    const Paths taken = clip_regions(plain[k], cut[k], ClipperLib::ctDifference);
    ASSERT_FALSE(taken.empty()) << "layer " << k;
    ClipperLib::ClipperOffset grow;
    grow.AddPaths(taken, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    Paths grown;
    grow.Execute(grown, double(region_units(0.999)));
    EXPECT_TRUE(clip_regions(grown, cavity, ClipperLib::ctIntersection).empty()) << "layer " << k;
  }
  EXPECT_GT(near_cavity, 40u);  // the cavity spans most of the label's layers
}
