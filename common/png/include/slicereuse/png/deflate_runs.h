#pragma once
// RunDeflater: a zlib stream (RFC 1950/1951) of literals and distance-1 matches, i.e. what
// zlib's Z_RLE strategy emits, written directly: no sliding window, runs found 8 bytes at a
// time, and one deflate block whose Huffman codes are built for the image's own symbols. Mask
// images are long runs of 0 and 255, so a 1024x768 8-bit mask compresses to zlib's size in a
// fraction of its time. Any inflater reads the result.
//
// Use: d.add(bytes, n) and d.add_run(byte, n) as often as needed, then d.finish(out), which
// appends the stream to out and leaves d empty for the next stream (a deflater kept per thread
// allocates nothing per image once its buffer has grown). add_run(byte, n) is add() of n
// copies of byte without the bytes (n = 0 adds nothing): its cost does not depend on n, so an
// image that is known as runs (mask_png.h) deflates without ever being written out. Equal
// neighbours are merged, so how a caller splits a run does not change the stream. A caller
// that adds runs one after the other in a loop takes a Runs from runs() instead, adds to it
// (as add_run) and ends it before using the deflater otherwise: its state stays in the
// caller's registers. A deflater kept across calls that may throw should be reset() before
// each stream.
//
// How: as zlib does, the stream is kept as its deflate symbols, counted as they are written. A
// run of byte b and length n is the literal b, then its n - 1 repeats as matches of 258 and a
// last match of the rest, or the rest as literals when it is shorter than 3. Each run becomes
// its symbols, and its part of the Adler-32, as soon as it ends (the next run is of another
// byte); finish() builds the codes from the counts and writes the symbols. A run's matches of
// 258 are kept as one entry and their count, and written a machine word at a time: the black of
// a 16K display is about 230,000 of them per layer.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace slicereuse {

class RunDeflater {
 public:
  class Runs;

  RunDeflater() { reset(); }
  void add(const uint8_t* data, size_t n);
  void add_run(uint8_t byte, size_t n);
  inline Runs runs();
  void finish(std::vector<uint8_t>& out);
  void reset();  // drops what was added since the last finish (e.g. after an error)

  static constexpr unsigned kMaxMatch = 258;
  static constexpr uint16_t kRepeat = 0x8000;  // above every symbol with its extra bits (< 2^14)
  static constexpr size_t kSymbols = 286;  // literal/length alphabet

 private:
  uint16_t* make_room(uint16_t* at);  // grows symbols_; returns where at is now

  // The symbols so far, [0, used_): a literal/length symbol in the low 9 bits and a length's
  // extra bits above (every length is at distance 1), or kRepeat followed by a count of matches
  // of 258 in two entries (low, high 16 bits), and the symbols' counts. The run not ended yet
  // (byte 256 before the first), and Adler-32's sums so far, unreduced (see Runs).
  std::vector<uint16_t> symbols_;
  size_t used_ = 0;
  uint64_t freq_[kSymbols];
  unsigned open_byte_ = 256;
  uint64_t open_n_ = 0;
  uint64_t adler_a_ = 1, adler_b_ = 0;
};

// Runs added to a deflater: the state is copied here and back by end(), so that it stays in
// registers in the caller's loop. Equal neighbours are merged by add(); a run becomes its
// symbols in end_run() when the next one begins.
class RunDeflater::Runs {
 public:
  explicit Runs(RunDeflater& d)
      : d_(&d),
        at_(d.symbols_.data() + d.used_),
        limit_(d.symbols_.data() + d.symbols_.size()),
        byte_(d.open_byte_),
        n_(d.open_n_),
        a_(d.adler_a_),
        b_(d.adler_b_) {}
  void add(uint8_t byte, size_t n) {
    if (n == 0) return;
    if (byte == byte_) {
      n_ += n;
      return;
    }
    end_run();
    byte_ = byte;
    n_ = n;
  }
  // Ends the run begun last: its symbols, counts and Adler-32 (so finish() can write it).
  inline void end_run();
  // Hands the state back to the deflater.
  void end() {
    d_->used_ = size_t(at_ - d_->symbols_.data());
    d_->open_byte_ = byte_;
    d_->open_n_ = n_;
    d_->adler_a_ = a_;
    d_->adler_b_ = b_;
  }

 private:
  // A run of up to kShort bytes is at most kRoom symbols (its literal, 3 matches of 258, a rest
  // of 2 literals); longer ones, and a full buffer, go by long_run().
  static constexpr uint64_t kShort = 3 * 258 + 3;
  static constexpr ptrdiff_t kRoom = 6;
  struct State {
    uint16_t* at;
    uint16_t* limit;
    uint64_t a, b;
  };
  static State long_run(RunDeflater& d, State s, unsigned byte, uint64_t n);

  RunDeflater* d_;
  uint16_t* at_;
  uint16_t* limit_;
  unsigned byte_;
  uint64_t n_;
  uint64_t a_, b_;
};

RunDeflater::Runs RunDeflater::runs() { return Runs(*this); }

namespace deflate_runs {
// Per match length 3..258: its length symbol (257..285), and its extra bits from bit 9.
constexpr std::array<uint16_t, RunDeflater::kMaxMatch + 1> kLengthSymbols = [] {
  constexpr unsigned base[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                 31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
  std::array<uint16_t, RunDeflater::kMaxMatch + 1> t{};
  for (unsigned len = 3; len <= RunDeflater::kMaxMatch; ++len) {
    unsigned i = 28;
    while (base[i] > len) --i;
    t[len] = uint16_t((257 + i) | (len - base[i]) << 9);
  }
  return t;
}();
}  // namespace deflate_runs

void RunDeflater::Runs::end_run() {
  if (byte_ > 255) return;  // no run yet
  if (n_ > kShort || limit_ - at_ < kRoom) {
    const State s = long_run(*d_, {at_, limit_, a_, b_}, byte_, n_);
    at_ = s.at, limit_ = s.limit, a_ = s.a, b_ = s.b;
    return;
  }
  // Adler-32 (RFC 1950): n bytes b take A to A + n b and B to B + n A + b n (n + 1) / 2, mod
  // 65521, reduced only when A reaches 2^32 or B 2^62 (a run of up to kShort bytes adds less
  // than 2^19 to A and 2^43 to B: no overflow).
  const uint64_t b = byte_, n = n_;
  b_ += n * a_ + b * (n * (n + 1) / 2);
  a_ += n * b;
  if ((a_ >> 32) | (b_ >> 62)) {
    a_ %= 65521;
    b_ %= 65521;
  }
  uint64_t* const freq = d_->freq_;
  if (n <= 3) {  // literals only: an anti-aliased mask's grey pixels
    at_[0] = at_[1] = at_[2] = uint16_t(b);
    at_ += n;
    freq[b] += n;
    return;
  }
  const uint64_t repeats = n - 1, full = repeats / kMaxMatch, rest = repeats - full * kMaxMatch;
  constexpr uint16_t kFull = deflate_runs::kLengthSymbols[kMaxMatch];
  at_[0] = uint16_t(b);
  at_[1] = at_[2] = at_[3] = kFull;
  at_ += 1 + full;
  freq[kFull] += full;
  if (rest >= 3) {
    *at_++ = deflate_runs::kLengthSymbols[rest];
    ++freq[deflate_runs::kLengthSymbols[rest] & 511];
    ++freq[b];
  } else {
    at_[0] = at_[1] = uint16_t(b);
    at_ += rest;
    freq[b] += 1 + rest;
  }
}

}  // namespace slicereuse
