// Plates (issue #17): arrangement of members on build plates, checked by exact polygon geometry
// of the test's own; the placements file read back; and a plate's masks equal, pixel for pixel,
// the union of each placed member's own masks, by reuse and by direct slicing, binary and
// anti-aliased, whole and in ranges of layers.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <tuple>
#include <vector>

#include "error_of.h"
#include "family.h"
#include "mask_stack.h"
#include "shapes.h"
#include "wall_measure.h"
#include "slicereuse/hollowing/hollow_layers.h"
#include "slicereuse/plates/arrange_plates.h"
#include "slicereuse/plates/footprint.h"
#include "slicereuse/plates/placement.h"
#include "slicereuse/plates/plate_file_names.h"
#include "slicereuse/plates/placements_file.h"
#include "slicereuse/plates/plate_job.h"
#include "slicereuse/plates/plate_layout.h"
#include "slicereuse/regions/label_region.h"
#include "slicereuse/png/mask_png.h"
#include "slicereuse/printfiles/check_print_file.h"
#include "slicereuse/printfiles/compare_mask_stacks.h"
#include "slicereuse/printfiles/export_masks.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "slicereuse/util/format.h"
#include "slicereuse/slicing/slice_layers.h"
#include "shuffle_mesh.h"
#include "temp_folder.h"
#include "test_files.h"
#include "unsampled_edge.h"

using namespace slicereuse;

