#pragma once
// hollow_layers: a part's cavity (cavity.h) from its layers as Slices, and taken out of them.
//
// layers_cavity: input all of a part's layers (s, from its layer 0, at s.thickness) and the
// hollowing options; output each layer's cavity region (cavity_regions on layer_region of each).
// subtract_cavity: s holds the part's layers first .. first + s.layers() - 1, cavity all of its
// layers' cavities; each layer whose cavity is not empty is replaced by its region less the
// cavity (closed loops at its z, xyz only: open contours bound nothing and go); the others keep
// their contours as they are. When any layer changes, the encoding is dropped (it no longer
// matches the points). A cavity strictly inside its layer's region (region_clearance.h: no drain
// hole opening it to the outside) is taken out as the region's loops and its own reversed, which
// the nonzero rule fills as Clipper's difference (the same point set, on the same 1 nm grid);
// any other by Clipper's difference. Either way the loops may touch or nest, never cross. Throws Error when cavity has fewer than first + s.layers() layers.
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
