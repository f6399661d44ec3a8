// RunDeflater's streams must inflate, with zlib's own inflater, to exactly the input.
#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <random>
#include <vector>

#include "slicereuse/png/deflate_runs.h"

using namespace slicereuse;

namespace {

std::vector<uint8_t> inflate_all(const std::vector<uint8_t>& z, size_t size) {
  std::vector<uint8_t> out(size + 1);
  uLongf n = uLongf(out.size());
  EXPECT_EQ(uncompress(out.data(), &n, z.data(), uLong(z.size())), Z_OK);
  out.resize(n);
  return out;
}

// Deflates data in pieces of the given size, so runs cross add() calls.
std::vector<uint8_t> deflate_in_pieces(const std::vector<uint8_t>& data, size_t piece) {
  std::vector<uint8_t> z;
  RunDeflater d;
  for (size_t i = 0; i < data.size(); i += piece) d.add(data.data() + i, std::min(piece, data.size() - i));
  d.finish(z);
  return z;
}

}  // namespace

TEST(RunDeflater, RoundTripsRunsOfEveryLength) {
  std::vector<uint8_t> data;
  // Runs of 1..600 bytes: every match length and the 1- and 2-byte leftovers after 258s.
  for (size_t n = 1; n <= 600; ++n) data.insert(data.end(), n, uint8_t(n % 2 ? 255 : n % 251));
  for (size_t piece : {size_t(1), size_t(7), size_t(1025), data.size()})
    EXPECT_EQ(inflate_all(deflate_in_pieces(data, piece), data.size()), data) << "piece " << piece;
}

TEST(RunDeflater, RoundTripsRandomAndEmptyInput) {
  std::mt19937 rng(5);
  std::vector<uint8_t> data(100000);
  for (auto& b : data) b = uint8_t(rng());
  EXPECT_EQ(inflate_all(deflate_in_pieces(data, 4096), data.size()), data);
  EXPECT_TRUE(inflate_all(deflate_in_pieces({}, 1), 0).empty());
}

TEST(RunDeflater, LimitsCodeLengthsOnSkewedFrequencies) {
  // Byte k appears 2^k times: a plain Huffman tree would be 18 deep, deflate allows 15.
  std::vector<uint8_t> data;
  for (int k = 0; k < 18; ++k) data.insert(data.end(), size_t(1) << k, uint8_t(k));
  std::shuffle(data.begin(), data.end(), std::mt19937(3));
  EXPECT_EQ(inflate_all(deflate_in_pieces(data, 1000), data.size()), data);
}

TEST(RunDeflater, CompressesAMaskLikeZlibsRunLengthStrategy) {
  // 768 rows of 1025 bytes: filter byte, black, a white span, black.
  std::vector<uint8_t> data;
  for (int r = 0; r < 768; ++r) {
    data.push_back(0);
    data.insert(data.end(), 300 + r / 4, 0);
    data.insert(data.end(), 400, 255);
    data.insert(data.end(), 1024 - 700 - r / 4, 0);
  }
  const std::vector<uint8_t> z = deflate_in_pieces(data, 1025);
  EXPECT_EQ(inflate_all(z, data.size()), data);
  uLongf bound = compressBound(uLong(data.size()));
  std::vector<uint8_t> zz(bound);
  z_stream s{};
  deflateInit2(&s, 1, Z_DEFLATED, 15, 8, Z_RLE);
  s.next_in = data.data();
  s.avail_in = uInt(data.size());
  s.next_out = zz.data();
  s.avail_out = uInt(bound);
  ASSERT_EQ(deflate(&s, Z_FINISH), Z_STREAM_END);
  const size_t zlib_size = s.total_out;
  deflateEnd(&s);
  EXPECT_LE(z.size(), zlib_size + zlib_size / 10);  // within 10 % of zlib
}

TEST(RunDeflater, RunsWithoutBytesGiveTheSameStream) {
  // Long runs (beyond 65521, where the Adler-32 formula wraps) mixed with bytes.
  const std::vector<std::pair<uint8_t, size_t>> runs = {
      {0, 1}, {0, 70000}, {255, 3}, {7, 1}, {255, 300000}, {0, 2}, {255, 65521}, {0, 131043}, {9, 0}};
  std::vector<uint8_t> data, by_bytes, by_runs;
  for (const auto& [b, n] : runs) data.insert(data.end(), n, b);
  RunDeflater a, r;
  a.add(data.data(), data.size());
  for (const auto& [b, n] : runs) r.add_run(b, n);
  a.finish(by_bytes);
  r.finish(by_runs);
  EXPECT_EQ(by_runs, by_bytes);
  EXPECT_EQ(inflate_all(by_runs, data.size()), data);
}