namespace {

// ---- Independent 2-D geometry: distances between projected triangles. ----
using P2 = std::array<double, 2>;

double cross(const P2& o, const P2& a, const P2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

double point_segment(const P2& p, const P2& a, const P2& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
  double u = l2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2 : 0;
  u = std::clamp(u, 0.0, 1.0);
  return std::hypot(p[0] - a[0] - u * dx, p[1] - a[1] - u * dy);
}

bool segments_cross(const P2& a, const P2& b, const P2& c, const P2& d) {
  const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
  return ((d1 > 0) != (d2 > 0) && d1 != 0 && d2 != 0) && ((d3 > 0) != (d4 > 0) && d3 != 0 && d4 != 0);
}

double segment_segment(const P2& a, const P2& b, const P2& c, const P2& d) {
  if (segments_cross(a, b, c, d)) return 0;
  return std::min({point_segment(a, c, d), point_segment(b, c, d), point_segment(c, a, b), point_segment(d, a, b)});
}

bool inside_triangle(const P2& p, const std::array<P2, 3>& t) {
  const double a = cross(t[0], t[1], p), b = cross(t[1], t[2], p), c = cross(t[2], t[0], p);
  return (a >= 0 && b >= 0 && c >= 0) || (a <= 0 && b <= 0 && c <= 0);
}

double triangle_distance(const std::array<P2, 3>& s, const std::array<P2, 3>& t) {
  for (const P2& p : s)
    if (inside_triangle(p, t)) return 0;
  for (const P2& p : t)
    if (inside_triangle(p, s)) return 0;
  double d = INFINITY;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d = std::min(d, segment_segment(s[i], s[(i + 1) % 3], t[j], t[(j + 1) % 3]));
  return d;
}

struct Projected {
  std::vector<std::array<P2, 3>> tri;
  std::vector<std::array<double, 4>> box;  // x0, y0, x1, y1 per triangle
};

Projected project(const Mesh& m) {
  Projected p;
  for (size_t f = 0; f < m.faces(); ++f) {
    std::array<P2, 3> t;
    for (int c = 0; c < 3; ++c) t[c] = {m.V[3 * m.F[3 * f + c]], m.V[3 * m.F[3 * f + c] + 1]};
    p.tri.push_back(t);
    p.box.push_back({std::min({t[0][0], t[1][0], t[2][0]}), std::min({t[0][1], t[1][1], t[2][1]}),
                     std::max({t[0][0], t[1][0], t[2][0]}), std::max({t[0][1], t[1][1], t[2][1]})});
  }
  return p;
}

// The smallest distance between the two members' projected triangles, or `cap` when it is
// at least cap (triangles whose boxes are cap apart are skipped).
double min_distance(const Projected& a, const Projected& b, double cap) {
  double best = cap;
  for (size_t i = 0; i < a.tri.size(); ++i)
    for (size_t j = 0; j < b.tri.size(); ++j) {
      const auto& p = a.box[i];
      const auto& q = b.box[j];
      const double gx = std::max({0.0, q[0] - p[2], p[0] - q[2]}), gy = std::max({0.0, q[1] - p[3], p[1] - q[3]});
      if (std::hypot(gx, gy) >= best) continue;
      best = std::min(best, triangle_distance(a.tri[i], b.tri[j]));
    }
  return best;
}

PrinterProfile display(int w, int h, double um = 100) {
  PrinterProfile p;
  p.width_px = w;
  p.height_px = h;
  p.pixel_size_x_um = p.pixel_size_y_um = um;
  return p;
}

// A plate job at 0.1 mm layers hollowing its members with walls of wall_mm and no closing.
PlateJobOptions hollowing_at_tenths(double wall_mm) {
  PlateJobOptions o;
  o.slicing.thickness = 0.1;
  o.hollowing.wall_mm = wall_mm;
  o.hollowing.closing_mm = 0;
  return o;
}

// A sphere of 5 mm radius standing on z = 0.
Mesh standing_sphere() {
  Mesh sphere = test::make_sphere(5, 40, 80);
  for (size_t v = 2; v < sphere.V.size(); v += 3) sphere.V[v] += 5;
  return sphere;
}

// Members of different shapes: arch family members (non-convex, U-shaped), boxes and a sphere.
struct Members {
  std::vector<Mesh> meshes;
  std::vector<std::string> names;
  std::vector<const Mesh*> pointers() const {
    std::vector<const Mesh*> p;
    for (const Mesh& m : meshes) p.push_back(&m);
    return p;
  }
};

test::FamilyOptions small_arch() {
  test::FamilyOptions o;
  o.faces = 1500;
  o.height = 4;
  o.z_change = test::ZChange::Band;
  return o;
}

Members mixed_members() {
  Members s;
  const test::FamilyOptions o = small_arch();
  const Mesh base = test::make_family_base(o);
  for (int i = 0; i < 6; ++i) {
    s.meshes.push_back(test::make_family_member(base, o, i));
    s.names.push_back("arch" + std::to_string(i));
  }
  s.meshes.push_back(test::make_box(0, 0, 0, 12, 3, 5));
  s.names.push_back("bar");
  s.meshes.push_back(test::make_box(-4, -4, 0, 4, 4, 2));
  s.names.push_back("square");
  s.meshes.push_back(test::make_sphere(3, 8, 12));
  s.names.push_back("ball");
  return s;
}

// Every member's placed triangles within the platform less the spacing, and members of one
// plate at least the spacing apart.
void expect_valid(const Members& s, const Arrangement& a, const Platform& platform, double spacing) {
  constexpr double tol = 1e-6;
  ASSERT_EQ(a.placement.size(), s.meshes.size());
  std::vector<Projected> placed;
  for (size_t m = 0; m < s.meshes.size(); ++m) {
    const Mesh moved = place_mesh(s.meshes[m], a.placement[m]);
    for (size_t v = 0; v < moved.vertices(); ++v) {
      EXPECT_GE(moved.V[3 * v], platform.x0 + spacing - tol) << s.names[m];
      EXPECT_LE(moved.V[3 * v], platform.x1 - spacing + tol) << s.names[m];
      EXPECT_GE(moved.V[3 * v + 1], platform.y0 + spacing - tol) << s.names[m];
      EXPECT_LE(moved.V[3 * v + 1], platform.y1 - spacing + tol) << s.names[m];
      EXPECT_EQ(moved.V[3 * v + 2], s.meshes[m].V[3 * v + 2]);
    }
    placed.push_back(project(moved));
  }
  size_t listed = 0;
  for (size_t k = 0; k < a.members.size(); ++k) {
    listed += a.members[k].size();
    for (size_t i = 0; i < a.members[k].size(); ++i) {
      EXPECT_EQ(a.plate[a.members[k][i]], k);
      for (size_t j = 0; j < i; ++j) {
        const size_t p = a.members[k][i], q = a.members[k][j];
        EXPECT_GE(min_distance(placed[p], placed[q], spacing), spacing - tol)
            << s.names[p] << " and " << s.names[q] << " on plate " << k + 1;
      }
    }
  }
  EXPECT_EQ(listed, s.meshes.size());
}

}  // namespace

TEST(Footprint, CoversEveryProjectedTriangleAndNotTheBoundingBox) {
  const test::FamilyOptions o = small_arch();
  const Mesh arch = test::make_family_base(o);
  // Rasterized at the turn, or derived as the arrangement derives it: turned a quarter (q) or a
  // half (h) from a footprint before, in the order listed.
  const std::pair<double, const char*> cases[] = {{0, ""},    {15, ""},   {90, ""},  {105, "q"},
                                                  {195, "h"}, {270, "h"}, {285, "qh"}};
  for (const auto& [theta, turns] : cases) {
    const std::string derived = turns;
    double from = theta;
    for (char t : derived) from -= t == 'q' ? 90 : 180;
    Footprint f = mesh_footprint(arch, from, 0.25);
    for (char t : derived) f = t == 'q' ? quarter_turn_footprint(f) : half_turn_footprint(f);
    // Every projected vertex of the turned arch lies in a marked cell.
    const Turn turn = turn_of(theta);
    for (size_t v = 0; v < arch.vertices(); ++v) {
      double x, y;
      turn.apply(arch.V[3 * v], arch.V[3 * v + 1], x, y);
      const int i = int(std::floor((x - f.x0) / f.cell)), j = int(std::floor((y - f.y0) / f.cell));
      ASSERT_TRUE(i >= 0 && i < f.width && j >= 0 && j < f.height);
      EXPECT_EQ(f.cells[size_t(j) * f.width + i], 1);
    }
    // The arch's bay (inside the horseshoe) is free: well under its bounding box.
    EXPECT_LT(f.marked(), size_t(f.width) * size_t(f.height) * 3 / 4) << theta;
  }
}

TEST(ArrangePlates, MembersNeverOverlapAndKeepTheSpacing) {
  const Members s = mixed_members();
  for (double spacing : {2.0, 0.5}) {
    const PrinterProfile profile = display(500, 400);  // 50 x 40 mm
    const Platform platform = printer_platform(profile);
    ArrangeOptions o;
    o.spacing_mm = spacing;
    const Arrangement a = arrange_plates(s.pointers(), s.names, platform, o);
    expect_valid(s, a, platform, spacing);
    ASSERT_EQ(a.area_used.size(), a.members.size());
    for (double used : a.area_used) EXPECT_TRUE(used > 0 && used < 1);
  }
}

TEST(ArrangePlates, MembersThatDoNotFitGoToTheNextPlate) {
  Members s;
  for (int i = 0; i < 7; ++i) {
    s.meshes.push_back(test::make_box(0, 0, 0, 14, 9, 3));
    s.names.push_back("box" + std::to_string(i));
  }
  // 40 x 30 mm with 2 mm spacing: 2 x 2 boxes of 14 x 9 per plate at best (rows of 9 + 2 + 9 + 2 + 9 do not fit 26 mm).
  const Platform platform = printer_platform(display(400, 300));
  const Arrangement a = arrange_plates(s.pointers(), s.names, platform, {});
  expect_valid(s, a, platform, 2);
  EXPECT_GE(a.members.size(), 2u);
  for (const auto& plate : a.members) EXPECT_LE(plate.size(), 4u);
  // Turning helps: a 30 x 6 bar fits a 40 x 20 platform only near 0 or 180 degrees, and with a
  // rotation step of 15 degrees three fit across 20 mm only lying along x.
}

TEST(ArrangePlates, TurnsMembersWhereThatPacksMore) {
  // A 24 x 6 bar on a 12 x 40 mm platform fits only turned by 90 degrees.
  Members s;
  s.meshes.push_back(test::make_box(0, 0, 0, 24, 6, 3));
  s.names.push_back("bar");
  const Platform platform = printer_platform(display(120, 400));
  const Arrangement a = arrange_plates(s.pointers(), s.names, platform, {});
  expect_valid(s, a, platform, 2);
  EXPECT_TRUE(a.placement[0].theta_deg == 90 || a.placement[0].theta_deg == 270);
}

TEST(ArrangePlates, RefusesAMemberLargerThanThePlatformWithBothSizes) {
  Members s = mixed_members();
  s.meshes.push_back(test::make_box(0, 0, 0, 100, 10, 3));
  s.names.push_back("long bar");
  const Platform platform = printer_platform(display(500, 400));
  const std::string e = test::error_of([&] { arrange_plates(s.pointers(), s.names, platform, {}); });
  EXPECT_NE(e.find("member 'long bar' (100.00 x 10.00 mm"), std::string::npos) << e;
  EXPECT_NE(e.find("the platform is 50.00 x 40.00 mm, 46.00 x 36.00 mm inside the spacing of 2 mm"), std::string::npos) << e;
}

TEST(ArrangePlates, RefusesBadOptions) {
  const Members s = mixed_members();
  const Platform platform = printer_platform(display(500, 400));
  ArrangeOptions o;
  o.spacing_mm = -1;
  EXPECT_NE(test::error_of([&] { arrange_plates(s.pointers(), s.names, platform, o); }).find("spacing -1 mm"),
            std::string::npos);
  o = {};
  o.rotation_step_deg = 0;
  EXPECT_NE(test::error_of([&] { arrange_plates(s.pointers(), s.names, platform, o); }).find("rotation step"),
            std::string::npos);
  o = {};
  o.spacing_mm = 30;
  EXPECT_NE(test::error_of([&] { arrange_plates(s.pointers(), s.names, platform, o); }).find("leaves no room"),
            std::string::npos);
  Members empty = s;
  empty.meshes.back().F.clear();
  EXPECT_NE(test::error_of([&] { arrange_plates(empty.pointers(), empty.names, platform, {}); }).find("member 'ball': "),
            std::string::npos);
}

TEST(PlateFileNames, NumberThePatternAndPutTheLayoutBeside) {
  EXPECT_EQ(plate_file_name("out/plate.sl1", 2), "out/plate_2.sl1");
  EXPECT_EQ(plate_file_name("out/plate.direct.sl1s", 1), "out/plate.direct_1.sl1s");
  EXPECT_EQ(plate_file_name("out/masks", 3), "out/masks_3");
  EXPECT_EQ(plate_file_name("out/masks/", 3), "out/masks_3");
  EXPECT_EQ(plate_file_name("out.d/masks", 1), "out.d/masks_1");
  EXPECT_EQ(plate_layout_file_name("out/plate_2.sl1"), "out/plate_2_layout.png");
  EXPECT_EQ(plate_layout_file_name("out/masks_3"), "out/masks_3_layout.png");
}

class PlacementsFileTest : public test::TempFolderTest {};

TEST_F(PlacementsFileTest, ReadsBackExactlyThePlacementsUsed) {
  const Members s = mixed_members();
  const Platform platform = printer_platform(display(400, 300));
  const Arrangement a = arrange_plates(s.pointers(), s.names, platform, {});
  std::vector<std::string> outputs;
  for (size_t k = 0; k < a.members.size(); ++k) outputs.push_back("plate_" + std::to_string(k + 1) + ".sl1");
  write_placements_file(path("plates.json"), placements_of(a, s.names, 2, platform, outputs));
  const PlacementsFile f = read_placements_file(path("plates.json"));
  // Each plate's layout picture is named beside its print file, for readers of the file.
  std::ifstream written(path("plates.json"));
  const std::string text((std::istreambuf_iterator<char>(written)), std::istreambuf_iterator<char>());
  for (size_t k = 0; k < outputs.size(); ++k)
    EXPECT_NE(text.find("\"layout\": \"plate_" + std::to_string(k + 1) + "_layout.png\""), std::string::npos) << text;
  EXPECT_EQ(f.spacing_mm, 2);
  EXPECT_EQ(f.platform.x0, platform.x0);
  EXPECT_EQ(f.platform.y0, platform.y0);
  EXPECT_EQ(f.platform.x1, platform.x1);
  EXPECT_EQ(f.platform.y1, platform.y1);
  ASSERT_EQ(f.plates.size(), a.members.size());
  for (size_t k = 0; k < f.plates.size(); ++k) {
    EXPECT_EQ(f.plates[k].output, outputs[k]);
    EXPECT_EQ(f.plates[k].area_used, a.area_used[k]);
  }
  // Members in another order than the file's: matched by name.
  std::vector<std::string> names(s.names.rbegin(), s.names.rend());
  const Arrangement b = arrangement_of(f, names);
  for (size_t m = 0; m < names.size(); ++m) {
    const size_t orig = s.names.size() - 1 - m;
    EXPECT_EQ(b.plate[m], a.plate[orig]);
    EXPECT_EQ(b.placement[m].theta_deg, a.placement[orig].theta_deg);
    EXPECT_EQ(b.placement[m].tx_mm, a.placement[orig].tx_mm);
    EXPECT_EQ(b.placement[m].ty_mm, a.placement[orig].ty_mm);
  }
  // A member the file does not place, and one it places that is not given.
  names.push_back("extra");
  EXPECT_NE(test::error_of([&] { arrangement_of(f, names); }).find("do not place member 'extra'"), std::string::npos);
  names.erase(names.begin());
  names.pop_back();
  EXPECT_NE(test::error_of([&] { arrangement_of(f, names); }).find("member 'ball' (plate"), std::string::npos);
}

// Doubles whose shortest decimal form is long or extreme: each read back bit for bit.
TEST_F(PlacementsFileTest, EveryDoubleReadsBackBitForBit) {
  const std::vector<double> xs = {0.1 + 0.2, -1.0 / 3, 5e-324, 2.2250738585072014e-308, 1.7976931348623157e308,
                                  -0.0, 123456789.123456789, 1e22, 38.4 * 3, 0};
  PlacementsFile f;
  f.spacing_mm = xs[0];
  f.platform = {xs[1], xs[2], xs[3], xs[4]};
  PlateRecord r;
  for (size_t i = 0; i + 2 < xs.size(); ++i) {
    r.names.push_back("m" + std::to_string(i));
    r.placements.push_back({xs[i], xs[i + 1], xs[i + 2]});
  }
  r.area_used = xs[6];
  f.plates.push_back(r);
  write_placements_file(path("p.json"), f);
  const PlacementsFile g = read_placements_file(path("p.json"));
  auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  EXPECT_TRUE(same(g.spacing_mm, f.spacing_mm));
  EXPECT_TRUE(same(g.platform.x0, f.platform.x0) && same(g.platform.y0, f.platform.y0) &&
              same(g.platform.x1, f.platform.x1) && same(g.platform.y1, f.platform.y1));
  ASSERT_EQ(g.plates.size(), 1u);
  EXPECT_TRUE(same(g.plates[0].area_used, r.area_used));
  ASSERT_EQ(g.plates[0].placements.size(), r.placements.size());
  for (size_t i = 0; i < r.placements.size(); ++i) {
    const Placement &p = g.plates[0].placements[i], &q = r.placements[i];
    EXPECT_TRUE(same(p.theta_deg, q.theta_deg) && same(p.tx_mm, q.tx_mm) && same(p.ty_mm, q.ty_mm)) << i;
    EXPECT_EQ(g.plates[0].names[i], r.names[i]);
  }
  // A name that is not UTF-8 is refused before the file is made.
  f.plates[0].names[0] = "caf\xe9";
  EXPECT_EQ(test::error_of([&] { write_placements_file(path("q.json"), f); }),
            "cannot write the placements file '" + path("q.json") +
                "': a member's name or a plate's output is not UTF-8 text");
  EXPECT_FALSE(std::filesystem::exists(path("q.json")));
}

// One plate of a file (what family.py's per-plate tasks load): its members only, as one plate.
TEST_F(PlacementsFileTest, OnePlateOfAFileHoldsExactlyThatPlatesMembers) {
  const Members s = mixed_members();
  const Platform platform = printer_platform(display(300, 200));
  const Arrangement a = arrange_plates(s.pointers(), s.names, platform, {});
  ASSERT_GE(a.members.size(), 2u);
  const PlacementsFile f = placements_of(a, s.names, 2, platform);
  for (size_t k = 0; k < a.members.size(); ++k) {
    std::vector<std::string> names;
    for (size_t m : a.members[k]) names.push_back(s.names[m]);
    const Arrangement one = arrangement_of(f, names, k + 1);
    ASSERT_EQ(one.members.size(), 1u);
    EXPECT_EQ(one.area_used[0], a.area_used[k]);
    for (size_t i = 0; i < names.size(); ++i) {
      EXPECT_EQ(one.members[0][i], i);
      EXPECT_EQ(one.plate[i], 0u);
      EXPECT_EQ(one.placement[i].tx_mm, a.placement[a.members[k][i]].tx_mm);
      EXPECT_EQ(one.placement[i].theta_deg, a.placement[a.members[k][i]].theta_deg);
    }
  }
  std::vector<std::string> first;
  for (size_t m : a.members[0]) first.push_back(s.names[m]);
  first.push_back(s.names[a.members[1][0]]);
  EXPECT_EQ(test::error_of([&] { arrangement_of(f, first, 1); }),
            "the placements do not place member '" + s.names[a.members[1][0]] + "' on plate 1");
  EXPECT_EQ(test::error_of([&] { arrangement_of(f, first, a.members.size() + 1); }),
            format("the placements have %zu plates: there is no plate %zu", a.members.size(), a.members.size() + 1));
}

TEST_F(PlacementsFileTest, RefusesBrokenFilesNamingTheProblem) {
  auto write = [&](const std::string& text) {
    std::ofstream(path("p.json")) << text;
    return test::error_of([&] { read_placements_file(path("p.json")); });
  };
  const std::string head = R"({"format": "slicereuse placements", "version": 1, "spacing_mm": 2,
  "platform_mm": {"x0": -10, "y0": -10, "x1": 10, "y1": 10}, "plates": [)";
  EXPECT_NE(write(head + R"({"area_used": 0.1, "members": [{"name": "a", "theta_deg": 0, "tx_mm": 1}]}]})")
                .find("plate 1, member 1 has no \"ty_mm\""),
            std::string::npos);
  EXPECT_NE(write(head + R"({"area_used": 0.1, "members": [{"name": "a", "theta_deg": "x", "tx_mm": 1, "ty_mm": 1}]}]})")
                .find("member 1's theta_deg is a string, not a number"),
            std::string::npos);
  EXPECT_NE(write(head + "\n{\"area_used\": 0.1, \"members\": [}]}").find("parse error at line 3"), std::string::npos);
  EXPECT_NE(write(head + R"({"area_used": 0.1, "members": []}]})").find("plate 1 has no members"), std::string::npos);
  EXPECT_NE(write(R"({"format": "other", "version": 1})").find("is not a slicereuse placements file"), std::string::npos);
  EXPECT_NE(test::error_of([&] { read_placements_file(path("missing.json")); }).find("missing.json"), std::string::npos);
}

// ---- A plate's masks: the union of each placed member's own masks. ----

// The layers a reused plate made where drawn slices directly for member m: those failing its
// certificate, cheap or whole, or every layer when they are more than half.
namespace {
size_t resliced_on_plate(const Slices& encoding, const Mesh& m) {
  const ExactTransfer t(encoding, m);
  size_t failing = 0;
  for (size_t k = 0; k < t.layers(); ++k) failing += !t.transferable(k) || !t.certified(k);
  return 2 * failing > t.layers() ? t.layers() : failing;
}
}  // namespace

class PlateJobTest : public test::TempFolderTest {
 protected:
  // Layer k of a PNG stack.
  static MaskImage layer(MaskStack& stack, size_t k) {
    std::vector<uint8_t> bytes;
    stack.read(k, bytes);
    MaskImage img;
    decode_mask_png(bytes.data(), bytes.size(), stack.layer_name(k), img);
    return img;
  }

