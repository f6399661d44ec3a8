#pragma once
// seal_support_pockets: a layer of a supported print with the pockets of air its supports close
// lit.
//
// A pocket is a region of air of the layer (pixels <= 100, UVtools' resin-trap BinaryThreshold,
// 4-connected, as the resin-trap check joins air: check_layers.h) that does not reach the image
// border and has fewer than max_pixels pixels. It is lit when it touches the supports (one of its
// pixels is at or next to, 8 neighbours, a lit pixel of support_runs, the supports' own binary
// mask of the layer) or when it has fewer than the 10 pixels through which air drains to the
// next layer (RequiredBlackPixelsToDrain: such a pocket is a trap to UVtools whatever surrounds
// it, and no print resolves it). Where pillars, heads and the part stand a few pixels apart they
// close such pockets layer after layer, and a print keeps their resin. A pocket's pixels become
// 255 (fully lit, which every print file's grey levels hold). A hole of the part of 10 pixels or
// more that no support touches stays; nothing changes without support pixels.
// In: mask (the layer's runs, every part; mask_png.h), support_runs (the same size), max_pixels.
// Out: mask with each pocket's pixels in runs of 255 (a row's runs still increasing and
// disjoint, runs of one level side by side joined where a pocket went); returns the pockets
// lit. Throws Error when the two masks differ in size.
// kSupportPocketMm2: the largest pocket lit, in mm² of the display (0.5 mm²: 200 pixels of the
// SL1S). In the supports' small sweep, lighting pockets of up to 0.1 mm² still left traps on 3
// of its 12 parts.
#include <cstddef>
#include <cstdint>

#include "slicereuse/png/mask_png.h"

namespace slicereuse {

constexpr double kSupportPocketMm2 = 0.5;

size_t seal_support_pockets(MaskRuns& mask, const MaskRuns& support_runs, uint64_t max_pixels);

}  // namespace slicereuse