TEST(RunDeflater, AdlerOfManyAndHugeRunsMatchesZlibs) {
  // Runs of up to 2^24 bytes and more, far longer than the runs whose Adler-32 sums go in one
  // step (they go in steps, reduced after each), between shorter runs and bytes added as bytes.
  std::vector<uint8_t> data, z;
  RunDeflater r;
  std::mt19937_64 rng(5);
  const uint8_t some[] = {1, 2, 255, 0, 255, 3};
  for (int i = 0; i < 40; ++i) {
    const uint8_t b = uint8_t(i % 2 ? 255 : 1 + i);
    const size_t n = i % 7 == 0 ? (size_t(1) << 24) + 12345 + rng() % 99 : 1 + rng() % 3000000;
    data.insert(data.end(), n, b);
    r.add_run(b, n);
    if (i % 5 == 0) {
      data.insert(data.end(), std::begin(some), std::end(some));
      r.add(some, sizeof some);
    }
  }
  r.finish(z);
  ASSERT_GT(data.size(), size_t(1) << 26);
  const uint32_t expected = uint32_t(adler32(adler32(0, nullptr, 0), data.data(), uInt(data.size())));
  const uint32_t stored = uint32_t(z[z.size() - 4]) << 24 | uint32_t(z[z.size() - 3]) << 16 |
                          uint32_t(z[z.size() - 2]) << 8 | z[z.size() - 1];
  EXPECT_EQ(stored, expected);
  EXPECT_EQ(inflate_all(z, data.size()), data);
}

TEST(RunDeflater, EachFinishStartsAFreshStreamAndResetDropsInput) {
  std::vector<uint8_t> a(5000, 0), b(7000, 255);
  for (size_t i = 0; i < a.size(); i += 97) a[i] = uint8_t(i);
  std::vector<uint8_t> first, second, dropped, fresh;
  RunDeflater kept;
  kept.add(a.data(), a.size());
  kept.finish(first);
  kept.add(b.data(), b.size());
  kept.finish(second);
  kept.add_run(9, 123456);  // abandoned, e.g. by an error half-way through an image
  kept.add(a.data(), 10);
  kept.reset();
  kept.add(b.data(), b.size());
  kept.finish(dropped);
  RunDeflater d;
  d.add(b.data(), b.size());
  d.finish(fresh);
  EXPECT_EQ(inflate_all(first, a.size()), a);
  EXPECT_EQ(second, fresh);
  EXPECT_EQ(dropped, fresh);
  EXPECT_EQ(inflate_all(fresh, b.size()), b);
}

TEST(RunDeflater, StreamsOfEveryRunLengthAfterAFewBytesMatchZlibsAdler) {
  // Every rest of a run after its 258-byte matches (0 to 257: literals below 3, a match above),
  // the run starting in add() and going on in add_run().
  for (size_t n = 1; n <= 3 * 258 + 2; n += 7) {
    std::vector<uint8_t> data = {1, 2, 2};
    data.insert(data.end(), n, 2);
    data.push_back(3);
    std::vector<uint8_t> z;
    RunDeflater d;
    d.add(data.data(), 3);
    d.add_run(2, n);
    d.add_run(3, 1);
    d.finish(z);
    ASSERT_EQ(inflate_all(z, data.size()), data) << n;
  }
}

TEST(RunDeflater, RunsSplitAnyWayAndAddedThroughRunsGiveTheMergedStream) {
  // An anti-aliased mask's runs: single grey pixels between black and white runs of up to two
  // rows (beyond three matches of 258), some grey levels twice in a row. Added as bytes, as
  // runs split into pieces (empty ones in between), and through runs() in sessions of a few
  // hundred runs (so that the symbols outgrow their first buffer within a session).
  std::mt19937 rng(17);
  std::vector<std::pair<uint8_t, size_t>> runs;
  std::vector<uint8_t> data;
  for (int i = 0; i < 30000; ++i) {
    const uint8_t byte = i % 4 == 0 ? 0 : i % 4 == 2 ? 255 : uint8_t(1 + rng() % 254);
    const size_t n = i % 2 == 0 ? 1 + rng() % 2050 : 1 + rng() % 2;
    runs.push_back({byte, n});
    data.insert(data.end(), n, byte);
  }
  std::vector<uint8_t> by_bytes, by_pieces, through_runs;
  RunDeflater a, b, c;
  a.add(data.data(), data.size());
  a.finish(by_bytes);
  for (const auto& [byte, n] : runs) {
    const size_t first = rng() % (n + 1);
    b.add_run(byte, first);
    b.add_run(uint8_t(rng()), 0);
    b.add_run(byte, n - first);
  }
  b.finish(by_pieces);
  for (size_t i = 0; i < runs.size();) {
    RunDeflater::Runs r = c.runs();
    for (const size_t end = std::min(runs.size(), i + 1 + rng() % 500); i < end; ++i) {
      r.add(runs[i].first, runs[i].second / 2);
      r.add(runs[i].first, runs[i].second - runs[i].second / 2);
    }
    r.end();
  }
  c.finish(through_runs);
  EXPECT_EQ(by_pieces, by_bytes);
  EXPECT_EQ(through_runs, by_bytes);
  EXPECT_EQ(inflate_all(by_bytes, data.size()), data);
}
