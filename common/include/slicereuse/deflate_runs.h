#pragma once
// RunDeflater: a zlib stream (RFC 1950/1951) of literals and distance-1 matches, i.e. what
// zlib's Z_RLE strategy emits, written directly: no sliding window, runs found 8 bytes at a
// time, and one deflate block whose Huffman codes are built for the image's own symbols. Mask
// images are long runs of 0 and 255, so a 1024x768 8-bit mask compresses to zlib's size in a
// fraction of its time. Any inflater reads the result.
//
// Use: RunDeflater d(out); d.add(bytes, n) and d.add_run(byte, n) as often as needed;
// d.finish(). The stream is appended to out. add_run(byte, n) is add() of n copies of byte
// without the bytes: its cost does not depend on n (the Adler-32 of a run is a formula), so an
// image that is known as runs (mask_png.h) deflates without ever being written out.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace slicereuse {

class RunDeflater {
 public:
  explicit RunDeflater(std::vector<uint8_t>& out);
  void add(const uint8_t* data, size_t n);
  void add_run(uint8_t byte, size_t n);
  void finish();

 private:
  void repeats();  // records the pending repeats of the last literal
  void count_run(uint8_t byte, size_t n);  // the symbols of a run
  void fold_adler();                      // run_b_ into adler_

  // Adler-32 of runs: A is kept reduced in run_a_, B's increments add up unreduced in run_b_,
  // which stays below 2^64: a run of at most kMaxRun = 2^24 bytes adds less than
  // 2^24 * 2^16 + 255 * 2^48 / 2 < 2^56, and run_b_ is folded once it passes kMaxB = 2^62.
  static constexpr uint64_t kAdlerMod = 65521;
  static constexpr uint64_t kMaxRun = uint64_t(1) << 24;
  static constexpr uint64_t kMaxB = uint64_t(1) << 62;

  std::vector<uint8_t>& out_;
  std::vector<uint16_t> symbols_;  // literal byte, or 256 + match length (3..258)
  int last_ = -1;                  // last byte recorded, or -1 before the first
  size_t pending_ = 0;             // bytes equal to last_ seen since it was recorded
  uint32_t adler_ = 1;  // A in the low half, B in the high half, as far as folded
  uint64_t run_a_ = 1;
  uint64_t run_b_ = 0;
};

}  // namespace slicereuse