  // members arranged on one plate of profile's display and moved there (place_mesh); empty,
  // with a failure, when they take more than one plate.
  static std::vector<Mesh> placed_on_one_plate(const std::vector<Mesh>& members, const std::vector<std::string>& names,
                                               const PrinterProfile& profile) {
    std::vector<const Mesh*> ptrs;
    for (const Mesh& m : members) ptrs.push_back(&m);
    const Arrangement a = arrange_plates(ptrs, names, printer_platform(profile), {});
    if (a.members.size() != 1) {
      ADD_FAILURE() << "the test wants one plate, not " << a.members.size();
      return {};
    }
    std::vector<Mesh> placed;
    for (size_t m = 0; m < members.size(); ++m) placed.push_back(place_mesh(members[m], a.placement[m]));
    return placed;
  }

  // The plate stack at `plate` equals, pixel for pixel, the union (largest value) of the member
  // stacks; members' stacks end where they end.
  void expect_union(const std::string& plate, const std::vector<std::string>& members) {
    MaskStack p(plate);
    std::vector<std::unique_ptr<MaskStack>> ms;
    size_t tallest = 0;
    for (const auto& m : members) {
      ms.push_back(std::make_unique<MaskStack>(m));
      tallest = std::max(tallest, ms.back()->layers());
    }
    ASSERT_EQ(p.layers(), tallest);
    size_t lit = 0;
    for (size_t k = 0; k < p.layers(); ++k) {
      const MaskImage img = layer(p, k);
      std::vector<uint8_t> u(img.pixels.size(), 0);
      for (auto& m : ms) {
        if (k >= m->layers()) continue;
        const MaskImage mi = layer(*m, k);
        ASSERT_EQ(mi.pixels.size(), u.size());
        for (size_t i = 0; i < u.size(); ++i) {
          // Members never share a lit pixel: the union is the sum.
          if (mi.pixels[i] && u[i]) ADD_FAILURE() << "pixel " << i << " of layer " << k << " lit by two members";
          u[i] = std::max(u[i], mi.pixels[i]);
        }
      }
      for (uint8_t v : u) lit += v != 0;
      ASSERT_TRUE(img.pixels == u) << "layer " << k;
    }
    EXPECT_GT(lit, 0u);
  }
};

TEST_F(PlateJobTest, PlateMasksEqualTheUnionOfTheMembersOwnMasksByReuseAndDirect) {
  // Members of one family (the same faces), z edited in a band so that transfer re-slices some
  // layers, plus a member made taller than the source and one shorter (both changed in z, so
  // their layers failing the whole certificate are found before the masks), and one that fails
  // it on one layer only the transfer finds.
  test::FamilyOptions o = small_arch();
  const Mesh base = test::make_family_base(o);
  std::vector<Mesh> members;
  std::vector<std::string> names;
  for (int i = 1; i <= 5; ++i) {
    members.push_back(test::make_family_member(base, o, i));
    names.push_back("m" + std::to_string(i));
  }
  for (size_t v = 0; v < members[3].vertices(); ++v) members[3].V[3 * v + 2] *= 1.2;
  for (size_t v = 0; v < members[4].vertices(); ++v) members[4].V[3 * v + 2] *= 0.7;
  SliceOptions so;
  so.thickness = 0.1;
  const Slices encoding = slice_layers(base, so);
  // Member 2 passes every layer's counts and sample, and fails the whole certificate on one: made
  // where drawn, it finds that layer only while transferring it.
  size_t broken = 0;
  ASSERT_TRUE(test::move_vertex_across_unsampled_edge(encoding, members[1], &broken));
  PrinterProfile profile = display(500, 400);
  const std::vector<Mesh> placed = placed_on_one_plate(members, names, profile);
  ASSERT_EQ(placed.size(), members.size());

  for (bool aa : {false, true}) {
    profile.antialiasing = aa;
    const std::string tag = aa ? "aa" : "bin";
    // Each placed member's own masks, sliced directly on the encoding's planes.
    std::vector<std::string> own;
    size_t member_layers = 0;
    for (size_t m = 0; m < placed.size(); ++m) {
      SliceOptions mo = so;
      mo.z_start = encoding.z_start;
      mo.encoding = false;
      own.push_back(path(tag + "_own_" + names[m]));
      const Slices direct = slice_layers(placed[m], mo);
      member_layers += direct.layers();
      export_masks(direct, profile, own.back());
    }
    PlateJobOptions reuse;
    reuse.encoding = &encoding;
    const PlateJobStats r = export_plate(placed, reuse, profile, path(tag + "_reuse"));
    EXPECT_EQ(r.ranges, 0u);  // made where drawn
    EXPECT_GT(r.transferred_layers, 0u);
    // Re-sliced: exactly the layers failing the certificate, cheap or whole, in any member (the
    // z-scaled members' layers, the tall member's top, member 2's broken layer), or every layer
    // of a member that fails on more than half.
    size_t failing = 0;
    for (const Mesh& m : placed) failing += resliced_on_plate(encoding, m);
    EXPECT_EQ(r.resliced_layers, failing);
    EXPECT_EQ(r.transferred_layers + r.resliced_layers, member_layers);
    expect_union(path(tag + "_reuse"), own);

    PlateJobOptions direct;
    direct.slicing = so;
    direct.slicing.z_start = encoding.z_start;
    const PlateJobStats d = export_plate(placed, direct, profile, path(tag + "_direct.sl1"));
    EXPECT_EQ(d.transferred_layers, 0u);
    EXPECT_EQ(d.layers, r.layers);
    expect_union(path(tag + "_direct.sl1"), own);

    // Through the edge ends, the vertices read in the order the points use them: the same masks.
    const Buffer<uint32_t> ends = encoded_edge_ends(encoding, base);
    const VertexOrder order = vertex_order(ends);
    PlateJobOptions ordered = reuse;
    ordered.edge_ends = &ends;
    ordered.vertex_order = &order;
    const PlateJobStats ro = export_plate(placed, ordered, profile, path(tag + "_ordered"));
    EXPECT_EQ(ro.ranges, 0u);
    EXPECT_EQ(ro.points, r.points);
    EXPECT_EQ(ro.resliced_layers, r.resliced_layers);
    expect_union(path(tag + "_ordered"), own);

    // In ranges of layers, to stay within a (tiny) memory budget: the same masks.
    reuse.range_budget_bytes = 200000;
    const PlateJobStats rr = export_plate(placed, reuse, profile, path(tag + "_ranges"));
    EXPECT_GT(rr.ranges, 2u);
    EXPECT_EQ(rr.points, r.points);
    EXPECT_EQ(rr.transferred_layers + rr.resliced_layers, member_layers);
    expect_union(path(tag + "_ranges"), own);
  }
}

// With elephant-foot compensation (faded over the first 10 layers), a plate is still the union
// of its members printed alone, each a plate of one on the same planes, made where drawn or in
// ranges that split the faded layers: every member's faded layers are compensated as it is
// alone, not with the others (together, far parts came out otherwise).
TEST_F(PlateJobTest, WithElephantFootThePlateIsStillTheUnionOfItsMembersAlone) {
  test::FamilyOptions o = small_arch();
  const Mesh base = test::make_family_base(o);
  std::vector<Mesh> members;
  std::vector<std::string> names;
  for (int i = 1; i <= 6; ++i) {
    members.push_back(test::make_family_member(base, o, i));
    names.push_back("m" + std::to_string(i));
  }
  PrinterProfile profile = display(500, 400);
  profile.elephant_foot_mm = 0.2;
  profile.elephant_foot_min_width_mm = 0.2;
  ASSERT_EQ(profile.faded_layers, 10);
  const std::vector<Mesh> placed = placed_on_one_plate(members, names, profile);
  ASSERT_EQ(placed.size(), members.size());
  SliceOptions so;
  so.thickness = 0.1;
  const Slices encoding = slice_layers(base, so);
  for (bool aa : {false, true}) {
    profile.antialiasing = aa;
    const std::string tag = aa ? "aa" : "bin";
    PlateJobOptions direct;
    direct.slicing = so;
    direct.slicing.z_start = encoding.z_start;
    std::vector<std::string> alone;
    for (size_t m = 0; m < placed.size(); ++m) {
      alone.push_back(path(tag + "_alone_" + names[m]));
      export_plate({placed[m]}, direct, profile, alone.back());
    }
    export_plate(placed, direct, profile, path(tag + "_direct"));
    expect_union(path(tag + "_direct"), alone);
    PlateJobOptions reuse;
    reuse.encoding = &encoding;
    EXPECT_EQ(export_plate(placed, reuse, profile, path(tag + "_reuse")).ranges, 0u);
    expect_union(path(tag + "_reuse"), alone);
    reuse.range_budget_bytes = 50000;
    direct.range_budget_bytes = 50000;
    const PlateJobStats rr = export_plate(placed, reuse, profile, path(tag + "_reuse_ranges"));
    const PlateJobStats dr = export_plate(placed, direct, profile, path(tag + "_direct_ranges"));
    EXPECT_GT(rr.ranges, 4u);  // some within the faded layers
    EXPECT_GT(dr.ranges, 4u);
    expect_union(path(tag + "_reuse_ranges"), alone);
    expect_union(path(tag + "_direct_ranges"), alone);
  }
  // Anti-aliased, layers 0 to 8 differ from the uncompensated plate's, and no other.
  PrinterProfile plain = profile;
  plain.elephant_foot_mm = 0;
  PlateJobOptions direct;
  direct.slicing = so;
  direct.slicing.z_start = encoding.z_start;
  export_plate(placed, direct, plain, path("aa_plain"));
  const StackComparison c = compare_mask_stacks(path("aa_plain"), path("aa_direct"), "");
  ASSERT_GT(c.layers.size(), 9u);
  for (size_t k = 0; k < c.layers.size(); ++k)
    EXPECT_EQ(c.layers[k].max_grey_difference > 0, k < 9) << "layer " << k;
}

// A plate of members of two connectivities, by reuse: the member whose faces are not the
// encoding's mesh's (the same surface, renumbered) is sliced directly on the encoding's planes,
// made where drawn and in ranges alike; the plate's masks are the union of every member's own,
// and the stats say which member was sliced directly and why. Strict, the plate is refused,
// naming the member, and nothing is written.
TEST_F(PlateJobTest, AMemberOfAnotherConnectivityIsSlicedDirectlyOnAReusedPlate) {
  const test::FamilyOptions o = small_arch();
  const Mesh base = test::make_family_base(o);
  std::vector<Mesh> members = {test::make_family_member(base, o, 1), test::make_family_member(base, o, 2),
                               test::shuffle_mesh(test::make_family_member(base, o, 3), 11).mesh};
  const std::vector<std::string> names = {"m1", "m2", "renumbered"};
  SliceOptions so;
  so.thickness = 0.1;
  const Slices encoding = slice_layers(base, so);
  PrinterProfile profile = display(500, 400);
  profile.antialiasing = true;
  const std::vector<Mesh> placed = placed_on_one_plate(members, names, profile);
  ASSERT_EQ(placed.size(), members.size());
  std::vector<std::string> own;
  size_t renumbered_layers = 0;
  for (size_t m = 0; m < members.size(); ++m) {
    SliceOptions mo = so;
    mo.z_start = encoding.z_start;
    mo.encoding = false;
    const Slices direct = slice_layers(placed[m], mo);
    if (m == 2) renumbered_layers = direct.layers();
    own.push_back(path("own_" + names[m]));
    export_masks(direct, profile, own.back());
  }
  ASSERT_GT(renumbered_layers, 0u);
  const Buffer<uint32_t> ends = encoded_edge_ends(encoding, base);
  const VertexOrder order = vertex_order(ends);
  PlateJobOptions reuse;
  reuse.encoding = &encoding;
  reuse.edge_ends = &ends;
  reuse.vertex_order = &order;
  reuse.names = names;
  for (uint64_t budget : {uint64_t(0), uint64_t(200000)}) {
    reuse.range_budget_bytes = budget;
    const std::string out = path(budget ? "ranges.sl1" : "where_drawn.sl1");
    const PlateJobStats st = export_plate(placed, reuse, profile, out);
    EXPECT_EQ(st.ranges == 0, budget == 0);
    ASSERT_EQ(st.direct_reasons.size(), 3u);
    EXPECT_EQ(st.direct_reasons[0], "");
    EXPECT_EQ(st.direct_reasons[1], "");
    EXPECT_EQ(st.direct_reasons[2].rfind("its faces differ from those of the mesh the encoding was made from", 0), 0u)
        << st.direct_reasons[2];
    // The family's members are transferred but for the layers failing their certificate; every
    // layer of the other is sliced.
    EXPECT_EQ(st.resliced_layers,
              renumbered_layers + resliced_on_plate(encoding, placed[0]) + resliced_on_plate(encoding, placed[1]));
    EXPECT_GT(st.transferred_layers, 0u);
    expect_union(out, own);
  }
  reuse.strict = true;
  const std::string e = test::error_of([&] { export_plate(placed, reuse, profile, path("strict.sl1")); });
  EXPECT_EQ(e.rfind("renumbered cannot be made by reuse: its faces differ", 0), 0u) << e;
  EXPECT_NE(e.find("strict is on"), std::string::npos) << e;
  EXPECT_FALSE(std::filesystem::exists(path("strict.sl1")));
}

// Cancelled half-way through its masks, a plate leaves nothing: made where drawn (reusing),
// in ranges (reusing within a tiny budget), and sliced directly; and the progress it reported
// never went back.
// A plate of a hollow box (a sealed cavity), a solid box and a cup open at the top, sliced
// directly at 0.1 mm on a display of 0.1 mm pixels.
struct CheckedPlate {
  std::vector<Mesh> placed{test::make_hollow_box(-25, -5, 0, -15, 5, 6, 2), test::make_box(-5, -5, 0, 5, 5, 6),
                           test::make_cup(15, -5, 0, 25, 5, 6, 2)};
  PlateJobOptions options;
  CheckedPlate() {
    options.slicing.thickness = 0.1;
    options.names = {"hollow", "solid", "cup"};
    options.check_printability = true;
  }
};

TEST_F(PlateJobTest, ChecksItsMasksAsWrittenAndPlacesEachFindingOnItsMember) {
  CheckedPlate plate;
  for (const char* name : {"p.sl1", "p.goo", "p"}) {
    SCOPED_TRACE(name);
    const PrinterProfile profile = display(800, 600);
    const PlateJobStats st = export_plate(plate.placed, plate.options, profile, path(name));
    ASSERT_TRUE(st.checked);
    const PrintabilityReport& r = st.printability;
    EXPECT_EQ(r.layers, 60u);
    EXPECT_EQ(r.count(FindingKind::Island), 0u);
    ASSERT_EQ(r.count(FindingKind::ResinTrap), 1u);
    ASSERT_EQ(r.count(FindingKind::SuctionCup), 1u);
    EXPECT_TRUE(r.blocks_printing());
    ASSERT_EQ(st.finding_places.size(), r.findings.size());
    for (size_t i = 0; i < r.findings.size(); ++i) {
      const Finding& f = r.findings[i];
      const FindingPlace& at = st.finding_places[i];
      if (f.kind == FindingKind::ResinTrap) {
        EXPECT_EQ(at.member, 0u);
        EXPECT_NEAR(at.x_mm, -20, 0.05);  // the cavity's centre
        EXPECT_NEAR(at.y_mm, 0, 0.05);
        EXPECT_EQ(f.first_layer, 20u);  // the cavity spans z 2..4 mm
        EXPECT_EQ(f.last_layer, 39u);
        EXPECT_NEAR(f.volume_mm3, 6 * 6 * 2, 1e-9);
      }
      if (f.kind == FindingKind::SuctionCup) {
        EXPECT_EQ(at.member, 2u);
        EXPECT_NEAR(at.x_mm, 20, 0.05);
        EXPECT_EQ(f.first_layer, 20u);
        EXPECT_EQ(f.last_layer, 59u);
        EXPECT_NEAR(f.volume_mm3, 6 * 6 * 4, 1e-9);
      }
    }
    // What was checked as written is what the written file holds.
    const PrintabilityReport again = check_print_file(path(name), 0.1, 0.1, 0.1, "");
    ASSERT_EQ(again.findings.size(), r.findings.size());
    for (size_t i = 0; i < r.findings.size(); ++i) {
      EXPECT_EQ(again.findings[i].kind, r.findings[i].kind);
      EXPECT_EQ(again.findings[i].first_layer, r.findings[i].first_layer);
      EXPECT_EQ(again.findings[i].x0, r.findings[i].x0);
      EXPECT_EQ(again.findings[i].y1, r.findings[i].y1);
    }
  }
}

TEST_F(PlateJobTest, RequiredPrintableRefusesATrapAndACupNamingThemAndWritesNothing) {
  CheckedPlate plate;
  plate.options.require_printable = true;
  for (const char* name : {"p.sl1", "p.goo", "p"}) {
    SCOPED_TRACE(name);
    const std::string message = test::error_of([&] { export_plate(plate.placed, plate.options, display(800, 600), path(name)); });
    EXPECT_NE(message.find("not printable"), std::string::npos) << message;
    EXPECT_NE(message.find("resin trap in hollow, layers 20-39, at x -20.00 y 0.00 mm (72 mm3)"), std::string::npos) << message;
    EXPECT_NE(message.find("suction cup in cup, layers 20-59"), std::string::npos) << message;
    EXPECT_TRUE(std::filesystem::is_empty(dir));
  }
  // The solid box alone is printable, and written.
  const std::vector<Mesh> solid{plate.placed[1]};
  plate.options.names = {"solid"};
  const PlateJobStats st = export_plate(solid, plate.options, display(800, 600), path("s.goo"));
  EXPECT_FALSE(st.printability.blocks_printing());
  EXPECT_TRUE(std::filesystem::exists(path("s.goo")));
}

// Labels cut into each member's base (mirrored, the largest height that fits, 3 mm deep): by
// reuse as by direct slicing, made where drawn and in ranges alike, with the elephant foot
// compensated after; the layers below the depth lose the letters and no other layer changes.
TEST_F(PlateJobTest, LabelsAreCutIntoEachBaseByReuseAsByDirect) {
  // One family: boxes of the same faces, the second a little longer (same connectivity).
  const Mesh base = test::make_box(0, 0, 0, 30, 15, 4, 6);
  Mesh longer = base;
  for (size_t v = 0; v < longer.vertices(); ++v) longer.V[3 * v] *= 1.05;
  const std::vector<std::string> names{"b1", "b2"};
  PrinterProfile profile = display(500, 400);
  profile.antialiasing = true;
  profile.elephant_foot_mm = 0.2;
  const std::vector<Mesh> placed = placed_on_one_plate({base, longer}, names, profile);
  ASSERT_EQ(placed.size(), 2u);
  SliceOptions so;
  so.thickness = 0.1;
  const Slices encoding = slice_layers(base, so);
  PlateJobOptions direct;
  direct.slicing = so;
  direct.slicing.z_start = encoding.z_start;
  direct.names = names;
  export_plate(placed, direct, profile, path("plain"));
  direct.labels = {"CASE1", "CASE2"};
  const PlateJobStats d = export_plate(placed, direct, profile, path("direct"));
  // "CASE1" is 31.7 mm long at 7.5 mm, 28.5 at 6.75: 28 mm of the 30 mm box fit it at 6.075 mm.
  // The longer box (31.5 mm) holds 6.75 mm.
  ASSERT_EQ(d.label_heights_mm.size(), 2u);
  EXPECT_DOUBLE_EQ(d.label_heights_mm[0], 7.5 * 0.9 * 0.9);
  EXPECT_DOUBLE_EQ(d.label_heights_mm[1], 7.5 * 0.9);
  PlateJobOptions reuse = direct;
  reuse.encoding = &encoding;
  EXPECT_EQ(export_plate(placed, reuse, profile, path("reuse")).ranges, 0u);
  direct.range_budget_bytes = 20000;
  EXPECT_GT(export_plate(placed, direct, profile, path("direct_ranges")).ranges, 2u);  // some in the engraved layers
  for (const char* made : {"reuse", "direct_ranges"}) {
    const StackComparison same = compare_mask_stacks(path("direct"), path(made), "");
    EXPECT_EQ(same.max_grey_difference, 0) << made;
  }
  // 3 mm deep: layers 0-29 of 0.1 mm lose the letters, and no other layer changes.
  const StackComparison c = compare_mask_stacks(path("plain"), path("direct"), "");
  ASSERT_EQ(c.layers.size(), 40u);
  for (size_t k = 0; k < c.layers.size(); ++k)
    EXPECT_EQ(c.layers[k].max_grey_difference > 0, k < 30) << "layer " << k;
  MaskStack plain(path("plain")), labelled(path("direct"));
  for (size_t k : {size_t(0), size_t(29)}) {
    uint64_t before = 0, after = 0;
    for (uint8_t v : layer(plain, k).pixels) before += v;
    for (uint8_t v : layer(labelled, k).pixels) after += v;
    EXPECT_LT(after, before) << "layer " << k;  // only cut, never lit
  }
}

TEST_F(PlateJobTest, ALabelThatFitsNowhereFailsTheJobUnlessAllowedUnlabelled) {
  const std::vector<Mesh> placed{test::make_box(-3, -3, 0, 3, 3, 5, 2), test::make_box(10, -3, 0, 40, 12, 5, 2)};
  PlateJobOptions o;
  o.slicing.thickness = 0.1;
  o.names = {"tiny", "big"};
  o.labels = {"CASE12", "CASE13"};
  const std::string message = test::error_of([&] { export_plate(placed, o, display(500, 400), path("p.sl1")); });
  EXPECT_NE(message.find("the label 'CASE12' does not fit on the base of tiny: even 2.5 mm high it is "), std::string::npos)
      << message;
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  o.allow_unlabelled = true;
  const PlateJobStats st = export_plate(placed, o, display(500, 400), path("p.sl1"));
  // "CASE13" is 5.107 times as long as high: 5.47 mm high (27.92 mm long) it would fit the 28 mm
  // inside the margins only 0.08 mm either side of the middle, between two centres of the
  // 0.112 mm grid tried; 4.92 mm high it fits.
  EXPECT_EQ(st.label_heights_mm, (std::vector<double>{0, 7.5 * 0.9 * 0.9 * 0.9 * 0.9}));
  o.labels = {"CASE12"};
  EXPECT_ERROR(export_plate(placed, o, display(500, 400), path("q.sl1")), "a plate of 2 members was given 1 labels");
  // A part must stand a millimetre above its label's letters: none cut through it.
  o.labels = {"A", "B"};
  o.allow_unlabelled = false;
  const std::vector<Mesh> thin{test::make_box(-3, -3, 0, 3, 3, 5, 2), test::make_box(10, -3, 0, 40, 12, 2, 2)};
  EXPECT_ERROR(export_plate(thin, o, display(500, 400), path("r.sl1")),
               "the label 'B' does not fit big: big is 2 mm tall, and a label 3 mm deep needs 4 mm");
  // Hollowed, the letters keep 1 mm from the cavity, which lies at least the wall above the base.
  o.hollowing.wall_mm = 3;
  EXPECT_ERROR(export_plate(placed, o, display(500, 400), path("s.sl1")),
               "labels 3 mm deep would come within 1 mm of the cavity behind walls of 3 mm: make them at most 2 mm "
               "deep, or the walls at least 4 mm");
}

TEST_F(PlateJobTest, CancellingAPlateLeavesNothing) {
  test::FamilyOptions o = small_arch();
  const Mesh base = test::make_family_base(o);
  std::vector<Mesh> placed;
  for (int i = 1; i <= 2; ++i) {
    Mesh m = test::make_family_member(base, o, i);
    for (size_t v = 0; v < m.vertices(); ++v) m.V[3 * v] += 40.0 * (i - 1);  // apart
    placed.push_back(m);
  }
  SliceOptions so;
  so.thickness = 0.02;  // 200 layers: export reports its progress every 64
  const Slices encoding = slice_layers(base, so);
  PlateJobOptions reuse, ranged, direct;
  reuse.encoding = ranged.encoding = &encoding;
  ranged.range_budget_bytes = 100000;
  direct.slicing = so;
  for (const PlateJobOptions* job : {&reuse, &ranged, &direct})
    for (const char* name : {"c.sl1", "c.goo", "c"}) {
      SCOPED_TRACE(std::string(name) + (job == &reuse ? " reuse" : job == &ranged ? " ranges" : " direct"));
      double last = 0;
      bool backwards = false;
      EXPECT_THROW(export_plate(placed, *job, display(800, 600), path(name),
                                [&](double f, const char*) {
                                  backwards |= f < last;
                                  last = f;
                                  return f < 0.5;
                                }),
                   Cancelled);
      EXPECT_FALSE(backwards);
      EXPECT_GE(last, 0.5);
      EXPECT_TRUE(std::filesystem::is_empty(dir));
    }
}

class PlateLayoutTest : public test::TempFolderTest {};

namespace {

constexpr uint8_t kBlack = 0, kLightGrey = 215, kWhite = 255;

// Every pixel of a layout picture against the placed members' own projected triangles, as
// plate_layout.h promises it: column c, row r (from the top) shows the platform at
// (x0 + (c + 1/2) px, y0 + (height - r - 1/2) px), framed in black. The footprint is
// conservative and placed to the nearest pixel, so a pixel is light grey only where its 5 x 5
// neighbours' centres all lie on a member, and white only 4 pixels from every member; black
// there is a name, in a box of the glyphs' size about the centre of its member's box, and
// every member's name has some.
void expect_layout_shows(const std::string& png_path, const std::vector<Mesh>& placed,
                         const std::vector<std::string>& names, const Platform& platform, double px) {
  const std::string bytes = test::slurp(png_path);
  MaskImage img;
  decode_mask_png(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), png_path, img);
  ASSERT_EQ(img.width, int(std::ceil((platform.x1 - platform.x0) / px)));
  ASSERT_EQ(img.height, int(std::ceil((platform.y1 - platform.y0) / px)));
  const int w = img.width, h = img.height, scale = std::max(1, std::min(w, h) / 150);
  constexpr double kFar = 4;
  // Distance in pixels (up to kFar) from each pixel's centre to the members' projected triangles.
  std::vector<double> distance(size_t(w) * h, kFar);
  std::vector<int> nearest(size_t(w) * h, -1);
  struct Box {
    double c0, r0, c1, r1;
  };
  std::vector<Box> text;
  for (size_t m = 0; m < placed.size(); ++m) {
    const Projected p = project(placed[m]);
    double bx0 = INFINITY, by0 = INFINITY, bx1 = -INFINITY, by1 = -INFINITY;
    for (size_t t = 0; t < p.tri.size(); ++t) {
      const auto& b = p.box[t];
      bx0 = std::min(bx0, b[0]), by0 = std::min(by0, b[1]), bx1 = std::max(bx1, b[2]), by1 = std::max(by1, b[3]);
      const int c0 = std::max(0, int(std::floor((b[0] - platform.x0) / px - kFar))),
                c1 = std::min(w - 1, int(std::ceil((b[2] - platform.x0) / px + kFar))),
                r0 = std::max(0, int(std::floor(h - (b[3] - platform.y0) / px - kFar))),
                r1 = std::min(h - 1, int(std::ceil(h - (b[1] - platform.y0) / px + kFar)));
      for (int r = r0; r <= r1; ++r)
        for (int c = c0; c <= c1; ++c) {
          const P2 q{platform.x0 + (c + 0.5) * px, platform.y0 + (h - r - 0.5) * px};
          const auto& v = p.tri[t];
          const double d = inside_triangle(q, v) ? 0
                                                 : std::min({point_segment(q, v[0], v[1]), point_segment(q, v[1], v[2]),
                                                             point_segment(q, v[2], v[0])}) / px;
          const size_t i = size_t(r) * w + c;
          if (d < distance[i]) distance[i] = d, nearest[i] = int(m);
        }
    }
    // The name's box about the centre of the member's box, a footprint cell and a rounding wider.
    const double cc = ((bx0 + bx1) / 2 - platform.x0) / px, cr = h - ((by0 + by1) / 2 - platform.y0) / px;
    const double half_w = (int(names[m].size()) * 4 * scale - scale) / 2.0 + 3, half_h = 5 * scale / 2.0 + 3;
    text.push_back({cc - half_w, cr - half_h, cc + half_w, cr + half_h});
  }
  std::vector<size_t> inside(placed.size()), name_ink(placed.size());
  size_t wrong = 0;
  std::string first;
  auto expect = [&](bool ok, int c, int r, const char* what) {
    if (ok) return;
    if (!wrong++) first = format("pixel (%d, %d) is %d, not %s", c, r, img.pixels[size_t(r) * w + c], what);
  };
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const size_t i = size_t(r) * w + c;
      const uint8_t v = img.pixels[i];
      if (r == 0 || c == 0 || r == h - 1 || c == w - 1) {
        expect(v == kBlack, c, r, "the frame's black");
        continue;
      }
      bool deep = r >= 2 && c >= 2 && r < h - 2 && c < w - 2;
      for (int dr = -2; dr <= 2 && deep; ++dr)
        for (int dc = -2; dc <= 2 && deep; ++dc) deep = distance[size_t(r + dr) * w + c + dc] == 0;
      const bool far = distance[i] >= kFar;
      int in_text = -1;
      for (size_t m = 0; m < text.size(); ++m)
        if (c >= text[m].c0 && c <= text[m].c1 && r >= text[m].r0 && r <= text[m].r1) in_text = int(m);
      if (deep && v == kLightGrey) ++inside[size_t(nearest[i])];
      const bool plain = deep ? v == kLightGrey : far ? v == kWhite : v == kBlack || v == kLightGrey || v == kWhite;
      const char* what = deep ? "a member's light grey" : far ? "the paper's white" : "black, light grey or white";
      // Within a name's box black may also be the name; on a member or on the paper, not an
      // outline, it is the name.
      if (in_text >= 0 && v == kBlack && (deep || far)) ++name_ink[size_t(in_text)];
      expect(plain || (in_text >= 0 && v == kBlack), c, r, what);
    }
  EXPECT_EQ(wrong, 0u) << first;
  for (size_t m = 0; m < placed.size(); ++m) {
    EXPECT_GT(inside[m], 100u) << names[m] << " is not on the picture where it is placed";
    EXPECT_GT(name_ink[m], 0u) << names[m] << "'s name is not drawn on it";
  }
}

}  // namespace

