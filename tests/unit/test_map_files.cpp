// Map files: text and binary round trips are exact; truncation, corruption, absurd counts and
// maps that do not fit their fingerprints are rejected with messages naming the problem.
#include <gtest/gtest.h>
#include <xxhash.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "error_of.h"
#include "family.h"
#include "slicereuse/formats/map_files.h"
#include "slicereuse/formats/slice_files.h"
#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/util/error.h"
#include "test_files.h"

using namespace slicereuse;
using slicereuse::test::error_of;
using slicereuse::test::slurp;
using slicereuse::test::spit;
namespace fs = std::filesystem;

namespace {

// A small valid map from a family mesh onto itself, with irregular barycentric coordinates.
SurfaceMap sample_map() {
  test::FamilyOptions o;
  o.shape = "ear";
  o.faces = 600;
  const Mesh m = test::make_family_base(o);
  SurfaceMap map;
  map.source = map.target = mesh_fingerprint(m);
  map.source_vertices = map.target_vertices = m.vertices();
  map.source_faces = m.F;
  for (size_t i = 0; i < m.vertices(); ++i) {
    map.face.push_back(uint32_t((i * 7) % m.faces()));
    const double a = double(i % 13) / 13, b = (1 - a) * double(i % 5) / 7;
    map.bary.insert(map.bary.end(), {a, b, 1 - a - b});
  }
  return map;
}

class MapFiles : public test::FileTest {};

void expect_equal(const SurfaceMap& a, const SurfaceMap& b) {
  EXPECT_EQ(a.source, b.source);
  EXPECT_EQ(a.target, b.target);
  EXPECT_EQ(a.source_vertices, b.source_vertices);
  EXPECT_EQ(a.target_vertices, b.target_vertices);
  EXPECT_EQ(a.source_faces, b.source_faces);
  EXPECT_EQ(a.face, b.face);
  EXPECT_EQ(a.bary, b.bary);  // bit-exact: shortest round-trip doubles in text
}

}  // namespace

TEST_F(MapFiles, RoundTripsAreExact) {
  const SurfaceMap map = sample_map();
  for (const char* name : {"m.map", "m.srb", "M.SRB"}) {
    write_map_file(path(name), map);
    expect_equal(read_map_file(path(name)), map);
  }
  EXPECT_EQ(slurp(path("m.srb")).substr(0, 4), "\x89SRB");
  EXPECT_EQ(slurp(path("m.map")).substr(0, 18), "# slicereuse map 1");
  for (const auto& e : fs::directory_iterator(dir)) EXPECT_EQ(e.path().string().find(".tmp-"), std::string::npos);
}

TEST_F(MapFiles, InvalidMapIsNotWritten) {
  SurfaceMap map = sample_map();
  map.bary[0] = 2;
  EXPECT_ERROR(write_map_file(path("bad.srb"), map), "barycentric coordinate outside [0, 1]");
  EXPECT_FALSE(fs::exists(path("bad.srb")));
  map = sample_map();
  map.source_faces[0] ^= 1;
  EXPECT_ERROR(write_map_file(path("bad.map"), map), "do not match its source fingerprint");
  map = sample_map();
  map.face[3] = uint32_t(map.target.faces);
  EXPECT_ERROR(write_map_file(path("bad.map"), map), "maps to target face");
}

TEST_F(MapFiles, BinaryTruncatedOrCorruptedAnywhereIsRejected) {
  write_map_file(path("m.srb"), sample_map());
  const std::string good = slurp(path("m.srb"));
  for (size_t n = 0; n < good.size(); n += 1 + n / 3) {
    spit(path("t.srb"), good.substr(0, n));
    EXPECT_THROW(read_map_file(path("t.srb")), Error) << "truncated to " << n;
  }
  EXPECT_ERROR((spit(path("t.srb"), good.substr(0, 100)), read_map_file(path("t.srb"))), "truncated file");
  for (size_t at = 0; at < good.size(); at += 1 + at / 5) {
    std::string b = good;
    b[at] ^= 0x10;
    spit(path("c.srb"), b);
    EXPECT_THROW(read_map_file(path("c.srb")), Error) << "byte " << at;
  }
  std::string b = good;
  b[b.size() - 3] ^= 1;
  spit(path("c.srb"), b);
  EXPECT_ERROR(read_map_file(path("c.srb")), "section bary: checksum mismatch");
}

