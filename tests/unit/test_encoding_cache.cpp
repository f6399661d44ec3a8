// EncodingCache and slice_file_identity: the cached encoding is the file's, it is read once per
// file content (a file rewritten with other content is read again, with the same bytes not;
// another path is read again), members with other faces are refused, and the memory it holds
// is reported and freed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "family.h"
#include "slicereuse/formats/slice_files.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/transfer/encoding_cache.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "slicereuse/util/error.h"
#include "temp_folder.h"

using namespace slicereuse;
namespace fs = std::filesystem;

namespace {

class Cache : public test::TempFolderTest {
 protected:
  void SetUp() override {
    TempFolderTest::SetUp();
    o.shape = "arch";
    o.faces = 3000;
    o.height = 5;
    o.seed = 3;
    base = test::make_family_base(o);
    member = test::make_family_member(base, o, 1);
    SliceOptions s;
    s.thickness = 0.1;
    source = slice_layers(base, s);
    // Planes 1 nm higher: the same layers, contours and points (a binary file of the same
    // size), other t values.
    s.z_start = source.z_start + 1e-6;
    other = slice_layers(base, s);
  }
  test::FamilyOptions o;
  Mesh base, member;
  Slices source, other;  // two encodings of the same mesh
};

}  // namespace

TEST_F(Cache, ReadsEachFileContentOnce) {
  for (FileFormat format : {FileFormat::Binary, FileFormat::Text}) {
    const std::string path = dir + (format == FileFormat::Binary ? "/enc.srb" : "/enc.enc");
    write_encoding_file(path, source, format);
    EncodingCache cache;
    bool hit = true;
    const auto first = cache.get(path, {&member}, &hit);
    EXPECT_FALSE(hit);
    EXPECT_EQ(first->encoding.points(), source.points());
    EXPECT_TRUE(first->encoding.face == source.face && first->encoding.t == source.t);
    EXPECT_TRUE(first->edge_ends == encoded_edge_ends(source, member));
    const auto second = cache.get(path, {&member}, &hit);
    EXPECT_TRUE(hit);
    EXPECT_EQ(first.get(), second.get());
    // The same bytes rewritten: the same content, not read again.
    write_encoding_file(path, source, format);
    EXPECT_EQ(cache.get(path, {&member}, &hit).get(), first.get());
    EXPECT_TRUE(hit);
    // Other content under the same name, at once (a coarse clock may give it the same
    // modification time; a binary file has the same size): read again.
    const auto size = fs::file_size(path);
    write_encoding_file(path, other, format);
    if (format == FileFormat::Binary) ASSERT_EQ(fs::file_size(path), size);
    const auto third = cache.get(path, {&member}, &hit);
    EXPECT_FALSE(hit);
    EXPECT_TRUE(third->encoding.t == other.t);
    EXPECT_FALSE(third->encoding.t == source.t);
    // Another name for the same content: read again (the key includes the path).
    fs::copy_file(path, path + ".copy");
    cache.get(path + ".copy", {&member}, &hit);
    EXPECT_FALSE(hit);
    cache.clear();
    cache.get(path + ".copy", {&member}, &hit);
    EXPECT_FALSE(hit);
  }
}

// bytes() is what the entry's arrays hold: the encoding's (layer heights and offsets, open
// flags, face, edge, t; no points in an encoding file) and the edge ends.
TEST_F(Cache, ReportsAndFreesItsMemory) {
  const std::string path = dir + "/enc.srb";
  write_encoding_file(path, source, FileFormat::Binary);
  EncodingCache cache;
  EXPECT_EQ(cache.bytes(), 0u);
  cache.get(path, {&member});
  const size_t L = source.layers(), C = source.contours(), P = source.points();
  ASSERT_GT(P, 0u);
  // layer_z, layer_begin, contour_begin (doubles, uint64), contour_open (uint8); face (uint32),
  // edge (uint8), t (double) per point; two uint32 edge ends per point.
  const size_t expected = 8 * L + 8 * (L + 1) + 8 * (C + 1) + C + (4 + 1 + 8) * P + 2 * 4 * P;
  EXPECT_EQ(cache.bytes(), expected);
  EXPECT_EQ(cache.clear(), expected);
  EXPECT_EQ(cache.bytes(), 0u);
  EXPECT_EQ(cache.clear(), 0u);
}

