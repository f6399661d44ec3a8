#pragma once
// Elephant-foot compensation as PrusaSlicer applies it (SLAPrint's apply_printer_corrections):
// the first layers of a stack shrunk (elephant_foot.h), faded linearly over the profile's faded
// layers, on everything a layer holds (parts, supports and pad alike), for every print file.
//   faded_elephant_foot_mm(profile, k, layers)
//       how much layer k of a stack of `layers` shrinks: with F = min(layers, faded_layers) and
//       E = max(1, F - 1), (E - k) / E * elephant_foot_mm for k < F (the full amount on layer
//       0, none from layer F - 1 on), else 0. F = 0 (no faded layers) shrinks layer 0 alone, by
//       the full amount (PrusaSlicer would not compensate at all: a compensation asked for is
//       applied).
//   compensate_faded_layers(parts, profile, stack)
//       parts (export_masks.h) of the range of layers [begin, begin + count) of the stack: each
//       layer of it that shrinks is replaced by one part of the compensated contours of all its
//       parts (one layer, at its plane, its slab from its bottom), the parts' other layers copied
//       out behind it (those layers counted from the range's start, as parts' first are).
//       Nothing changes when no layer of the range shrinks.
#include <cstddef>
#include <vector>

#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/printfiles/export_masks.h"

namespace slicereuse {

// The stack a range belongs to: layer k's slab is [bottom + k * thickness, + thickness], its
// plane the slab's middle.
struct StackLayers {
  double bottom = 0, thickness = 0;
  size_t layers = 0;   // of the whole stack
  size_t begin = 0;    // the range's first layer in the stack
  size_t count = 0;    // the range's layers
};

double faded_elephant_foot_mm(const PrinterProfile& profile, size_t k, size_t layers);

void compensate_faded_layers(std::vector<SlicePart>& parts, const PrinterProfile& profile, const StackLayers& stack);

}  // namespace slicereuse
