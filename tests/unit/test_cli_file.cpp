// CLI files (ASCII and binary): round trips, the layout checked by an independent reader written
// from the specification (tests/support/spec_readers.cpp), files from other writers (units,
// short format, hatches, implicit closing), and refusal of damaged or absurd files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "shapes.h"
#include "slicereuse/formats/cli_file.h"
#include "slicereuse/formats/slice_files.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/util/error.h"
#include "spec_readers.h"
#include "test_files.h"

using namespace slicereuse;
using namespace slicereuse::test;

namespace {

// CLI carries 2D points on layers: every point's z is its layer's z; no encoding.
Slices planar(Slices s, bool float_range) {
  std::mt19937_64 rng(7);
  s.face.clear();
  s.edge.clear();
  s.t.clear();
  for (size_t k = 0; k < s.layers(); ++k)
    for (uint64_t p = s.contour_begin[s.layer_begin[k]]; p < s.contour_begin[s.layer_begin[k + 1]]; ++p) {
      if (float_range)
        for (int a = 0; a < 2; ++a) s.xyz[3 * p + a] = std::uniform_real_distribution<double>(-200, 200)(rng);
      s.xyz[3 * p + 2] = s.layer_z[k];
    }
  return s;
}

Slices sample(bool float_range) {
  return planar(make_slices({5, 3, 4, -1, -1, 7, 2, 1, -1, 30, 3, 3, 9}, 42), float_range);
}

void expect_same_layers(const Slices& a, const Slices& b) {
  EXPECT_EQ(a.layer_begin, b.layer_begin);
  EXPECT_EQ(a.contour_begin, b.contour_begin);
  EXPECT_EQ(a.contour_open, b.contour_open);
  ASSERT_EQ(a.layer_z.size(), b.layer_z.size());
  ASSERT_EQ(a.xyz.size(), b.xyz.size());
}

class CliFiles : public FileTest {};

const CliEncoding kEncodings[] = {CliEncoding::Ascii, CliEncoding::Binary};

}  // namespace

TEST_F(CliFiles, AsciiRoundTripIsBitExact) {
  const Slices s = sample(false);  // doubles over the whole range
  write_cli_file(path("a.cli"), s, CliEncoding::Ascii);
  const Slices r = read_cli_file(path("a.cli"));
  expect_same_layers(s, r);
  EXPECT_EQ(std::memcmp(s.layer_z.data(), r.layer_z.data(), 8 * s.layers()), 0);
  EXPECT_EQ(std::memcmp(s.xyz.data(), r.xyz.data(), 8 * s.xyz.size()), 0);
  EXPECT_FALSE(r.has_encoding());
  // Uniform layers: thickness and z_start come back from the layer spacing.
  EXPECT_NEAR(r.thickness, s.thickness, 1e-12);
  EXPECT_NEAR(r.z_start, s.z_start, 1e-12);
}

TEST_F(CliFiles, BinaryRoundTripIsFloat32) {
  const Slices s = sample(true);
  write_cli_file(path("b.cli"), s, CliEncoding::Binary);
  const Slices r = read_cli_file(path("b.cli"));
  expect_same_layers(s, r);
  for (size_t k = 0; k < s.layers(); ++k) EXPECT_EQ(r.layer_z[k], double(float(s.layer_z[k])));
  for (size_t i = 0; i < s.xyz.size(); ++i) {
    const size_t p = i / 3;
    if (i % 3 < 2) {
      ASSERT_EQ(r.xyz[i], double(float(s.xyz[i]))) << "point " << p;
    } else {
      ASSERT_EQ(r.xyz[i], r.layer_z[std::upper_bound(r.layer_begin.begin(), r.layer_begin.end(),
                                                     std::upper_bound(r.contour_begin.begin(), r.contour_begin.end(), p) -
                                                         r.contour_begin.begin() - 1) -
                                     r.layer_begin.begin() - 1]);
    }
  }
}