TEST_F(MapFiles, AbsurdCountsAreRejectedBeforeAllocating) {
  write_map_file(path("m.srb"), sample_map());
  std::string b = slurp(path("m.srb"));
  const uint64_t huge = uint64_t(1) << 60;
  std::memcpy(&b[16], &huge, 8);  // source vertices
  const size_t table_end = 80 + 32 * 3;
  const uint64_t sum = XXH3_64bits(b.data(), table_end);
  std::memcpy(&b[table_end], &sum, 8);
  spit(path("a.srb"), b);
  EXPECT_ERROR(read_map_file(path("a.srb")), "more than the file's");
  write_map_file(path("m.map"), sample_map());
  std::string t = slurp(path("m.map"));
  const size_t at = t.find("# source ") + 9;
  t.replace(at, t.find(' ', at) - at, "99999999999");
  spit(path("a.map"), t);
  EXPECT_ERROR(read_map_file(path("a.map")), "more than the file can hold");
}

TEST_F(MapFiles, TextDamageIsRejectedWithLineNumbers) {
  write_map_file(path("m.map"), sample_map());
  const std::string good = slurp(path("m.map"));
  spit(path("t.map"), good.substr(0, good.rfind('\n', good.size() / 2) + 1));
  EXPECT_ERROR(read_map_file(path("t.map")), "truncated file?");
  spit(path("t.map"), good.substr(0, good.size() / 2));
  EXPECT_THROW(read_map_file(path("t.map")), Error);
  std::string b = good;
  b.replace(b.find("\nv ") + 1, 1, "x");
  spit(path("t.map"), b);
  EXPECT_ERROR(read_map_file(path("t.map")), "expected a vertex line");
  b = good;
  const size_t v = b.find("\nv ") + 3;
  b.replace(v, b.find(' ', v) - v, "nan");
  spit(path("t.map"), b);
  EXPECT_ERROR(read_map_file(path("t.map")), "expected a target face id");
  spit(path("t.map"), good + "v 0 1 0 0\n");
  EXPECT_ERROR(read_map_file(path("t.map")), "unexpected line after the last vertex line");
  spit(path("t.map"), "hello\n");
  EXPECT_ERROR(read_map_file(path("t.map")), "not a slicereuse map file");
  spit(path("t.map"), "# slicereuse map 2\n");
  EXPECT_ERROR(read_map_file(path("t.map")), "line 1: the first line must be");
  EXPECT_ERROR(read_map_file(path("missing.map")), "cannot open the map file");
}

TEST_F(MapFiles, WrongFingerprintsAreRejected) {
  SurfaceMap map = sample_map();
  write_map_file(path("m.map"), map);
  std::string t = slurp(path("m.map"));
  // Another source hash: the faces in the file no longer match it.
  const size_t line = t.find("# source ");
  const size_t hash_at = t.find('\n', line) - 16;
  t[hash_at] = t[hash_at] == '0' ? '1' : '0';
  spit(path("f.map"), t);
  EXPECT_ERROR(read_map_file(path("f.map")), "do not match its source fingerprint");
  // The map's target is not this mesh.
  test::FamilyOptions o;
  o.shape = "ear";
  o.faces = 700;
  EXPECT_ERROR(check_map_target(map, test::make_family_base(o)), "is not the map's target");
  // An empty file is no map file.
  EXPECT_ERROR((spit(path("e.srb"), ""), read_map_file(path("e.srb"))), "not a slicereuse map file");
}

TEST_F(MapFiles, SliceAndMapFilesAreToldApartByTheirKind) {
  write_map_file(path("m.srb"), sample_map());
  EXPECT_ERROR(read_contour_file(path("m.srb")), "this is a map file, expected a contour file");
  Slices s;
  s.thickness = 1;
  s.layer_z = {0.5};
  s.layer_begin = {0, 1};
  s.contour_begin = {0, 1};
  s.contour_open = {0};
  s.xyz = {0, 0, 0.5};
  write_contour_file(path("c.srb"), s, FileFormat::Binary);
  EXPECT_ERROR(read_map_file(path("c.srb")), "this is a contour file, expected a map file");
}