// The members' footprints are made on all cores; a member that has none (no faces) is refused in
// words, as on one core, and no picture is written.
TEST_F(PlateLayoutTest, DrawsEveryMemberAndRefusesOneWithoutFacesWritingNothing) {
  const Members s = mixed_members();
  const Platform platform = printer_platform(display(400, 300));
  const Arrangement a = arrange_plates(s.pointers(), s.names, platform, {});
  std::vector<Mesh> placed;
  std::vector<std::string> names;
  for (size_t m : a.members[0]) {
    placed.push_back(place_mesh(s.meshes[m], a.placement[m]));
    names.push_back(s.names[m]);
  }
  write_plate_layout(path("plate_layout.png"), placed, names, platform);
  ASSERT_GE(placed.size(), 3u);  // members side by side, each drawn where it is placed
  expect_layout_shows(path("plate_layout.png"), placed, names, platform, 0.1);
  Mesh faceless = placed[0];
  faceless.F.clear();
  placed.push_back(faceless);
  names.push_back("faceless");
  const std::string e = test::error_of([&] { write_plate_layout(path("bad_layout.png"), placed, names, platform); });
  EXPECT_EQ(e, "a footprint needs a mesh with faces");
  EXPECT_FALSE(std::filesystem::exists(path("bad_layout.png")));
}

