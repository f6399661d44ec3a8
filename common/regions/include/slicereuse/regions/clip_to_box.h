#pragma once
// clip_to_box: a region (Clipper loops, filled by the nonzero rule) and a box -> what of the
// region lies in the box (clip_regions' intersection with it), in time for the region's
// vertices plus a clip of those near the box: a small box over a large region costs little more
// than scanning it.
//
// Before the clip, each run of consecutive vertices lying strictly beyond one side of the box is
// cut to its first and last vertex, and a loop wholly beyond one side is dropped. The new edges
// stay beyond that side, so every point of the box keeps its winding number, and the edges that
// enter the box are the same ones: the clip's result is the same region, but that Clipper may
// round a crossing a unit or two otherwise (it clamps crossings to its scanbeams, which lie at
// the heights of the vertices it is given).
#include <clipper.hpp>

namespace slicereuse {

ClipperLib::Paths clip_to_box(const ClipperLib::Paths& region, const ClipperLib::IntRect& box);

}  // namespace slicereuse
