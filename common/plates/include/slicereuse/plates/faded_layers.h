#pragma once
// faded_layers: elephant-foot compensation (elephant_foot.h) faded over an object's first layers,
// as PrusaSlicer 2.5 applies it (SLAPrint's apply_printer_corrections, on the model and on the
// supports and pad alike).
//
// faded_compensation_mm: the compensation of layer k of an object of `layers` layers, counted from
// its lowest layer (the pad's bottom under a supported part: PrusaSlicer's slice index), by
// profile's elephant_foot_mm and faded_layers: with F = min(layers, faded_layers) and
// E = max(1, F - 1), layer k < F is compensated by (E - k) elephant_foot_mm / E, the full value
// on layer 0 fading linearly to 0 on layer E; 0 from layer E (or F) up. faded_layers 0 counts as
// 1 (PrusaSlicer allows 3 to 20): layer 0 alone, as faded_layers 1 and 2 give.
//
// compensate_faded_layers: a range of a plate's layers with those layers compensated, object by
// object. Input: parts, the range's (export_masks.h: layers counted from the range's first, which
// is the plate's layer a), and their owners: one per part (a plate's members, a member's supports
// sharing its owner), or empty: one owner; object_layers: per owner, its layer count from the
// plate's layer 0 (its pad's bottom, or its own first layer standing on the plate); and
// on_all_cores: the layers compensated at once (parallel_blocks; false on a thread that already
// draws masks, LayerMaker). Output: parts, where the layers an owner's compensation reaches are
// replaced by one part per layer of the compensated contours of that owner's parts together
// (at the plane and bottom of its first part there; not a support part, export_masks.h, even
// where it holds supports), followed by the rest of its parts' layers
// copied out; the layers above are kept as they are. Apart, each member's layers are those it has
// printed alone, whatever else is on the plate: the compensation is local, yet compensated
// together, a plate of 11 nested arches lit 0.24 % more of its first layer than its members alone
// (6,855 pixels differing, some by 255). Nothing changes when profile.elephant_foot_mm is 0.
// Throws Error for owners that are not one per part or an owner without object_layers.
#include <cstddef>
#include <vector>

#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/printfiles/export_masks.h"

namespace slicereuse {

double faded_compensation_mm(const PrinterProfile& profile, size_t layers, size_t k);

void compensate_faded_layers(std::vector<SlicePart>& parts, size_t a, const std::vector<size_t>& owners,
                             const std::vector<size_t>& object_layers, const PrinterProfile& profile,
                             bool on_all_cores);

}  // namespace slicereuse
