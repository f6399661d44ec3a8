#pragma once
// hollow_layers: a part's cavity (cavity.h) from its layers as Slices, and taken out of them.
//
// layers_cavity: input all of a part's layers (s, from its layer 0, at s.thickness) and the
// hollowing options; output each layer's cavity region (cavity_regions on layer_region of each).
// subtract_cavity: s holds the part's layers first .. first + s.layers() - 1, cavity all of its
// layers' cavities; each layer whose cavity is not empty is replaced by its region less the
// cavity (closed loops at its z, xyz only: open contours bound nothing and go); the others keep
// their contours as they are. When any layer changes, the encoding is dropped (it no longer
// matches the points). A cavity around which the layer's contours wind exactly once (none comes
// within 2 nm of it: no drain hole opens it to the outside, no second shell overlaps the first
// there) is taken out as those contours, as they are, and the cavity's loops reversed, which the
// nonzero rule fills as the difference; else one strictly inside the layer's region (its
// contours' union, layer_region) as the region's loops and its own reversed (the same point set
// as Clipper's difference, on its 1 nm grid); else by Clipper's difference. The loops may touch or
// nest, never cross. Throws Error when cavity has fewer than first + s.layers() layers.
// cavity_volume_mm3: the cavity's volume, its layers' areas times the layer thickness.
#include <clipper.hpp>

#include <vector>

#include "slicereuse/hollowing/cavity.h"
#include "slicereuse/slicing/slices.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

std::vector<ClipperLib::Paths> layers_cavity(const Slices& s, const HollowingOptions& options,
                                             const Progress& progress = {});
void subtract_cavity(Slices& s, size_t first, const std::vector<ClipperLib::Paths>& cavity);
double cavity_volume_mm3(const std::vector<ClipperLib::Paths>& cavity, double thickness_mm);

}  // namespace slicereuse
