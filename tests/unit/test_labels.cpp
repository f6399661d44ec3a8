// Labels: the stroke font's text as a region (its box, its strokes' area, mirrored), refused
// characters in words, and placing it on a face: the largest height that fits, turned where only
// a turn fits, none on a face too small, the same placement every time.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "error_of.h"
#include "slicereuse/formats/labels_file.h"
#include "slicereuse/regions/clip_regions.h"
#include "slicereuse/regions/label_region.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/regions/place_label.h"
#include "temp_folder.h"

using namespace slicereuse;
using ClipperLib::Path;
using ClipperLib::Paths;

namespace {

ClipperLib::IntRect bounds(const Paths& p) {
  ClipperLib::Clipper c;
  c.AddPaths(p, ClipperLib::ptSubject, true);
  return c.GetBounds();
}

double mm(ClipperLib::cInt units) { return double(units) / kRegionScale; }

ClipperLib::IntPoint at(double x, double y) { return {region_units(x), region_units(y)}; }

bool covers(const Paths& region, double x, double y) { return region_covers(region, at(x, y)); }

Paths rect(double x0, double y0, double x1, double y1) { return {{at(x0, y0), at(x1, y0), at(x1, y1), at(x0, y1)}}; }

// Pieces of a outside b.
Paths outside(const Paths& a, const Paths& b) { return clip_regions(a, b, ClipperLib::ctDifference); }

Paths shrunk(const Paths& face, double margin) {
  ClipperLib::ClipperOffset o;
  o.AddPaths(face, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
  Paths out;
  o.Execute(out, -double(region_units(margin)) + 2);  // miter: the rectangle exactly, less 2 nm of rounding
  return out;
}

}  // namespace

TEST(LabelRegion, FillsItsBoxCentredOnTheOrigin) {
  // 7.5 mm high: strokes of 0.9 mm, a grid unit of 1.1 mm; "AB12" is 3 advances of 6 units and a
  // glyph of 4: 22 units, 24.2 mm, and a stroke: 25.1 mm.
  const std::array<double, 2> box = label_box_mm("AB12", 7.5);
  EXPECT_NEAR(box[0], 25.1, 1e-9);
  EXPECT_DOUBLE_EQ(box[1], 7.5);
  for (const bool mirrored : {false, true}) {
    const ClipperLib::IntRect b = bounds(label_region("AB12", 7.5, mirrored));
    EXPECT_NEAR(mm(b.left), -12.55, 0.003);
    EXPECT_NEAR(mm(b.right), 12.55, 0.003);
    EXPECT_NEAR(mm(b.top), -3.75, 0.003);
    EXPECT_NEAR(mm(b.bottom), 3.75, 0.003);
  }
}

TEST(LabelRegion, ADashIsABandWithRoundEnds) {
  // 5 mm high: stroke 0.6 mm, unit 0.7333 mm; '-' runs 2 units: 1.4667 x 0.6 mm and two half discs,
  // drawn as polygons inside them within 2 um (the arc tolerance) of their arcs.
  const double area = region_area_mm2(label_region("-", 5, false));
  const double exact = 2 * (5 - 0.6) / 6 * 0.6 + M_PI * 0.3 * 0.3;
  EXPECT_LE(area, exact);
  EXPECT_GE(area, exact - 2 * M_PI * 0.3 * 0.002);
}

TEST(LabelRegion, MirroredReadsFromTheOtherSide) {
  // 'L' is a stroke up its left side and one along its foot: mirrored, the upright is on the right.
  const Paths plain = label_region("L", 6, false), mirrored = label_region("L", 6, true);
  const double upright = 2 * (6 - 0.72) / 6;  // the glyph's left edge is 2 units left of its centre
  EXPECT_TRUE(covers(plain, -upright, 1.5));
  EXPECT_FALSE(covers(plain, upright, 1.5));
  EXPECT_TRUE(covers(mirrored, upright, 1.5));
  EXPECT_FALSE(covers(mirrored, -upright, 1.5));
  EXPECT_NEAR(region_area_mm2(plain), region_area_mm2(mirrored), 1e-6);
}

TEST(LabelRegion, RefusesWhatItCannotPrintInWords) {
  EXPECT_ERROR(label_region("A@B", 7.5, false), "the label 'A@B' holds '@', which labels cannot print");
  EXPECT_ERROR(label_region("  ", 7.5, false), "a label needs a text, but it is empty");
  EXPECT_ERROR(label_region("A", 0, false), "a label's height is 0 mm; it must be a positive number");
  EXPECT_ERROR(place_label(rect(0, 0, 40, 20), "A", 5, 6, 1, false), "a label's least height is 6 mm");
}

TEST(PlaceLabel, TakesTheLargestHeightThatFits) {
  // 40 x 20 mm less a 1 mm margin: "CASE12" at 7.5 mm is 38.3 mm wide, too wide; a tenth less,
  // 6.75 mm, is 34.47 mm wide and fits, unturned, near the middle.
  const Paths face = rect(0, 0, 40, 20);
  const LabelPlacement p = place_label(face, "CASE12", 7.5, 3, 1, false);
  ASSERT_TRUE(p.placed);
  EXPECT_DOUBLE_EQ(p.height_mm, 7.5 * 0.9);
  EXPECT_EQ(p.angle_deg, 0);
  EXPECT_NEAR(p.x_mm, 20, 0.5);
  EXPECT_NEAR(p.y_mm, 10, 0.5);
  EXPECT_TRUE(outside(p.region, shrunk(face, 1)).empty());
  EXPECT_NEAR(region_area_mm2(p.region), region_area_mm2(label_region("CASE12", p.height_mm, false)), 1e-3);
  // The same face places it the same way, to the nanometre.
  EXPECT_EQ(place_label(face, "CASE12", 7.5, 3, 1, false).region, p.region);
}

TEST(PlaceLabel, TurnsToFitABandAtAnAngle) {
  // A band 60 mm long and 10 mm wide at 45 degrees: "AB123" (31.7 x 7.5 mm) fits only along it.
  const double c = std::sqrt(0.5);
  const auto p = [&](double u, double v) { return at(c * u - c * v, c * u + c * v); };
  const Paths band = {{p(-30, -5), p(30, -5), p(30, 5), p(-30, 5)}};
  const LabelPlacement placed = place_label(band, "AB123", 7.5, 3, 1, false);
  ASSERT_TRUE(placed.placed);
  EXPECT_DOUBLE_EQ(placed.height_mm, 7.5);
  EXPECT_EQ(placed.angle_deg, 45);
  EXPECT_TRUE(outside(placed.region, band).empty());
}

TEST(PlaceLabel, NoneOnAFaceTooSmall) {
  // 5 x 5 mm: "CASE12" is 15 mm wide even at its least height, 3 mm.
  EXPECT_FALSE(place_label(rect(0, 0, 5, 5), "CASE12", 7.5, 3, 1, false).placed);
  // A margin as wide as the face leaves nothing.
  EXPECT_FALSE(place_label(rect(0, 0, 5, 5), "A", 2, 1, 3, false).placed);
}

class LabelsFileTest : public test::TempFolderTest {
 protected:
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(path(name)) << text;
    return path(name);
  }
};

