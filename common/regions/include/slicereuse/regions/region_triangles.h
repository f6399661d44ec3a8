#pragma once
// region_triangles: a filled region (Clipper polygons, either orientation, nonzero rule) as
// triangles whose union is the region and whose interiors do not overlap, each counter-clockwise
// (positive area), for meshing a region's faces. The region is first split into its strictly simple
// pieces (region_pieces.h); each piece with holes is cut in two by a horizontal line through the middle of
// a hole (a line through the hole's interior opens it), until no piece has a hole; each simple
// piece is then ear-clipped (orientation tests in exact integer arithmetic). The cuts' corners are
// rounded to Clipper's 1 nm grid: the triangles' area is the region's within a few nm^2 per cut.
// Cost: O(n^2) per piece of n corners.
#include <clipper.hpp>

#include <array>
#include <vector>

namespace slicereuse {

using RegionTriangle = std::array<ClipperLib::IntPoint, 3>;

std::vector<RegionTriangle> region_triangles(const ClipperLib::Paths& region);

}  // namespace slicereuse