TEST_F(CliFiles, LayoutMatchesTheSpecification) {
  for (CliEncoding enc : kEncodings) {
    SCOPED_TRACE(enc == CliEncoding::Binary ? "binary" : "ascii");
    const Slices s = sample(true);
    write_cli_file(path("s.cli"), s, enc);
    const SpecCli f = read_cli_per_spec(slurp(path("s.cli")));
    EXPECT_EQ(f.binary, enc == CliEncoding::Binary);
    EXPECT_EQ(f.header_lines.front(), enc == CliEncoding::Binary ? "$$BINARY" : "$$ASCII");
    EXPECT_EQ(f.units, 1.0);
    EXPECT_EQ(f.version, 200);
    EXPECT_EQ(f.date.size(), 6u);
    EXPECT_EQ(f.layers, long(s.layers()));
    ASSERT_EQ(f.geometry.size(), s.layers());
    // $$DIMENSION: the points' x, y range and the slabs' z range.
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (size_t p = 0; p < s.points(); ++p)
      for (int a = 0; a < 2; ++a) {
        lo[a] = std::min(lo[a], s.xyz[3 * p + a]);
        hi[a] = std::max(hi[a], s.xyz[3 * p + a]);
      }
    ASSERT_EQ(f.dimension.size(), 6u);
    EXPECT_EQ(f.dimension[0], lo[0]);
    EXPECT_EQ(f.dimension[1], lo[1]);
    EXPECT_EQ(f.dimension[3], hi[0]);
    EXPECT_EQ(f.dimension[4], hi[1]);
    EXPECT_NEAR(f.dimension[2], s.layer_z.front() - s.thickness / 2, 1e-12);
    EXPECT_NEAR(f.dimension[5], s.layer_z.back() + s.thickness / 2, 1e-12);
    for (size_t k = 0; k < s.layers(); ++k) {
      const SpecCliLayer& l = f.geometry[k];
      EXPECT_EQ(l.z, enc == CliEncoding::Binary ? double(float(s.layer_z[k])) : s.layer_z[k]);
      ASSERT_EQ(l.polylines.size(), s.layer_begin[k + 1] - s.layer_begin[k]);
      for (size_t i = 0; i < l.polylines.size(); ++i) {
        const size_t c = s.layer_begin[k] + i;
        const SpecCliPolyline& pl = l.polylines[i];
        const uint64_t b = s.contour_begin[c], n = s.contour_begin[c + 1] - b;
        EXPECT_EQ(pl.id, 1);
        const int dir = s.contour_open[c] ? 2 : contour_area(s, c) > 0 ? 1 : 0;
        EXPECT_EQ(pl.dir, dir) << "contour " << c;
        // Closed polylines repeat the first point at the end.
        const size_t count = n + (s.contour_open[c] ? 0 : 1);
        ASSERT_EQ(pl.xy.size(), 2 * count) << "contour " << c;
        for (size_t j = 0; j < count; ++j)
          for (int a = 0; a < 2; ++a) {
            const double v = s.xyz[3 * (b + (j == n ? 0 : j)) + a];
            ASSERT_EQ(pl.xy[2 * j + a], enc == CliEncoding::Binary ? double(float(v)) : v);
          }
      }
    }
  }
}

TEST_F(CliFiles, SlicedTorusKeepsOrientationAndLayers) {
  SliceOptions o;
  o.thickness = 0.05;
  const Slices s = slice_layers(make_torus(3, 1, 48, 24), o);
  ASSERT_GT(s.contours(), 2 * s.layers() - 10);  // most layers: an outer loop and a hole
  for (CliEncoding enc : kEncodings) {
    write_cli_file(path("t.cli"), s, enc);
    const SpecCli f = read_cli_per_spec(slurp(path("t.cli")));
    size_t outer = 0, inner = 0;
    for (const auto& l : f.geometry)
      for (const auto& pl : l.polylines) (pl.dir == 1 ? outer : inner) += 1;
    EXPECT_EQ(outer + inner, s.contours());
    EXPECT_GT(inner, 0u);
    EXPECT_GT(outer, inner - 1);
    const Slices r = read_cli_file(path("t.cli"));
    EXPECT_EQ(r.layer_begin, s.layer_begin);
    EXPECT_EQ(r.contour_begin, s.contour_begin);
    for (size_t c = 0; c < s.contours(); ++c)
      EXPECT_EQ(contour_area(r, c) > 0, contour_area(s, c) > 0);
  }
}

