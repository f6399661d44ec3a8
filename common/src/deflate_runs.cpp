#include "slicereuse/deflate_runs.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <functional>
#include <queue>

namespace slicereuse {
namespace {

constexpr unsigned kEndOfBlock = 256;
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

// Huffman code lengths for the frequencies, none longer than limit: a Huffman tree, rebuilt on
// halved frequencies while it is too deep. Symbols of frequency 0 get no code.
std::vector<uint8_t> code_lengths(std::vector<uint64_t> freq, unsigned limit) {
  const size_t n = freq.size();
  std::vector<uint8_t> length(n, 0);
  for (;;) {
    std::vector<int> parent;
    using Node = std::pair<uint64_t, int>;
    std::priority_queue<Node, std::vector<Node>, std::greater<Node>> heap;
    std::vector<int> leaf(n, -1);
    for (size_t s = 0; s < n; ++s)
      if (freq[s]) {
        leaf[s] = int(parent.size());
        parent.push_back(-1);
        heap.push({freq[s], leaf[s]});
      }
    while (heap.size() > 1) {
      const Node a = heap.top();
      heap.pop();
      const Node b = heap.top();
      heap.pop();
      const int joined = int(parent.size());
      parent.push_back(-1);
      parent[a.second] = parent[b.second] = joined;
      heap.push({a.first + b.first, joined});
    }
    unsigned deepest = 0;
    for (size_t s = 0; s < n; ++s) {
      unsigned depth = 0;
      if (leaf[s] >= 0)
        for (int x = leaf[s]; parent[x] >= 0; x = parent[x]) ++depth;
      length[s] = uint8_t(depth);
      deepest = std::max(deepest, depth);
    }
    if (deepest <= limit) return length;
    for (uint64_t& f : freq)
      if (f) f = (f + 1) / 2;
  }
}

// Canonical codes (RFC 1951 3.2.2), bit-reversed because deflate sends Huffman codes most
// significant bit first into an LSB-first stream.
std::vector<uint16_t> canonical_codes(const std::vector<uint8_t>& length) {
  unsigned count[16] = {0}, next[16] = {0};
  for (uint8_t l : length) ++count[l];
  count[0] = 0;
  for (unsigned bits = 1, code = 0; bits < 16; ++bits) next[bits] = code = (code + count[bits - 1]) << 1;
  std::vector<uint16_t> codes(length.size(), 0);
  for (size_t s = 0; s < length.size(); ++s)
    if (length[s]) {
      const unsigned code = next[length[s]]++;
      unsigned r = 0;
      for (unsigned i = 0; i < length[s]; ++i) r |= ((code >> i) & 1u) << (length[s] - 1 - i);
      codes[s] = uint16_t(r);
    }
  return codes;
}

// Writes bits LSB first into memory the caller sized for them, 32 bits at a time.
class BitWriter {
 public:
  explicit BitWriter(uint8_t* dst) : begin_(dst), at_(dst) {}
  void put(uint64_t value, unsigned count) {  // count <= 32
    buffer_ |= value << used_;
    used_ += count;
    if (used_ >= 32) {
      const uint32_t word = uint32_t(buffer_);
      std::memcpy(at_, &word, 4);  // little-endian host, as the PNG/zip code assumes
      at_ += 4;
      buffer_ >>= 32;
      used_ -= 32;
    }
  }
  // Pads the last byte with zero bits; returns the bytes written.
  size_t flush() {
    for (; used_ > 0; used_ = used_ > 8 ? used_ - 8 : 0) {
      *at_++ = uint8_t(buffer_);
      buffer_ >>= 8;
    }
    return size_t(at_ - begin_);
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
// 18 repeat zero 3..10 and 11..138 times.
std::vector<LengthRun> length_runs(const std::vector<uint8_t>& lengths) {
  std::vector<LengthRun> runs;
  for (size_t i = 0; i < lengths.size();) {
    size_t j = i;
    while (j < lengths.size() && lengths[j] == lengths[i]) ++j;
    size_t n = j - i;
    if (lengths[i] == 0) {
      for (; n >= 11; n -= std::min<size_t>(n, 138)) runs.push_back({18, uint8_t(std::min<size_t>(n, 138) - 11)});
      if (n >= 3) {
        runs.push_back({17, uint8_t(n - 3)});
        n = 0;
      }
      for (; n > 0; --n) runs.push_back({0, 0});
    } else {
      runs.push_back({lengths[i], 0});
      for (--n; n >= 3; n -= std::min<size_t>(n, 6)) runs.push_back({16, uint8_t(std::min<size_t>(n, 6) - 3)});
      for (; n > 0; --n) runs.push_back({lengths[i], 0});
    }
    i = j;
  }
  return runs;
}

}  // namespace

RunDeflater::RunDeflater(std::vector<uint8_t>& out) : out_(out) {}

void RunDeflater::repeats() {
  while (pending_ >= 3) {
    const size_t n = std::min<size_t>(pending_, 258);
    symbols_.push_back(uint16_t(256 + n));
    pending_ -= n;
  }
  for (; pending_ > 0; --pending_) symbols_.push_back(uint16_t(last_));
}

void RunDeflater::add(const uint8_t* data, size_t n) {
  fold_adler();
  adler_ = uint32_t(adler32(adler_, data, uInt(n)));
  run_a_ = adler_ & 0xffff;
  size_t i = 0;
  while (i < n) {
    if (data[i] == last_) {
      // Extend the run a word at a time while all 8 bytes match.
      const uint64_t pattern = 0x0101010101010101ULL * uint8_t(last_);
      size_t j = i;
      uint64_t word;
      while (j + 8 <= n && (std::memcpy(&word, data + j, 8), word == pattern)) j += 8;
      while (j < n && data[j] == last_) ++j;
      pending_ += j - i;
      i = j;
    } else {
      repeats();
      symbols_.push_back(data[i]);
      last_ = data[i++];
    }
  }
}

void RunDeflater::add_run(uint8_t byte, size_t n) {
  if (n == 0) return;
  // Adler-32 over n bytes b: A' = A + n*b, B' = B + n*A + b*n*(n+1)/2, mod 65521. B is reduced
  // only when it could overflow (see run_b_), not per run: the reductions were most of the cost.
  const uint64_t a = run_a_;
  if (n > kMaxRun || run_b_ > kMaxB) {
    fold_adler();
    if (n > kMaxRun) {  // longer than any mask image: in pieces that keep the bound
      for (; n > kMaxRun; n -= kMaxRun) add_run(byte, kMaxRun);
      add_run(byte, n);
      return;
    }
  }
  run_b_ += n * a + uint64_t(byte) * (n * (n + 1) / 2);
  run_a_ = (a + n * byte) % kAdlerMod;
  count_run(byte, n);
}

void RunDeflater::fold_adler() {
  const uint64_t b = ((adler_ >> 16) + run_b_) % kAdlerMod;
  adler_ = uint32_t(b << 16 | run_a_);
  run_b_ = 0;
}

void RunDeflater::count_run(uint8_t byte, size_t n) {
  if (byte != last_) {
    repeats();
    symbols_.push_back(byte);
    last_ = byte;
    --n;
  }
  pending_ += n;
}

void RunDeflater::finish() {
  repeats();
  fold_adler();
  const auto& lengths_of = length_codes();
  // Counted per recorded symbol (literal, or 256 + match length), then per deflate symbol.
  std::array<uint32_t, 256 + 259> count{};
  for (uint16_t s : symbols_) ++count[s];
  std::vector<uint64_t> freq(286, 0);
  for (unsigned s = 0; s < 256; ++s) freq[s] = count[s];
  for (unsigned len = 3; len <= 258; ++len) freq[lengths_of[len].symbol] += count[256 + len];
  freq[kEndOfBlock] = 1;
  freq[0] |= 1;  // at least two codes, so the code is complete for every inflater
  const std::vector<uint8_t> lit_length = code_lengths(freq, 15);
  const std::vector<uint16_t> lit_code = canonical_codes(lit_length);
  size_t hlit = 286;
  while (hlit > 257 && lit_length[hlit - 1] == 0) --hlit;
  // Every match is at distance 1 (distance code 0); code 1 is unused but makes the code complete.
  const std::vector<uint8_t> dist_length = {1, 1};

  std::vector<uint8_t> all(lit_length.begin(), lit_length.begin() + hlit);
  all.insert(all.end(), dist_length.begin(), dist_length.end());
  const std::vector<LengthRun> runs = length_runs(all);
  std::vector<uint64_t> run_freq(19, 0);
  for (const LengthRun& r : runs) ++run_freq[r.symbol];
  run_freq[0] |= 1;
  run_freq[18] |= 1;
  const std::vector<uint8_t> run_length = code_lengths(run_freq, 7);
  const std::vector<uint16_t> run_code = canonical_codes(run_length);
  size_t hclen = 19;
  while (hclen > 4 && run_length[kCodeLengthOrder[hclen - 1]] == 0) --hclen;

  out_.push_back(0x78);  // deflate, 32 KiB window
  out_.push_back(0x01);  // fastest; (0x78 << 8 | 0x01) is a multiple of 31
  // Room for the block: 17 header bits, 3 per code length code, 7+7 per length run, and at
  // most 15 + 5 + 1 bits per symbol, plus the end code and 8 bytes of slack for the last word.
  const size_t start = out_.size();
  out_.resize(start + (17 + 3 * 19 + 14 * runs.size() + 21 * (symbols_.size() + 1)) / 8 + 16);
  BitWriter w(out_.data() + start);
  w.put(0b101, 3);  // final block, dynamic Huffman codes
  w.put(hlit - 257, 5);
  w.put(dist_length.size() - 1, 5);
  w.put(hclen - 4, 4);
  for (size_t i = 0; i < hclen; ++i) w.put(run_length[kCodeLengthOrder[i]], 3);
  for (const LengthRun& r : runs) {
    w.put(run_code[r.symbol], run_length[r.symbol]);
    if (r.symbol == 16) w.put(r.extra, 2);
    if (r.symbol == 17) w.put(r.extra, 3);
    if (r.symbol == 18) w.put(r.extra, 7);
  }
  // Each recorded symbol's bits in one piece: a literal's code, or a match's length code, extra
  // bits and distance code 0 (distance 1), at most 15 + 5 + 1 bits.
  std::array<uint32_t, 256 + 259> bits{};
  std::array<uint8_t, 256 + 259> nbits{};
  for (unsigned s = 0; s < 256; ++s) {
    bits[s] = lit_code[s];
    nbits[s] = lit_length[s];
  }
  for (unsigned len = 3; len <= 258; ++len) {
    const LengthCode& lc = lengths_of[len];
    const unsigned n = lit_length[lc.symbol];
    bits[256 + len] = uint32_t(lit_code[lc.symbol]) | uint32_t(lc.extra) << n;
    nbits[256 + len] = uint8_t(n + lc.extra_bits + 1);
  }
  for (uint16_t s : symbols_) w.put(bits[s], nbits[s]);
  w.put(lit_code[kEndOfBlock], lit_length[kEndOfBlock]);
  out_.resize(start + w.flush());
  for (int shift = 24; shift >= 0; shift -= 8) out_.push_back(uint8_t(adler_ >> shift));
  symbols_.clear();
}

}  // namespace slicereuse
