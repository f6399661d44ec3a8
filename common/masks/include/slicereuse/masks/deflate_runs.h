#pragma once
// RunDeflater: a zlib stream (RFC 1950/1951) of literals and distance-1 matches, i.e. what
// zlib's Z_RLE strategy emits, written directly: no sliding window, runs found 8 bytes at a
// time, and one deflate block whose Huffman codes are built for the image's own symbols. Mask
// images are long runs of 0 and 255, so a 1024x768 8-bit mask compresses to zlib's size in a
// fraction of its time. Any inflater reads the result.
//
// Use: d.add(bytes, n), d.add_run(byte, n) and d.add_literal(byte) as often as needed, then
// d.finish(out), which appends the stream to out and leaves d empty for the next stream (a
// deflater kept per thread allocates nothing per image once its buffer has grown).
// add_run(byte, n) is add() of n copies of byte without the bytes: its cost does not depend on
// n (the Adler-32 of a run is a formula), so an image that is known as runs (mask_png.h)
// deflates without ever being written out. add_literal(byte) sends byte as a literal: n of them
// are the symbols add_run(byte, n) sends for n <= 3, at a fraction of a run's cost (an
// anti-aliased mask's grey pixels). add_run merges a run with the one before of the same byte
// and add_literal does not, so a caller that wants add_run's stream merges equal neighbours
// first. A deflater kept across calls that may throw should be reset() before each stream.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace slicereuse {

class RunDeflater {
 public:
  void add(const uint8_t* data, size_t n);
  void add_run(uint8_t byte, size_t n);
  // byte as a literal; inline, as it is called once per grey pixel.
  void add_literal(uint8_t byte) {
    adler_a_ += byte;  // by at most 255 and 2^32 + 255 per byte: far from the bounds below
    adler_b_ += adler_a_;
    if (adler_a_ >= (uint64_t(1) << 32) || adler_b_ >= (uint64_t(1) << 62)) fold_adler();
    literals_.push_back(byte);
    if (last_ != kInLiterals) {
      runs_.push_back(kLiterals);
      last_ = kInLiterals;
    }
    ++runs_.back();
  }
  void finish(std::vector<uint8_t>& out);
  void reset();  // drops what was added since the last finish (e.g. after an error)

 private:
  void fold_adler();  // reduces adler_a_ and adler_b_ mod 65521

  // The input as runs of equal bytes, the byte in the low 8 bits and the length above; each
  // run is sent as a literal followed by distance-1 matches of its repeats. Recording runs
  // instead of deflate symbols makes a run's cost independent of its length. An entry with
  // kLiterals set stands for the next (entry - kLiterals) bytes of literals_, sent as literals.
  static constexpr uint64_t kLiterals = uint64_t(1) << 63;
  static constexpr int kInLiterals = -2;
  std::vector<uint64_t> runs_;
  std::vector<uint8_t> literals_;
  int last_ = -1;  // byte of the last run, kInLiterals after literals, or -1 before the first

  // Adler-32 of runs: A and B summed unreduced and reduced only when A reaches 2^32 or B 2^62
  // (a reduction per run was most of a run's cost). From there, a run of at most kMaxRun = 2^24
  // bytes adds less than 2^33 to A and 2^24 * 2^32 + 255 * 2^48 / 2 < 2^57 to B: no overflow.
  static constexpr uint64_t kMaxRun = uint64_t(1) << 24;
  uint64_t adler_a_ = 1;
  uint64_t adler_b_ = 0;
};

}  // namespace slicereuse