TEST_F(CliFiles, EmptyAndContourFreeSlices) {
  Slices s;
  s.thickness = 0.1;
  s.layer_begin = {0};
  s.contour_begin = {0};
  for (CliEncoding enc : kEncodings) {
    write_cli_file(path("e.cli"), s, enc);
    const Slices r = read_cli_file(path("e.cli"));
    EXPECT_EQ(r.layers(), 0u);
    EXPECT_EQ(r.points(), 0u);
  }
  s.layer_z = {0.05, 0.15, 0.25};
  s.layer_begin = {0, 0, 0, 0};
  for (CliEncoding enc : kEncodings) {
    write_cli_file(path("e.cli"), s, enc);
    const Slices r = read_cli_file(path("e.cli"));
    EXPECT_EQ(r.layers(), 3u);
    EXPECT_EQ(r.contours(), 0u);
  }
}

TEST_F(CliFiles, ContourFilesConvertBothWays) {
  const Slices s = sample(true);
  write_contour_file(path("s.srb"), s, FileFormat::Binary);
  write_cli_file(path("s.cli"), read_contour_file(path("s.srb")), CliEncoding::Ascii);
  write_contour_file(path("back.ctr"), read_cli_file(path("s.cli")), FileFormat::Text);
  const Slices r = read_contour_file(path("back.ctr"));
  expect_same_layers(s, r);
  EXPECT_EQ(std::memcmp(s.xyz.data(), r.xyz.data(), 8 * s.xyz.size()), 0);
}

TEST_F(CliFiles, OtherWritersFilesAreRead) {
  // Units in micrometres, CRLF lines, a comment in the header, a polyline over two lines, a
  // closed polyline without the repeated point, hatches, '+' signs.
  spit(path("o.cli"),
       "$$HEADERSTART\r\n// written by hand //\r\n$$ASCII\r\n$$UNITS/0.001\r\n$$VERSION/200\r\n"
       "$$LABEL/1,part\r\n$$LAYERS/000002\r\n$$HEADEREND\r\n$$GEOMETRYSTART\r\n"
       "$$LAYER/100\r\n$$POLYLINE/1,1,4,0,0,1000,0,\r\n1000,1000,0,0\r\n"
       "$$HATCHES/1,1,0,0,5,5\r\n$$LAYER/+200\r\n$$POLYLINE/1,0,3,0,0,0,1000,1000,1000\r\n"
       "$$POLYLINE/1,2,2,5,5,6,6\r\n$$GEOMETRYEND\r\n");
  const Slices r = read_cli_file(path("o.cli"));
  ASSERT_EQ(r.layers(), 2u);
  EXPECT_EQ(r.layer_z, (std::vector<double>{0.1, 0.2}));
  EXPECT_EQ(r.contour_begin, (std::vector<uint64_t>{0, 3, 6, 8}));
  EXPECT_EQ(r.contour_open, (std::vector<uint8_t>{0, 0, 1}));
  EXPECT_EQ(r.xyz[3], 1.0);
  EXPECT_EQ(r.xyz[5], 0.1);
  EXPECT_NEAR(r.thickness, 0.1, 1e-15);

  // Binary: a line end after $$HEADEREND, short-format layer and polyline, long hatches.
  std::string b = "$$HEADERSTART\n$$BINARY\n$$UNITS/0.5\n$$HEADEREND\n";
  auto u16 = [&](uint16_t v) { b.append(reinterpret_cast<const char*>(&v), 2); };
  auto i32 = [&](int32_t v) { b.append(reinterpret_cast<const char*>(&v), 4); };
  auto f32 = [&](float v) { b.append(reinterpret_cast<const char*>(&v), 4); };
  u16(128), u16(4);                                          // layer z = 4 units
  u16(129), u16(1), u16(1), u16(3), u16(0), u16(0), u16(8), u16(0), u16(0), u16(8);
  u16(132), i32(1), i32(1), f32(0), f32(0), f32(1), f32(1);  // one hatch
  u16(127), f32(6);
  u16(130), i32(1), i32(2), i32(2), f32(1), f32(2), f32(3), f32(4);
  spit(path("o.cli"), b);
  const Slices q = read_cli_file(path("o.cli"));
  EXPECT_EQ(q.layer_z, (std::vector<double>{2, 3}));
  EXPECT_EQ(q.contour_begin, (std::vector<uint64_t>{0, 3, 5}));
  EXPECT_EQ(q.contour_open, (std::vector<uint8_t>{0, 1}));
  EXPECT_EQ(q.xyz[3 * 1 + 0], 4.0);
  EXPECT_EQ(q.xyz[3 * 4 + 1], 2.0);
  EXPECT_EQ(q.xyz[3 * 4 + 2], 3.0);
}