TEST(PlateJob, RefusesNoMembersAnEncodingWithoutThicknessAndAStartAboveEveryMember) {
  PlateJobOptions o;
  EXPECT_NE(test::error_of([&] { export_plate({}, o, display(100, 100), "/tmp/never"); }).find("at least one member"),
            std::string::npos);
  const Mesh box = test::make_box(0, 0, 0, 1, 1, 1);
  Slices planes_only = slice_planes(box, {0.5});
  o.encoding = &planes_only;
  EXPECT_NE(test::error_of([&] { export_plate({box}, o, display(100, 100), "/tmp/never"); }).find("no layer thickness"),
            std::string::npos);
  PlateJobOptions above;
  above.slicing.thickness = 0.1;
  above.slicing.z_start = 5;
  EXPECT_EQ(test::error_of([&] { export_plate({box}, above, display(100, 100), "/tmp/never"); }),
            "no layers: z_start 5 mm is not below the top of the mesh at z = 1 mm");
  EXPECT_EQ(test::error_of([&] {
              export_plate({box, test::make_box(3, 0, 0, 4, 1, 2)}, above, display(100, 100), "/tmp/never");
            }),
            "no layers: z_start 5 mm is not below the top of any member at z = 2 mm");
  EXPECT_FALSE(std::filesystem::exists("/tmp/never"));
}

