#include <omp.h>

#include <algorithm>
#include <charconv>
#include <string>
#include <vector>

#include "mask_stack.h"
#include "slicereuse/masks/compare_mask_stacks.h"
#include "slicereuse/masks/mask_png.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse {
namespace {

const char* const PHASE = "comparing mask images";

std::string size_text(const MaskImage& m) {
  return std::to_string(m.width) + "x" + std::to_string(m.height);
}

void write_csv(const std::string& path, const StackComparison& c) {
  std::string text = "layer,similarity,differing_pixels\n";
  char buf[64];
  for (const LayerSimilarity& l : c.layers) {
    char* p = std::to_chars(buf, buf + sizeof buf, l.layer).ptr;
    *p++ = ',';
    p = std::to_chars(p, buf + sizeof buf, l.similarity).ptr;
    *p++ = ',';
    p = std::to_chars(p, buf + sizeof buf, l.differing_pixels).ptr;
    *p++ = '\n';
    text.append(buf, p);
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
          uint64_t differ = 0;
          // Equal bytes hold equal images (e.g. reused and direct .sl1 or .goo layers, which the
          // encoders write byte for byte alike; a PNG and a .goo layer never begin alike): one
          // decode checks them, the second is skipped.
          if (bytes_a[i] != bytes_b[i]) {
            b.decode(k, bytes_b[i], ib);
            if (ia.width != ib.width || ia.height != ib.height)
              throw Error("mask images of layer " + std::to_string(k) + " differ in size: '" +
                          a.layer_name(k) + "' is " + size_text(ia) + ", '" + b.layer_name(k) +
                          "' is " + size_text(ib));
            for (size_t p = 0, np = ia.pixels.size(); p < np; ++p) differ += ia.pixels[p] != ib.pixels[p];
          }
          LayerSimilarity& l = result.layers[k];
          l.layer = k;
          l.differing_pixels = differ;
          l.similarity = 1.0 - double(differ) / double(ia.pixels.size());
        },
        {}, PHASE);
  }
  for (const LayerSimilarity& l : result.layers) {
    result.differing_pixels += l.differing_pixels;
    if (l.similarity < result.min_similarity) {
      result.min_similarity = l.similarity;
      result.worst_layer = l.layer;
    }
  }
  report_progress(progress, 1, PHASE);
  if (!report_csv.empty()) write_csv(report_csv, result);
  return result;
}

}  // namespace slicereuse