TEST_F(CliFiles, TruncatedFilesAreRefused) {
  const Slices s = sample(true);
  for (CliEncoding enc : kEncodings) {
    write_cli_file(path("t.cli"), s, enc);
    const std::string full = slurp(path("t.cli"));
    size_t accepted = 0;
    for (size_t n = 0; n < full.size(); ++n) {
      spit(path("cut.cli"), full.substr(0, n));
      try {
        const Slices r = read_cli_file(path("cut.cli"));
        // ASCII: only the final line end may be missing. Binary: only a file cut exactly between
        // two polylines of the last layer still parses (the format has no end marker); it then
        // lacks points, it is never taken as whole.
        if (enc == CliEncoding::Ascii) {
          EXPECT_EQ(n, full.size() - 1) << "ascii prefix of " << n << " bytes accepted";
          EXPECT_EQ(r.points(), s.points());
        } else {
          EXPECT_LT(r.points(), s.points());
          ++accepted;
        }
      } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("cut.cli"), std::string::npos) << e.what();
      }
    }
    // Last layer (9 contours): cut after each of its first 3 polylines... and so on.
    EXPECT_LE(accepted, s.layer_begin[s.layers()] - s.layer_begin[s.layers() - 1]);
  }
}

TEST_F(CliFiles, DamagedFilesAreRefusedWithReasons) {
  const std::string head = "$$HEADERSTART\n$$ASCII\n$$UNITS/1\n$$LAYERS/1\n$$HEADEREND\n$$GEOMETRYSTART\n";
  auto ascii = [&](const std::string& body, const char* why) {
    spit(path("d.cli"), head + body);
    EXPECT_ERROR(read_cli_file(path("d.cli")), why);
  };
  ascii("$$LAYER/1\n$$POLYLINE/1,1,3,0,0,1,1\n$$GEOMETRYEND\n", "says 3 points but carries 4 coordinates");
  ascii("$$LAYER/1\n$$POLYLINE/1,1,2000000000,0,0,1,1\n$$GEOMETRYEND\n", "says 2000000000 points");
  ascii("$$LAYER/1\n$$POLYLINE/1,7,2,0,0,1,1\n$$GEOMETRYEND\n", "direction 7 is not 0, 1 or 2");
  ascii("$$LAYER/1\n$$POLYLINE/1,1,2,0,nan,1,1\n$$GEOMETRYEND\n", "not a finite number");
  ascii("$$LAYER/1\n$$POLYLINE/1,1,2,0,inf,1,1\n$$GEOMETRYEND\n", "not a finite number");
  ascii("$$LAYER/1\n$$POLYLINE/1,1,2,0,x,1,1\n$$GEOMETRYEND\n", "not a number");
  ascii("$$POLYLINE/1,1,1,0,0\n$$LAYER/1\n$$GEOMETRYEND\n", "before the first layer");
  ascii("$$LAYER/1\n$$CIRCLE/1,2,3\n$$GEOMETRYEND\n", "line 8: unknown command '$$CIRCLE");
  ascii("$$LAYER/1\n$$LAYER/2\n$$GEOMETRYEND\n", "$$LAYERS says 1 layers but the file has 2");
  ascii("$$LAYER/1\n", "ends before $$GEOMETRYEND");
  ascii("$$LAYER/1\n$$POLYLINE/1,1,0\n$$GEOMETRYEND\n", "a polyline with 0 points");
  spit(path("d.cli"), "$$HEADERSTART\n$$ASCII\n$$UNITS/1\n$$HEADEREND\n$$GEOMETRYSTART\n"
                      "$$LAYER/2\n$$LAYER/1\n$$GEOMETRYEND\n");
  EXPECT_ERROR(read_cli_file(path("d.cli")), "line 7: layer 1 at z = 1 is not above the previous layer");
  spit(path("d.cli"), "solid x\nfacet normal 0 0 1\n");
  EXPECT_ERROR(read_cli_file(path("d.cli")), "not a CLI file");
  spit(path("d.cli"), "$$HEADERSTART\n$$ASCII\n$$UNITS/1\n");
  EXPECT_ERROR(read_cli_file(path("d.cli")), "no $$HEADEREND");
  spit(path("d.cli"), "$$HEADERSTART\n$$ASCII\n$$BINARY\n$$UNITS/1\n$$HEADEREND");
  EXPECT_ERROR(read_cli_file(path("d.cli")), "both $$ASCII and $$BINARY");
  spit(path("d.cli"), "$$HEADERSTART\n$$ASCII\n$$HEADEREND\n$$GEOMETRYSTART\n$$GEOMETRYEND\n");
  EXPECT_ERROR(read_cli_file(path("d.cli")), "no $$UNITS");
  spit(path("d.cli"), "$$HEADERSTART\n$$ASCII\n$$UNITS/-2\n$$HEADEREND\n");
  EXPECT_ERROR(read_cli_file(path("d.cli")), "line 3: $$UNITS/-2 is not a positive number");
  EXPECT_ERROR(read_cli_file(path("missing.cli")), "cannot open");

  std::string bin = "$$HEADERSTART\n$$BINARY\n$$UNITS/1\n$$HEADEREND";
  const size_t at = bin.size();
  auto binary = [&](const std::string& body, const std::string& why) {
    spit(path("d.cli"), bin + body);
    EXPECT_ERROR(read_cli_file(path("d.cli")), why);
  };
  auto raw = [](std::initializer_list<uint32_t> words16, std::initializer_list<float> floats = {}) {
    std::string r;
    for (uint32_t w : words16) r.append(reinterpret_cast<const char*>(&w), 2);
    for (float f : floats) r.append(reinterpret_cast<const char*>(&f), 4);
    return r;
  };
  auto polyline = [](int32_t dir, int32_t n, std::initializer_list<float> xy) {
    std::string r;
    const uint16_t cmd = 130;
    r.append(reinterpret_cast<const char*>(&cmd), 2);
    for (int32_t v : {int32_t(1), dir, n}) r.append(reinterpret_cast<const char*>(&v), 4);
    for (float f : xy) r.append(reinterpret_cast<const char*>(&f), 4);
    return r;
  };
  const std::string layer = raw({127}, {1.0f});
  binary(layer + polyline(1, 0x7fffffff, {0, 0}), "a polyline of 2147483647 points needs 17179869190 bytes but only 22 remain");
  binary(layer + polyline(1, -5, {}), "a polyline with -5 points");
  binary(layer + polyline(3, 1, {0, 0}), "direction 3 is not 0, 1 or 2");
  binary(layer + polyline(1, 2, {0, std::numeric_limits<float>::quiet_NaN(), 1, 1}), "not a finite number");
  binary(layer + polyline(1, 2, {0, std::numeric_limits<float>::infinity(), 1, 1}), "not a finite number");
  binary(raw({127}, {std::numeric_limits<float>::quiet_NaN()}), "byte " + std::to_string(at) + ": layer 0: z is not a finite number");
  binary(layer + raw({0x4141}), "byte " + std::to_string(at + 6) + ": unknown command id 16705");
  binary(layer + raw({130}), "a polyline header (long) needs 14 bytes but only 2 remain");
  binary(raw({7}).substr(0, 1), "a command id needs 2 bytes but only 1 remain");
  binary(raw({132, 1, 0, 0xffff, 0x7fff}), "hatches of 2147483647 lines needs");
}

TEST_F(CliFiles, WriterRefusesWhatCliCannotHold) {
  Slices s = sample(true);
  s.xyz[0] = 1e300;
  EXPECT_ERROR(write_cli_file(path("w.cli"), s, CliEncoding::Binary), "does not fit in a float32");
  EXPECT_TRUE(leftovers().empty());
  write_cli_file(path("w.cli"), s, CliEncoding::Ascii);  // exact doubles: fine in ASCII
  Slices bad = sample(true);
  bad.thickness = -1;
  EXPECT_ERROR(write_cli_file(path("w.cli"), bad, CliEncoding::Ascii), "thickness");
  Slices encoding_only = sample(true);
  encoding_only.xyz.clear();
  EXPECT_ERROR(write_cli_file(path("w.cli"), encoding_only, CliEncoding::Ascii), "no contour points");
  EXPECT_ERROR(write_cli_file(dir + "/no/such/folder/w.cli", sample(true), CliEncoding::Ascii), "cannot create");
}