// A hollowed solid box (direct slicing, 0.1 mm layers and pixels, walls of 1 mm): its cavity is
// the box shrunk by 1 mm, sealed, so the printability check finds exactly one resin trap of its
// volume, and its walls measure 1 mm on the masks in 3-D. So do a sphere's, whose walls all
// slope: a 2-D offset per layer would thin them.
TEST_F(PlateJobTest, AHollowedBoxIsOneResinTrapOfItsCavityAndItsWallsKeepTheThickness) {
  const Mesh sphere = standing_sphere();
  for (const auto& [mesh, name, cavity] :
       {std::tuple{test::make_box(-5, -4, 0, 5, 4, 6), "box", 8.0 * 6 * 4}, {sphere, "sphere", 4 * M_PI / 3 * 64}}) {
    SCOPED_TRACE(name);
    PlateJobOptions o = hollowing_at_tenths(1);
    o.check_printability = true;
    const PlateJobStats st = export_plate({mesh}, o, display(800, 600), path(name));
    ASSERT_EQ(st.cavity_mm3.size(), 1u);
    EXPECT_NEAR(st.cavity_mm3[0], cavity, cavity * 0.01);  // a sphere's facets: within a per cent
    EXPECT_EQ(st.hollowing_notes[0], "");
    ASSERT_EQ(st.printability.count(FindingKind::ResinTrap), 1u);
    for (const Finding& f : st.printability.findings)
      if (f.kind == FindingKind::ResinTrap) {
        EXPECT_EQ(f.first_layer, 10u);
        EXPECT_EQ(f.last_layer, std::string(name) == "box" ? 49u : 89u);
        if (std::string(name) == "box") EXPECT_NEAR(f.volume_mm3, cavity, 1e-6);  // pixel edges on its edges
        else EXPECT_NEAR(f.volume_mm3, st.cavity_mm3[0], 0.5 * 0.1 * 4 * M_PI * 16);  // half a pixel over its surface
      }
    MaskStack stack(path(name));
    const test::WallMeasure walls = test::measure_walls(stack, 0.1, 0.1, 3);
    EXPECT_GE(walls.thinnest_mm, 1 - 0.1);
    EXPECT_LE(walls.thinnest_mm, 1 + 0.1 + 1e-9);
    EXPECT_NEAR(walls.cavity_mm3, st.printability.findings[0].volume_mm3, 1e-6);
  }
  // Walls thicker than half the part leave it solid, and the stats say so in words.
  PlateJobOptions o;
  o.slicing.thickness = 0.1;
  o.names = {"slab"};
  o.hollowing.wall_mm = 2;
  const PlateJobStats st = export_plate({test::make_box(-5, -4, 0, 5, 4, 3)}, o, display(800, 600), path("slab"));
  EXPECT_EQ(st.cavity_mm3[0], 0);
  EXPECT_EQ(st.hollowing_notes[0],
            "slab stays solid: no cavity with walls of 2 mm and a closing distance of 2 mm, since no ball of 4 mm "
            "radius fits inside it");
  o.hollowing.wall_mm = -0.5;
  EXPECT_EQ(test::error_of([&] { export_plate({test::make_box(-5, -4, 0, 5, 4, 3)}, o, display(800, 600), path("bad")); }),
            "the hollowing wall thickness is -0.5 mm; it must be a finite, non-negative number (0: solid)");
  EXPECT_FALSE(std::filesystem::exists(path("bad")));
}

