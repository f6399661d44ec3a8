#pragma once
// compare_mask_stacks: two mask stacks (folders of PNGs, .sl1 archives, .goo or .ctb files, in
// any pairing) -> per layer the method's similarity S and the grey differences, and the same
// figures over the whole stack.
//
// Masks are 8-bit grey (binary masks 0 or 255, anti-aliased ones any level). For pixels a, b
// of the same place in layer k of the two stacks:
//   - on/off: a pixel is on when its level is >= 128 (the binary threshold; a 1-bit PNG decodes
//     to 0 and 255); it differs when it is on in one image and off in the other. S = 1 -
//     differing / all pixels, the method's S of the thresholded masks; for binary masks that is
//     the fraction of equal pixels, as the method defines it. Anti-aliased masks are
//     thresholded for S too, so S keeps the method's meaning (a share of pixels of binary
//     images) whatever the masks; the grey figures below say how far their levels differ.
//   - max_grey_difference: the largest |a - b| (0..255; 0 exactly when the images are equal).
//   - over_one_level_pixels: the pixels with |a - b| > 1, i.e. more than the one level that
//     rounding of the same covered area may give.
// All figures come from one pass over both images; layers are compared on all cores.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "slicereuse/util/progress.h"

namespace slicereuse {

struct LayerSimilarity {
  size_t layer = 0;
  double similarity = 1;              // S: 1 - differing_pixels / pixels
  uint64_t differing_pixels = 0;      // on in one image, off in the other
  int max_grey_difference = 0;        // largest |a - b|, 0..255
  uint64_t over_one_level_pixels = 0; // |a - b| > 1
};

// Worst layers are the first one on ties (layer 0 when every layer scores alike).
struct StackComparison {
  std::vector<LayerSimilarity> layers;
  double min_similarity = 1;
  size_t worst_layer = 0;              // the layer of min_similarity
  uint64_t differing_pixels = 0;       // summed over the layers
  int max_grey_difference = 0;         // over all layers
  size_t max_grey_difference_layer = 0;
  uint64_t over_one_level_pixels = 0;  // summed over the layers
  double over_one_level_share = 0;     // over_one_level_pixels / all pixels of all layers
  size_t over_one_level_layer = 0;     // the layer with the most over_one_level_pixels
};

// Compares two mask stacks layer by layer and, when report_csv is not empty, writes (atomically)
// one CSV row per layer (docs/formats.md, "Similarity report"). Throws Error when the stacks
// differ in layer count or image size, or an image cannot be read.
StackComparison compare_mask_stacks(const std::string& stack_a, const std::string& stack_b,
                                    const std::string& report_csv, const Progress& progress = {});

}  // namespace slicereuse
