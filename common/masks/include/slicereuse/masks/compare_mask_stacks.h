#pragma once
// compare_mask_stacks: the method's similarity S of two mask stacks (folders of PNGs, .sl1
// archives or .goo files, in any pairing), layer by layer: S = pixels equal in both images / all pixels, so S = 1 means the
// same masks.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "slicereuse/util/progress.h"

namespace slicereuse {

struct LayerSimilarity {
  size_t layer = 0;
  double similarity = 1;  // S(I1, I2): fraction of equal pixels
  uint64_t differing_pixels = 0;
};

struct StackComparison {
  std::vector<LayerSimilarity> layers;
  double min_similarity = 1;
  size_t worst_layer = 0;
  uint64_t differing_pixels = 0;
};

// Compares two mask stacks layer by layer and, when report_csv is not empty, writes one CSV row
// per layer. Throws Error when the stacks differ in layer count or image size.
StackComparison compare_mask_stacks(const std::string& stack_a, const std::string& stack_b,
                                    const std::string& report_csv, const Progress& progress = {});

}  // namespace slicereuse
