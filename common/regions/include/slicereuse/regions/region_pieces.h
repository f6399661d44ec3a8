#pragma once
// region_pieces: a region (Clipper polygons, either orientation, nonzero rule) as its pieces, each
// an outer loop (counter-clockwise) followed by the holes inside it (clockwise), strictly simple:
// no loop touches itself or another, even at a point.
#include <clipper.hpp>

#include <vector>

namespace slicereuse {

std::vector<ClipperLib::Paths> region_pieces(const ClipperLib::Paths& region);

}  // namespace slicereuse
