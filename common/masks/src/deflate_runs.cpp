#include "slicereuse/masks/deflate_runs.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstring>

namespace slicereuse {
namespace {

constexpr unsigned kEndOfBlock = 256;
constexpr unsigned kMaxMatch = 258;
constexpr unsigned kLengthBase[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                      31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr unsigned kLengthExtra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                       2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
// The order in which the code-length code's lengths are sent (RFC 1951 3.2.7).
constexpr unsigned kCodeLengthOrder[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};

// Length symbol (257..285) of a match length, and its extra bits.
struct LengthCode {
  uint16_t symbol;
  uint8_t extra_bits;
  uint16_t extra;
};

const std::array<LengthCode, 259>& length_codes() {
  static const std::array<LengthCode, 259> table = [] {
    std::array<LengthCode, 259> t{};
    for (unsigned len = 3; len <= 258; ++len) {
      unsigned i = 28;
      while (kLengthBase[i] > len) --i;
      t[len] = {uint16_t(257 + i), uint8_t(kLengthExtra[i]), uint16_t(len - kLengthBase[i])};
    }
    return t;
  }();
  return table;
}

// Largest alphabet: 286 literal/length symbols (the code-length alphabet has 19).
constexpr size_t kMaxSymbols = 286;

// Huffman code lengths for the frequencies of n <= kMaxSymbols symbols, none longer than limit:
// a Huffman tree, rebuilt on halved frequencies while it is too deep. Symbols of frequency 0 get
// no code. Built with two queues (the leaves sorted by frequency, the joined nodes in the order
// they are made, which is by frequency too) into fixed arrays: the same tree as a priority queue
// of (frequency, node) that numbers leaves by symbol, without its allocations.
void code_lengths(const uint64_t* freq_in, size_t n, unsigned limit, uint8_t* length) {
  uint64_t freq[kMaxSymbols];
  std::copy(freq_in, freq_in + n, freq);
  for (;;) {
    // Symbols by (frequency, symbol), sorted as one key each: an anti-aliased mask uses most of
    // the 286 symbols, too many for an insertion sort.
    uint64_t by_frequency[kMaxSymbols];
    size_t m = 0;
    for (size_t s = 0; s < n; ++s)
      if (freq[s]) by_frequency[m++] = freq[s] << 9 | s;
    std::sort(by_frequency, by_frequency + m);
    uint16_t leaf[kMaxSymbols];
    for (size_t i = 0; i < m; ++i) leaf[i] = uint16_t(by_frequency[i] & 511);
    // Nodes 0..m-1 are the sorted leaves, m.. the joined ones; parent of each.
    uint64_t weight[2 * kMaxSymbols];
    uint16_t parent[2 * kMaxSymbols];
    for (size_t i = 0; i < m; ++i) weight[i] = freq[leaf[i]];
    size_t next_leaf = 0, next_joined = m, made = m;
    auto smallest = [&] {
      // Ties go to the leaf: a priority queue numbers leaves before joined nodes.
      if (next_leaf < m && (next_joined == made || weight[next_leaf] <= weight[next_joined])) return next_leaf++;
      return next_joined++;
    };
    for (; made + 1 < 2 * m; ++made) {
      const size_t a = smallest(), b = smallest();
      weight[made] = weight[a] + weight[b];
      parent[a] = parent[b] = uint16_t(made);
    }
    uint8_t depth[2 * kMaxSymbols];
    unsigned deepest = 0;
    if (m > 0) depth[made - 1] = 0;  // the root
    for (size_t i = made - 1; m > 0 && i-- > 0;) {
      depth[i] = uint8_t(depth[parent[i]] + 1);
      if (i < m) deepest = std::max<unsigned>(deepest, depth[i]);
    }
    if (deepest <= limit) {
      std::fill(length, length + n, uint8_t(0));
      for (size_t i = 0; i < m; ++i) length[leaf[i]] = depth[i];
      return;
    }
    for (size_t s = 0; s < n; ++s)
      if (freq[s]) freq[s] = (freq[s] + 1) / 2;
  }
}

// Canonical codes (RFC 1951 3.2.2), bit-reversed because deflate sends Huffman codes most
// significant bit first into an LSB-first stream.
void canonical_codes(const uint8_t* length, size_t n, uint16_t* codes) {
  unsigned count[16] = {0}, next[16] = {0};
  for (size_t s = 0; s < n; ++s) ++count[length[s]];
  count[0] = 0;
  for (unsigned bits = 1, code = 0; bits < 16; ++bits) next[bits] = code = (code + count[bits - 1]) << 1;
  for (size_t s = 0; s < n; ++s) {
    codes[s] = 0;
    if (length[s]) {
      const unsigned code = next[length[s]]++;
      unsigned r = 0;
      for (unsigned i = 0; i < length[s]; ++i) r |= ((code >> i) & 1u) << (length[s] - 1 - i);
      codes[s] = uint16_t(r);
    }
  }
}

// Writes bits LSB first into memory the caller sized for them, with 8 bytes of slack: add()
// puts bits into a 64-bit buffer, at most 56 of them between two drain()s; drain() stores the
// whole buffer and moves on by its complete bytes, without a branch. put() is add() and drain().
class BitWriter {
 public:
  explicit BitWriter(uint8_t* dst) : begin_(dst), at_(dst) {}
  void add(uint64_t value, unsigned count) {  // value < 2^count
    buffer_ |= value << used_;
    used_ += count;
  }
  void drain() {
    std::memcpy(at_, &buffer_, 8);  // little-endian host, as the PNG/zip code assumes
    at_ += used_ >> 3;
    buffer_ >>= used_ & 56;
    used_ &= 7;
  }
  void put(uint64_t value, unsigned count) {
    add(value, count);
    drain();
  }
  // Pads the last byte with zero bits; returns the bytes written.
  size_t flush() {
    std::memcpy(at_, &buffer_, 8);
    return size_t(at_ - begin_) + (used_ + 7) / 8;
  }

 private:
  uint8_t* begin_;
  uint8_t* at_;
  uint64_t buffer_ = 0;
  unsigned used_ = 0;
};

// One code length run, as the code-length alphabet sends it: symbol 0..18 and its extra bits.
struct LengthRun {
  uint8_t symbol, extra;
};

// The code lengths as code-length symbols: 16 repeats the previous length 3..6 times, 17 and
// 18 repeat zero 3..10 and 11..138 times. Writes at most n_lengths runs; returns how many.
size_t length_runs(const uint8_t* lengths, size_t n_lengths, LengthRun* runs) {
  size_t count = 0;
  for (size_t i = 0; i < n_lengths;) {
    size_t j = i;
    while (j < n_lengths && lengths[j] == lengths[i]) ++j;
    size_t n = j - i;
    if (lengths[i] == 0) {
      for (; n >= 11; n -= std::min<size_t>(n, 138)) runs[count++] = {18, uint8_t(std::min<size_t>(n, 138) - 11)};
      if (n >= 3) {
        runs[count++] = {17, uint8_t(n - 3)};
        n = 0;
      }
      for (; n > 0; --n) runs[count++] = {0, 0};
    } else {
      runs[count++] = {lengths[i], 0};
      for (--n; n >= 3; n -= std::min<size_t>(n, 6)) runs[count++] = {16, uint8_t(std::min<size_t>(n, 6) - 3)};
      for (; n > 0; --n) runs[count++] = {lengths[i], 0};
    }
    i = j;
  }
  return count;
}

}  // namespace

void RunDeflater::add(const uint8_t* data, size_t n) {
  fold_adler();
  const uint32_t adler = uint32_t(adler32(uint32_t(adler_b_ << 16 | adler_a_), data, uInt(n)));
  adler_a_ = adler & 0xffff;
  adler_b_ = adler >> 16;
  size_t i = 0;
  while (i < n) {
    if (data[i] == last_) {
      // Extend the run a word at a time while all 8 bytes match.
      const uint64_t pattern = 0x0101010101010101ULL * uint8_t(last_);
      size_t j = i;
      uint64_t word;
      while (j + 8 <= n && (std::memcpy(&word, data + j, 8), word == pattern)) j += 8;
      while (j < n && data[j] == last_) ++j;
      runs_.back() += uint64_t(j - i) << 8;
      i = j;
    } else {
      last_ = data[i++];
      runs_.push_back(uint64_t(1) << 8 | uint64_t(last_));
    }
  }
}

void RunDeflater::add_run(uint8_t byte, size_t n) {
  if (n == 0) return;
  if (n > kMaxRun) {  // longer than any mask image: in pieces that keep the bound
    for (; n > kMaxRun; n -= kMaxRun) add_run(byte, kMaxRun);
    add_run(byte, n);
    return;
  }
  // Adler-32 over n bytes b: A' = A + n*b, B' = B + n*A + b*n*(n+1)/2, mod 65521 (see adler_b_).
  adler_b_ += n * adler_a_ + uint64_t(byte) * (n * (n + 1) / 2);
  adler_a_ += n * byte;
  if (adler_a_ >= (uint64_t(1) << 32) || adler_b_ >= (uint64_t(1) << 62)) fold_adler();
  if (byte == last_) {
    runs_.back() += uint64_t(n) << 8;
  } else {
    runs_.push_back(uint64_t(n) << 8 | byte);
    last_ = byte;
  }
}

void RunDeflater::fold_adler() {
  adler_a_ %= 65521;
  adler_b_ %= 65521;
}

void RunDeflater::finish(std::vector<uint8_t>& out) {
  fold_adler();
  const auto& lengths_of = length_codes();
  // A run of byte b and length n is the literal b, then its n - 1 repeats as matches of 258 and
  // a last match of the rest, or the rest as literals when it is shorter than 3. Counted into
  // locals and per rest, not per deflate symbol: increments of the same few counters, one run
  // after the other, would wait for each other. Strings of literals count byte by byte.
  uint64_t freq[kMaxSymbols] = {};
  uint64_t per_rest[kMaxMatch] = {}, full_matches = 0;
  size_t symbols = 0;
  const uint8_t* literal = literals_.data();
  for (const uint64_t run : runs_) {
    if (run & kLiterals) {
      const uint64_t n = run & ~kLiterals;
      for (uint64_t j = 0; j < n; ++j) ++freq[literal[j]];
      literal += n;
      symbols += n;
      continue;
    }
    const uint64_t repeats = (run >> 8) - 1, full = repeats / kMaxMatch;
    const unsigned rest = unsigned(repeats - full * kMaxMatch);
    freq[run & 0xff] += 1 + (rest < 3 ? rest : 0);
    full_matches += full;
    ++per_rest[rest];
  }
  freq[lengths_of[kMaxMatch].symbol] += full_matches;
  symbols += full_matches + per_rest[1] + 2 * per_rest[2];
  for (unsigned rest = 0; rest < kMaxMatch; ++rest) {
    symbols += per_rest[rest];  // each run's literal
    if (rest < 3) continue;
    freq[lengths_of[rest].symbol] += per_rest[rest];
    symbols += per_rest[rest];  // and its last match
  }
  freq[kEndOfBlock] = 1;
  freq[0] |= 1;  // at least two codes, so the code is complete for every inflater
  uint8_t lit_length[kMaxSymbols];
  uint16_t lit_code[kMaxSymbols];
  code_lengths(freq, kMaxSymbols, 15, lit_length);
  canonical_codes(lit_length, kMaxSymbols, lit_code);
  size_t hlit = kMaxSymbols;
  while (hlit > 257 && lit_length[hlit - 1] == 0) --hlit;
  // Every match is at distance 1 (distance code 0); code 1 is unused but makes the code complete.
  constexpr size_t kDistCodes = 2;
  uint8_t all[kMaxSymbols + kDistCodes];
  std::copy(lit_length, lit_length + hlit, all);
  all[hlit] = all[hlit + 1] = 1;
  LengthRun runs[kMaxSymbols + kDistCodes];
  const size_t n_runs = length_runs(all, hlit + kDistCodes, runs);
  uint64_t run_freq[19] = {};
  for (size_t i = 0; i < n_runs; ++i) ++run_freq[runs[i].symbol];
  run_freq[0] |= 1;
  run_freq[18] |= 1;
  uint8_t run_length[19];
  uint16_t run_code[19];
  code_lengths(run_freq, 19, 7, run_length);
  canonical_codes(run_length, 19, run_code);
  size_t hclen = 19;
  while (hclen > 4 && run_length[kCodeLengthOrder[hclen - 1]] == 0) --hclen;

  out.push_back(0x78);  // deflate, 32 KiB window
  out.push_back(0x01);  // fastest; (0x78 << 8 | 0x01) is a multiple of 31
  // Room for the block: 17 header bits, 3 per code length code, 7+7 per length run, and at
  // most 15 + 5 + 1 bits per symbol, plus the end code and 8 bytes of slack for the last word.
  const size_t start = out.size();
  out.resize(start + (17 + 3 * 19 + 14 * n_runs + 21 * (symbols + 1)) / 8 + 16);
  BitWriter w(out.data() + start);
  w.put(0b101, 3);  // final block, dynamic Huffman codes
  w.put(hlit - 257, 5);
  w.put(kDistCodes - 1, 5);
  w.put(hclen - 4, 4);
  for (size_t i = 0; i < hclen; ++i) w.put(run_length[kCodeLengthOrder[i]], 3);
  for (size_t i = 0; i < n_runs; ++i) {
    const LengthRun& r = runs[i];
    w.put(run_code[r.symbol], run_length[r.symbol]);
    if (r.symbol == 16) w.put(r.extra, 2);
    if (r.symbol == 17) w.put(r.extra, 3);
    if (r.symbol == 18) w.put(r.extra, 7);
  }
  // Each match length's bits in one piece, looked up once per length rather than through three
  // tables per run: its length code, extra bits and distance code 0 (distance 1), at most
  // 15 + 5 + 1 bits. Lengths 0..2 are no match (zero bits).
  uint32_t match_bits[kMaxMatch + 1] = {};
  uint8_t match_nbits[kMaxMatch + 1] = {};
  for (unsigned len = 3; len <= kMaxMatch; ++len) {
    const LengthCode& lc = lengths_of[len];
    match_bits[len] = uint32_t(lit_code[lc.symbol]) | uint32_t(lc.extra) << lit_length[lc.symbol];
    match_nbits[len] = uint8_t(lit_length[lc.symbol] + lc.extra_bits + 1);
  }
  // Between drains: a literal and a match (15 + 21 bits), or a literal and two more (3 * 15).
  // The rest after the full matches is chosen without a branch (a mask's runs alternate between
  // the two kinds unpredictably).
  literal = literals_.data();
  for (const uint64_t run : runs_) {
    if (run & kLiterals) {
      const uint64_t n = run & ~kLiterals;
      for (uint64_t j = 0; j < n; ++j) w.put(lit_code[literal[j]], lit_length[literal[j]]);
      literal += n;
      continue;
    }
    const unsigned byte = unsigned(run & 0xff);
    const uint64_t repeats = (run >> 8) - 1, full = repeats / kMaxMatch;
    const unsigned rest = unsigned(repeats - full * kMaxMatch);
    const uint64_t lit = lit_code[byte];
    const unsigned lit_bits = lit_length[byte];
    w.add(lit, lit_bits);
    for (uint64_t i = 0; i < full; ++i) w.put(match_bits[kMaxMatch], match_nbits[kMaxMatch]);
    const bool match = rest >= 3;
    const unsigned literal_bits = (match ? 0 : rest) * lit_bits;  // rest < 3 literals
    w.add(match ? match_bits[rest] : (lit | lit << lit_bits) & ((uint64_t(1) << literal_bits) - 1),
          match ? match_nbits[rest] : literal_bits);
    w.drain();
  }
  w.put(lit_code[kEndOfBlock], lit_length[kEndOfBlock]);
  out.resize(start + w.flush());
  const uint32_t adler = uint32_t(adler_b_ << 16 | adler_a_);
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(uint8_t(adler >> shift));
  reset();
}

void RunDeflater::reset() {
  runs_.clear();
  literals_.clear();
  last_ = -1;
  adler_a_ = 1;
  adler_b_ = 0;
}

}  // namespace slicereuse
