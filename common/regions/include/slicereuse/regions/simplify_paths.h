#pragma once
// simplify_paths: closed polygons with fewer vertices, each within tolerance (Clipper units) of
// the original (Douglas-Peucker on each loop, anchored at its first vertex and the vertex
// farthest from it). For analyses that need the region to a tolerance far below their own
// scale (support areas, layer_region.h), not for what the masks draw. Loops left with fewer than
// three vertices are dropped; simplified loops may touch or cross where the originals came
// within tolerance, so follow with a union (nonzero) when a simple region is needed. With
// deviation, also the farthest any dropped vertex lies from its chord (at most tolerance; 0 when
// only exactly collinear vertices went), so that a caller may bound the error it actually made.
#include <clipper.hpp>

namespace slicereuse {

ClipperLib::Paths simplify_paths(const ClipperLib::Paths& paths, double tolerance, double* deviation = nullptr);

}  // namespace slicereuse