// try_clear, what a memory reclaimer calls, gives up at once while another thread holds the
// cache: a check of memory inside a reading get() must not wait for that get() to end (with
// clear() this test never ends: the reading thread waits for the one waiting for it).
TEST_F(Cache, TryClearDoesNotWaitForAReadInProgress) {
  const std::string path = dir + "/enc.srb";
  write_encoding_file(path, source, FileFormat::Binary);
  EncodingCache cache;
  cache.get(path, {&member});
  write_encoding_file(path, source, FileFormat::Text);  // another content: get() reads it again
  int calls = 0;
  size_t during = SIZE_MAX;
  cache.get(path, {&member}, nullptr, [&](double, const char*) {
    if (calls++ == 0) std::thread([&] { during = cache.try_clear(); }).join();
    return true;
  });
  EXPECT_GT(calls, 0);
  EXPECT_EQ(during, 0u);
  const size_t held = cache.bytes();  // the text file's entry, read to the end
  ASSERT_GT(held, 0u);
  EXPECT_EQ(cache.try_clear(), held);  // idle: cleared
  EXPECT_EQ(cache.bytes(), 0u);
}

TEST_F(Cache, IdentityFollowsTheContent) {
  const std::string a = dir + "/a.srb", b = dir + "/b.srb", t = dir + "/t.enc";
  write_encoding_file(a, source, FileFormat::Binary);
  fs::copy_file(a, b);
  EXPECT_EQ(slice_file_identity(a).checksum, slice_file_identity(b).checksum);
  EXPECT_EQ(slice_file_identity(a).size, fs::file_size(a));
  SliceOptions s;
  s.thickness = 0.2;
  write_encoding_file(b, slice_layers(base, s), FileFormat::Binary);
  EXPECT_NE(slice_file_identity(a).checksum, slice_file_identity(b).checksum);
  write_encoding_file(t, source, FileFormat::Text);
  const uint64_t text = slice_file_identity(t).checksum;
  std::fstream f(t, std::ios::in | std::ios::out | std::ios::binary);
  f.seekp(-2, std::ios::end);
  f.put('7');
  f.close();
  EXPECT_NE(slice_file_identity(t).checksum, text);
  EXPECT_THROW(slice_file_identity(dir + "/missing.srb"), Error);
  EXPECT_THROW(slice_file_identity(dir), Error);
}

// A member of another family gets the encoding without edge ends (it is sliced directly); the
// first call that brings a member of the family reads it again, with them.
TEST_F(Cache, KeepsTheEncodingWithoutEdgeEndsForMembersOfAnotherFamily) {
  const std::string path = dir + "/enc.srb";
  write_encoding_file(path, source, FileFormat::Binary);
  test::FamilyOptions other_options = o;
  other_options.shape = "torus";
  const Mesh other = test::make_family_base(other_options);
  EncodingCache cache;
  bool hit = true;
  const auto alone = cache.get(path, {&other}, &hit);
  EXPECT_FALSE(hit);
  EXPECT_TRUE(alone->edge_ends.empty());
  EXPECT_EQ(alone->encoding.points(), source.points());
  EXPECT_EQ(cache.get(path, {&other}, &hit).get(), alone.get());
  EXPECT_TRUE(hit);
  const auto with_family = cache.get(path, {&other, &member}, &hit);
  EXPECT_FALSE(hit);
  EXPECT_TRUE(with_family->edge_ends == encoded_edge_ends(source, member));
  EXPECT_EQ(cache.get(path, {&other}, &hit).get(), with_family.get());
  EXPECT_TRUE(hit);
  EXPECT_THROW(cache.get(dir + "/missing.srb", {&member}), Error);
}