TEST_F(LabelsFileTest, MatchesMembersByFileNameOrStem) {
  const LabelsFile f = read_labels_file(write("l.csv", "member,label\n\n a_001.stl , CASE-0412\nb_002,CASE-0413\n"));
  ASSERT_EQ(f.rows.size(), 2u);
  EXPECT_EQ(label_of(f, "a_001.stl"), "CASE-0412");
  EXPECT_EQ(label_of(f, "a_001"), "CASE-0412");
  EXPECT_EQ(label_of(f, "b_002.ply"), "CASE-0413");
  EXPECT_ERROR(label_of(f, "c_003.stl"), "has no label for member 'c_003.stl'");
}

TEST_F(LabelsFileTest, RefusesBrokenFilesInWords) {
  EXPECT_ERROR(read_labels_file(path("none.csv")), "cannot read the labels file");
  EXPECT_ERROR(read_labels_file(write("a.csv", "a.stl,X,Y\n")), "line 1: 'a.stl,X,Y' is not two fields");
  EXPECT_ERROR(read_labels_file(write("b.csv", "a.stl\n")), "line 1: 'a.stl' is not two fields");
  EXPECT_ERROR(read_labels_file(write("c.csv", "a.stl,X\nb.stl, \n")), "line 2: the label is empty");
  EXPECT_ERROR(read_labels_file(write("d.csv", "a.stl,X\na.ply,Y\n")), "member 'a.ply' is listed twice (also as 'a.stl')");
}
