#pragma once
// support_checks: whether a mask stack can be printed layer on layer, the supports' acceptance
// (issue #30): every lit region of layer k > 0 overlaps a lit pixel of layer k-1, and no lit
// pixel of a layer is far from a lit pixel of the layer below.
//
// A pixel is lit when its level is >= 128 (the binary threshold, as compare_mask_stacks.h).
// islands: the lit regions (8-connected) of layers k > 0 with no lit pixel in common with layer
// k-1, summed over the layers; max_distance_mm: the largest distance from a lit pixel of a layer
// k > 0 to the nearest lit pixel of layer k-1 (exact Euclidean, pixel centres, the pixel's size
// along the image's columns and rows; infinite when layer k-1 has none). lit: per layer.
#include <cstddef>
#include <string>
#include <vector>

#include "slicereuse/png/mask_png.h"
#include "slicereuse/printer/printer_profile.h"

namespace slicereuse::test {

struct StackSupport {
  size_t islands = 0;
  size_t first_island_layer = 0;  // the lowest layer with one (when islands > 0)
  double max_distance_mm = 0;
  size_t max_distance_layer = 0;
  std::vector<size_t> lit;
};

StackSupport check_stack_support(const std::vector<MaskImage>& layers, const PrinterProfile& profile);
// The stack export_masks wrote at path (a PNG folder, .sl1/.sl1s, .goo or .ctb: mask_stack.h), read a
// layer at a time.
StackSupport check_stack_support(const std::string& path, const PrinterProfile& profile);

}  // namespace slicereuse::test