// A drain hole wider than the member's floor under its cavity fails the job naming the member,
// and nothing is written.
TEST_F(PlateJobTest, ADrainHoleWiderThanTheFloorFailsTheJobNamingTheMember) {
  PlateJobOptions o = hollowing_at_tenths(1);
  o.names = {"case-7"};
  o.drain_hole_mm = 9;
  const std::string message =
      test::error_of([&] { export_plate({test::make_box(0, 0, 0, 10, 8, 6)}, o, display(800, 600), path("wide")); });
  EXPECT_EQ(message.substr(0, 65), "case-7: a drain hole of 9 mm at (5.00, 4.00) mm would cut through") << message;
  EXPECT_FALSE(std::filesystem::exists(path("wide")));
}

// Drain holes (#36 item 2): each cavity gets a hole under its lowest layer, through the bottom
// wall to the base, and no cavity stays sealed: the check finds no resin trap where, without
// holes, it found one per cavity. Two boxes side by side, joined by a bar on their floor: one
// part, two cavities, two holes, each under its cavity's middle; a sphere's hole under its
// cavity's lowest point. A label on the base keeps clear of the holes.
TEST_F(PlateJobTest, DrainHolesOpenEveryCavityThroughTheBase) {
  Mesh twin = test::make_box(-18, -5, 0, -2, 5, 6);
  test::append_mesh(twin, test::make_box(2, -5, 0, 18, 5, 6));
  test::append_mesh(twin, test::make_box(-2.5, -1, 0, 2.5, 1, 0.5));  // overlapping both: one part
  const Mesh sphere = standing_sphere();
  for (const auto& [mesh, name, cavities] : {std::tuple{twin, "twin", size_t(2)}, {sphere, "sphere", size_t(1)}}) {
    SCOPED_TRACE(name);
    PlateJobOptions o = hollowing_at_tenths(1);
    o.check_printability = true;
    const PlateJobStats sealed = export_plate({mesh}, o, display(800, 600), path(std::string(name) + "_sealed"));
    EXPECT_EQ(sealed.printability.count(FindingKind::ResinTrap), cavities);
    o.drain_hole_mm = 2;
    const PlateJobStats drained = export_plate({mesh}, o, display(800, 600), path(name));
    ASSERT_EQ(drained.drain_holes.size(), 1u);
    ASSERT_EQ(drained.drain_holes[0].size(), cavities);
    EXPECT_EQ(drained.printability.count(FindingKind::ResinTrap), 0u);
    EXPECT_EQ(drained.printability.count(FindingKind::SuctionCup), 0u);
    EXPECT_EQ(drained.drain_holes[0][0].layer, 10u);  // the cavities begin 1 mm up
    if (std::string(name) == "twin") {
      EXPECT_NEAR(drained.drain_holes[0][0].x_mm, -10, 1e-6);
      EXPECT_NEAR(drained.drain_holes[0][1].x_mm, 10, 1e-6);
    } else {
      EXPECT_NEAR(drained.drain_holes[0][0].x_mm, 0, 0.05);
      EXPECT_NEAR(drained.drain_holes[0][0].y_mm, 0, 0.05);
    }
    if (std::string(name) != "twin") continue;  // the sphere's first layer is smaller than its hole
    // The twin's layer 0 lost each hole's disc (a 24-gon inscribed in a 2 mm circle), no more.
    MaskStack a(path(std::string(name) + "_sealed")), b(path(name));
    uint64_t before = 0, after = 0;
    for (uint8_t v : layer(a, 0).pixels) before += v != 0;
    for (uint8_t v : layer(b, 0).pixels) after += v != 0;
    EXPECT_NEAR(double(before - after), double(cavities) * M_PI / 0.01, double(cavities) * 40) << "pixels of 0.1 mm";
  }
  // A label on the twin's base keeps 1 mm from both holes.
  PlateJobOptions o = hollowing_at_tenths(2);
  o.drain_hole_mm = 2;
  o.labels = {"AB"};
  o.label.depth_mm = 1;
  const PlateJobStats st = export_plate({twin}, o, display(800, 600), path("labelled"));
  ASSERT_EQ(st.drain_holes[0].size(), 2u);
  ASSERT_GT(st.label_heights_mm[0], 0);
  const std::array<double, 2> box = label_box_mm("AB", st.label_heights_mm[0]);
  for (const DrainHole& h : st.drain_holes[0]) {
    const double dx = std::fabs(h.x_mm - st.label_places[0][0]), dy = std::fabs(h.y_mm - st.label_places[0][1]);
    const bool turned = std::fabs(st.label_places[0][2]) == 90;
    EXPECT_TRUE(dx > 0.5 * (turned ? box[1] : box[0]) + 1 || dy > 0.5 * (turned ? box[0] : box[1]) + 1)
        << "hole at " << h.x_mm << ", " << h.y_mm;
  }
}

