#include <omp.h>

#include <algorithm>
#include <charconv>
#include <string>
#include <vector>

#include "mask_stack.h"
#include "slicereuse/png/mask_png.h"
#include "slicereuse/printfiles/compare_mask_stacks.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse {
namespace {

const char* const PHASE = "comparing mask images";

std::string size_text(const MaskImage& m) {
  return std::to_string(m.width) + "x" + std::to_string(m.height);
}

// Every figure of one layer in one pass over both images. Branch-free on bytes, so the compiler
// vectorizes it: the on/off states differ exactly when the levels differ in their top bit
// (>= 128), and |a - b| is max - min. The counts are summed in 16 bits over blocks of at most
// 65535 pixels, so the vector loop adds 16-bit lanes instead of widening every byte to 64 bits.
void compare_pixels(const uint8_t* a, const uint8_t* b, size_t n, LayerSimilarity& l) {
  constexpr size_t kBlock = 65535;
  uint64_t differ = 0, over_one = 0;
  uint8_t max_difference = 0;
  for (size_t begin = 0; begin < n; begin += kBlock) {
    const size_t end = std::min(n, begin + kBlock);
    uint16_t block_differ = 0, block_over_one = 0;
    for (size_t p = begin; p < end; ++p) {
      const uint8_t x = a[p], y = b[p];
      const uint8_t d = uint8_t(std::max(x, y) - std::min(x, y));
      block_differ = uint16_t(block_differ + ((x ^ y) >> 7));
      block_over_one = uint16_t(block_over_one + (d > 1));
      max_difference = std::max(max_difference, d);
    }
    differ += block_differ;
    over_one += block_over_one;
  }
  l.differing_pixels = differ;
  l.over_one_level_pixels = over_one;
  l.max_grey_difference = max_difference;
}

void write_csv(const std::string& path, const StackComparison& c) {
  // to_chars prints a double in shortest round-trip form in at most 24 characters, a uint64 in
  // 20: a row is at most 4 integers and a double, each followed by ',' or the newline.
  constexpr size_t kDoubleChars = 24, kUintChars = 20;
  std::string text = "layer,similarity,differing_pixels,max_grey_difference,over_one_level_pixels\n";
  char row[4 * (kUintChars + 1) + kDoubleChars + 1];
  for (const LayerSimilarity& l : c.layers) {
    char* p = std::to_chars(row, row + kUintChars, uint64_t(l.layer)).ptr;
    *p++ = ',';
    p = std::to_chars(p, p + kDoubleChars, l.similarity).ptr;
    for (const uint64_t v : {l.differing_pixels, uint64_t(l.max_grey_difference), l.over_one_level_pixels}) {
      *p++ = ',';
      p = std::to_chars(p, p + kUintChars, v).ptr;
    }
    *p++ = '\n';
    text.append(row, p);
  }
  AtomicFile file(path);
  file.write(text.data(), text.size());
  file.commit();
}

}  // namespace

StackComparison compare_mask_stacks(const std::string& stack_a, const std::string& stack_b,
                                    const std::string& report_csv, const Progress& progress) {
  if (!report_csv.empty()) check_writable(report_csv);
  MaskStack a(stack_a), b(stack_b);
  const size_t L = a.layers();
  if (b.layers() != L)
    throw Error("mask stacks differ in layer count: '" + stack_a + "' has " + std::to_string(L) +
                " layers, '" + stack_b + "' has " + std::to_string(b.layers()));
  StackComparison result;
  result.layers.resize(L);
  std::vector<uint64_t> pixels(L);  // per layer, for the share over the stack
  // Archives are read on this thread (one zip handle each); decoding runs on all cores.
  const size_t batch = size_t(16) * size_t(omp_get_max_threads());
  std::vector<std::vector<uint8_t>> bytes_a(batch), bytes_b(batch);
  for (size_t first = 0; first < L; first += batch) {
    report_progress(progress, double(first) / double(L), PHASE);
    const size_t n = std::min(batch, L - first);
    for (size_t i = 0; i < n; ++i) {
      a.read(first + i, bytes_a[i]);
      b.read(first + i, bytes_b[i]);
    }
    parallel_blocks(
        n,
        [&](size_t i) {
          thread_local MaskImage ia, ib;
          const size_t k = first + i;
          a.decode(k, bytes_a[i], ia);
          LayerSimilarity& l = result.layers[k];
          l.layer = k;
          // Equal bytes hold equal images (e.g. reused and direct .sl1, .goo or .ctb layers, which
          // the encoders write byte for byte alike; a PNG, a .goo layer (0x55 first) and a mask's
          // .ctb layer (its top-left pixels' run first) do not begin alike): one decode checks
          // them, the second is skipped and every difference stays 0.
          if (bytes_a[i] != bytes_b[i]) {
            b.decode(k, bytes_b[i], ib);
            if (ia.width != ib.width || ia.height != ib.height)
              throw Error("mask images of layer " + std::to_string(k) + " differ in size: '" +
                          a.layer_name(k) + "' is " + size_text(ia) + ", '" + b.layer_name(k) +
                          "' is " + size_text(ib));
            compare_pixels(ia.pixels.data(), ib.pixels.data(), ia.pixels.size(), l);
          }
          pixels[k] = ia.pixels.size();
          l.similarity = 1.0 - double(l.differing_pixels) / double(pixels[k]);
        },
        {}, PHASE);
  }
  uint64_t all_pixels = 0;
  for (const LayerSimilarity& l : result.layers) {
    all_pixels += pixels[l.layer];
    result.differing_pixels += l.differing_pixels;
    result.over_one_level_pixels += l.over_one_level_pixels;
    if (l.similarity < result.min_similarity) {
      result.min_similarity = l.similarity;
      result.worst_layer = l.layer;
    }
    if (l.max_grey_difference > result.max_grey_difference) {
      result.max_grey_difference = l.max_grey_difference;
      result.max_grey_difference_layer = l.layer;
    }
    if (l.over_one_level_pixels > result.layers[result.over_one_level_layer].over_one_level_pixels)
      result.over_one_level_layer = l.layer;
  }
  result.over_one_level_share = double(result.over_one_level_pixels) / double(all_pixels);
  report_progress(progress, 1, PHASE);
  if (!report_csv.empty()) write_csv(report_csv, result);
  return result;
}

}  // namespace slicereuse
