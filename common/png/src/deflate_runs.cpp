#include "slicereuse/png/deflate_runs.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <utility>

namespace slicereuse {
namespace {

constexpr unsigned kEndOfBlock = 256;
// Extra bits of length symbols 257..285 (RFC 1951 3.2.5).
constexpr unsigned kLengthExtra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                       2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
// The order in which the code-length code's lengths are sent (RFC 1951 3.2.7).
constexpr unsigned kCodeLengthOrder[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};

// Largest alphabet: the literal/length symbols (the code-length alphabet has 19).
constexpr size_t kMaxSymbols = RunDeflater::kSymbols;

// Huffman code lengths for the frequencies of n <= kMaxSymbols symbols, none longer than limit:
// a Huffman tree, rebuilt on halved frequencies while it is too deep. Symbols of frequency 0 get
// no code. Built with two queues (the leaves sorted by frequency, the joined nodes in the order
// they are made, which is by frequency too) into fixed arrays: the same tree as a priority queue
// of (frequency, node) that numbers leaves by symbol, without its allocations.
void code_lengths(const uint64_t* freq_in, size_t n, unsigned limit, uint8_t* length) {
  uint64_t freq[kMaxSymbols];
  std::copy(freq_in, freq_in + n, freq);
  for (;;) {
    // Symbols by (frequency, symbol). An anti-aliased mask uses most of the 286 symbols, most
    // of them (its grey levels) rarely: those of frequency below kCounted are placed by a
    // counting sort (symbols in increasing order within a frequency), the few others after
    // them by a sort of (frequency, symbol) keys.
    constexpr size_t kCounted = 256;
    uint16_t at[kCounted] = {};
    uint64_t frequent[kMaxSymbols];
    size_t m = 0, n_frequent = 0;
    for (size_t s = 0; s < n; ++s) {
      if (freq[s] == 0) continue;
      ++m;
      if (freq[s] < kCounted)
        ++at[freq[s]];
      else
        frequent[n_frequent++] = freq[s] << 9 | s;
    }
    for (size_t f = 0, sum = 0; f < kCounted; ++f) sum += std::exchange(at[f], uint16_t(sum));
    uint16_t leaf[kMaxSymbols];
    for (size_t s = 0; s < n; ++s)
      if (freq[s] != 0 && freq[s] < kCounted) leaf[at[freq[s]]++] = uint16_t(s);
    std::sort(frequent, frequent + n_frequent);
    for (size_t i = 0; i < n_frequent; ++i) leaf[m - n_frequent + i] = uint16_t(frequent[i] & 511);
    // Nodes 0..m-1 are the sorted leaves, m.. the joined ones; parent of each.
    uint64_t weight[2 * kMaxSymbols];
    uint16_t parent[2 * kMaxSymbols];
    for (size_t i = 0; i < m; ++i) weight[i] = freq[leaf[i]];
    size_t next_leaf = 0, next_joined = m, made = m;
    // The lighter of the next leaf and the next joined node, ties to the leaf (a priority
    // queue numbers leaves before joined nodes); chosen without a branch, as the choice
    // follows no pattern.
    auto smallest = [&] {
      const uint64_t leaf_weight = next_leaf < m ? weight[next_leaf] : UINT64_MAX;
      const uint64_t joined_weight = next_joined < made ? weight[next_joined] : UINT64_MAX;
      const bool is_leaf = leaf_weight <= joined_weight;
      const size_t node = is_leaf ? next_leaf : next_joined;
      next_leaf += is_leaf;
      next_joined += !is_leaf;
      return node;
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
  static const std::array<uint8_t, 256> reversed = [] {
    std::array<uint8_t, 256> r{};
    for (unsigned b = 0; b < 256; ++b)
      for (unsigned i = 0; i < 8; ++i) r[b] |= uint8_t(((b >> i) & 1u) << (7 - i));
    return r;
  }();
  unsigned count[16] = {0}, next[16] = {0};
  for (size_t s = 0; s < n; ++s) ++count[length[s]];
  count[0] = 0;
  for (unsigned bits = 1, code = 0; bits < 16; ++bits) next[bits] = code = (code + count[bits - 1]) << 1;
  for (size_t s = 0; s < n; ++s) {
    const unsigned code = next[length[s]]++;  // (length 0: a count nobody reads)
    const unsigned r16 = unsigned(reversed[code & 255]) << 8 | reversed[(code >> 8) & 255];
    codes[s] = length[s] ? uint16_t(r16 >> (16 - length[s])) : 0;
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
  Runs runs(*this);
  for (size_t i = 0; i < n;) {
    // A run of data[i], found a word at a time while all 8 bytes match.
    const uint8_t byte = data[i];
    const uint64_t pattern = 0x0101010101010101ULL * byte;
    size_t j = i + 1;
    uint64_t word;
    while (j + 8 <= n && (std::memcpy(&word, data + j, 8), word == pattern)) j += 8;
    while (j < n && data[j] == byte) ++j;
    runs.add(byte, j - i);
    i = j;
  }
  runs.end();
}

void RunDeflater::add_run(uint8_t byte, size_t n) {
  Runs runs(*this);
  runs.add(byte, n);
  runs.end();
}

uint16_t* RunDeflater::make_room(uint16_t* at) {
  const size_t i = size_t(at - symbols_.data());
  symbols_.resize(std::max<size_t>(4096, 2 * symbols_.size()));
  return symbols_.data() + i;
}

void RunDeflater::reset() {
  used_ = 0;
  std::fill(freq_, freq_ + kSymbols, uint64_t(0));
  open_byte_ = 256;
  open_n_ = 0;
  adler_a_ = 1;
  adler_b_ = 0;
}

// end_run() for a run of more than kShort bytes, or without room for kRoom symbols: Adler-32
// reduced before and after each step of up to 2^24 bytes (which then adds less than 2^32 to A
// and 2^40 + 255 * 2^47 < 2^56 to B), and room made for all of the run's symbols.
RunDeflater::Runs::State RunDeflater::Runs::long_run(RunDeflater& d, State s, unsigned byte, uint64_t n) {
  s.a %= 65521;
  s.b %= 65521;
  for (uint64_t left = n; left > 0;) {
    const uint64_t step = std::min(left, uint64_t(1) << 24);
    s.b += step * s.a + byte * (step * (step + 1) / 2);
    s.a += step * byte;
    s.a %= 65521;
    s.b %= 65521;
    left -= step;
  }
  const uint64_t repeats = n - 1, full = repeats / kMaxMatch, rest = repeats - full * kMaxMatch;
  // The matches of 258 as repeat entries of up to 2^32 - 1 each (3 symbols' room apiece), or as
  // themselves when there are only a few.
  constexpr uint64_t kMaxRepeat = 0xffffffff, kFewest = 3;
  const uint64_t room = full < kFewest ? full : 3 * ((full + kMaxRepeat - 1) / kMaxRepeat);
  while (uint64_t(s.limit - s.at) < room + 3) {
    s.at = d.make_room(s.at);
    s.limit = d.symbols_.data() + d.symbols_.size();
  }
  constexpr uint16_t kFull = deflate_runs::kLengthSymbols[kMaxMatch];
  *s.at++ = uint16_t(byte);
  if (full < kFewest) {
    s.at = std::fill_n(s.at, full, kFull);
  } else {
    for (uint64_t left = full; left > 0;) {
      const uint64_t count = std::min(left, kMaxRepeat);
      *s.at++ = kRepeat;
      *s.at++ = uint16_t(count);
      *s.at++ = uint16_t(count >> 16);
      left -= count;
    }
  }
  d.freq_[kFull] += full;
  if (rest >= 3) {
    *s.at++ = deflate_runs::kLengthSymbols[rest];
    ++d.freq_[deflate_runs::kLengthSymbols[rest] & 511];
    ++d.freq_[byte];
  } else {
    s.at = std::fill_n(s.at, rest, uint16_t(byte));
    d.freq_[byte] += 1 + rest;
  }
  return s;
}

namespace {

// Where a symbol's table entry keeps how many bits it sends (see finish).
constexpr int kCountShift = 56;

}  // namespace

void RunDeflater::finish(std::vector<uint8_t>& out) {
  Runs last(*this);
  last.end_run();
  last.end();
  uint64_t freq[kSymbols];
  size_t symbols = 0;
  for (size_t i = 0; i < kSymbols; ++i) symbols += freq[i] = freq_[i];
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
  // Per symbol in one word: its code, the code's length from bit 48 (where a length's extra
  // bits go), and from bit 56 all its bits: code, extra bits and, for a length, distance code 0
  // (one 0 bit), at most 15 + 5 + 1.
  uint64_t code[512] = {};
  for (unsigned sym = 0; sym < kMaxSymbols; ++sym) {
    const unsigned extra = sym > 256 ? kLengthExtra[sym - 257] + 1 : 0;
    code[sym] = lit_code[sym] | uint64_t(lit_length[sym]) << 48 | uint64_t(lit_length[sym] + extra) << kCountShift;
  }
  // Two symbols (at most 42 bits) between drains.
  auto bits = [&code](uint16_t sym, unsigned& count) {
    const uint64_t c = code[sym & 511];
    count = unsigned(c >> kCountShift);
    return (c & 0xffff) | uint64_t(sym >> 9) << ((c >> 48) & 0xff);
  };
  // A repeat entry's matches of 258: as many of their codes as fit in 48 bits at a time (a
  // match's code and its distance bit take 2 to 16 bits).
  unsigned full_n;
  const uint64_t full_bits = bits(deflate_runs::kLengthSymbols[kMaxMatch], full_n);
  const unsigned per_word = full_n ? 48 / full_n : 1;  // no code: the image has no such match
  uint64_t full_word = 0;
  for (unsigned i = 0; i < per_word; ++i) full_word |= full_bits << (i * full_n);
  const uint16_t* sym = symbols_.data();
  const uint16_t* const end = sym + used_;
  while (sym < end) {
    for (; sym + 2 <= end && !((sym[0] | sym[1]) & kRepeat); sym += 2) {
      unsigned n0, n1;
      const uint64_t b0 = bits(sym[0], n0), b1 = bits(sym[1], n1);
      w.add(b0 | b1 << n0, n0 + n1);
      w.drain();
    }
    if (sym == end) break;
    if (*sym & kRepeat) {
      uint64_t count = uint64_t(sym[1]) | uint64_t(sym[2]) << 16;
      sym += 3;
      for (; count >= per_word; count -= per_word) w.put(full_word, per_word * full_n);
      for (; count > 0; --count) w.put(full_bits, full_n);
    } else {
      unsigned n0;
      const uint64_t b0 = bits(*sym++, n0);
      w.put(b0, n0);
    }
  }
  w.put(lit_code[kEndOfBlock], lit_length[kEndOfBlock]);
  out.resize(start + w.flush());
  const uint32_t adler = uint32_t((adler_b_ % 65521) << 16 | (adler_a_ % 65521));
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(uint8_t(adler >> shift));
  reset();
}

}  // namespace slicereuse