// A cavity made before the job (options.made_cavities: a supported member's, made for its drain
// holes' keep-out) is the member's own when it is of the same mesh on the same planes with the
// same hollowing: the masks are those the job makes alone. The job uses what it takes (an empty
// one leaves the member solid), and takes none of other planes, another hollowing or a mesh with
// a vertex moved by a micrometre.
TEST_F(PlateJobTest, ACavityMadeBeforeTheJobIsTakenOnlyForTheSameLayers) {
  const std::vector<Mesh> sphere{standing_sphere()};
  const PrinterProfile profile = display(120, 120);
  PlateJobOptions o = hollowing_at_tenths(1);
  o.slicing.z_start = 0;
  PlateJobOptions solid = o;
  solid.hollowing.wall_mm = 0;
  export_plate(sphere, solid, profile, path("solid"));
  const PlateJobStats own = export_plate(sphere, o, profile, path("own"));
  ASSERT_GT(own.cavity_mm3[0], 100);
  const Slices layers = slice_layers(sphere[0], o.slicing);
  const std::vector<ClipperLib::Paths> none(layers.layers());
  Mesh moved = sphere[0];
  moved.V[0] += 1e-3;
  std::vector<double> shifted = layers.layer_z;
  for (double& z : shifted) z += 0.05;
  HollowingOptions thinner = o.hollowing;
  thinner.wall_mm = 0.9;
  const std::vector<std::tuple<std::string, PlateJobOptions::MadeCavity, std::string, double>> cases{
      {"the same", {&sphere[0], layers.layer_z, o.hollowing, layers_cavity(layers, o.hollowing)}, "own",
       own.cavity_mm3[0]},
      {"an empty one", {&sphere[0], layers.layer_z, o.hollowing, none}, "solid", 0},
      {"other planes", {&sphere[0], shifted, o.hollowing, none}, "own", own.cavity_mm3[0]},
      {"another hollowing", {&sphere[0], layers.layer_z, thinner, none}, "own", own.cavity_mm3[0]},
      {"a vertex moved", {&moved, layers.layer_z, o.hollowing, none}, "own", own.cavity_mm3[0]}};
  for (const auto& [name, made, masks, volume] : cases) {
    SCOPED_TRACE(name);
    PlateJobOptions with = o;
    with.made_cavities = {made};
    const PlateJobStats st = export_plate(sphere, with, profile, path("made"));
    EXPECT_EQ(st.cavity_mm3[0], volume);
    EXPECT_EQ(compare_mask_stacks(path(masks), path("made"), "").differing_pixels, 0u);
    std::filesystem::remove_all(path("made"));
  }
}

// Reused and direct hollowed plates give identical masks, made where drawn, in ranges and in one, with
// the elephant-foot compensation (after the hollowing) and anti-aliasing: the cavity is computed
// from the member's layers, which reuse makes equal to direct slicing's.
TEST_F(PlateJobTest, ReusedHollowedMembersEqualDirectSlicing) {
  test::FamilyOptions fo;
  fo.shape = "sphere";
  fo.faces = 3000;
  fo.height = 7;
  const Mesh base = test::make_family_base(fo);
  const std::vector<Mesh> members = {test::make_family_member(base, fo, 1), test::make_family_member(base, fo, 2)};
  PrinterProfile profile = display(500, 400);
  profile.elephant_foot_mm = 0.2;
  profile.antialiasing = true;
  const std::vector<Mesh> placed = placed_on_one_plate(members, {"a", "b"}, profile);
  ASSERT_EQ(placed.size(), 2u);
  SliceOptions so;
  so.thickness = 0.1;
  const Slices encoding = slice_layers(base, so);
  PlateJobOptions direct;
  direct.slicing = so;
  direct.slicing.z_start = encoding.z_start;
  direct.hollowing.wall_mm = 1;
  direct.hollowing.closing_mm = 0.5;
  PlateJobOptions reuse = direct;
  reuse.encoding = &encoding;
  const PlateJobStats d = export_plate(placed, direct, profile, path("direct"));
  const PlateJobStats r = export_plate(placed, reuse, profile, path("reuse"));
  EXPECT_EQ(r.ranges, 0u);
  EXPECT_GT(r.transferred_layers, 0u);
  // In ranges (slicing directly within a tiny budget) and in one (reusing for a contour file).
  PlateJobOptions ranges = direct;
  ranges.range_budget_bytes = 50000;
  EXPECT_GT(export_plate(placed, ranges, profile, path("direct_ranges")).ranges, 4u);
  size_t seen = 0;
  reuse.whole_stack = [&](const std::vector<SlicePart>& parts) { seen = parts.size(); };
  EXPECT_EQ(export_plate(placed, reuse, profile, path("reuse_whole")).ranges, 1u);
  EXPECT_EQ(seen, 2u);
  for (size_t m = 0; m < 2; ++m) {
    EXPECT_GT(d.cavity_mm3[m], 10);
    EXPECT_EQ(r.cavity_mm3[m], d.cavity_mm3[m]);
  }
  for (const char* other : {"reuse", "direct_ranges", "reuse_whole"}) {
    const StackComparison c = compare_mask_stacks(path("direct"), path(other), "");
    EXPECT_EQ(c.differing_pixels, 0u) << other;
  }
  // And the hollowed plate is not the solid one.
  PlateJobOptions solid = direct;
  solid.hollowing.wall_mm = 0;
  export_plate(placed, solid, profile, path("solid"));
  EXPECT_GT(compare_mask_stacks(path("direct"), path("solid"), "").differing_pixels, 1000u);
}
