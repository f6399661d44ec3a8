#pragma once
// region_clearance: how far a region lies inside another, for proving that a cavity already lies
// within an offset it has not been clipped by (cavity.cpp), without computing that offset.
//
// IndexedRegion: a region (Clipper loops: outer counter-clockwise, holes clockwise, none crossing)
// with its loops cut into runs of up to kRunEdges edges, each bounded by a capsule: the chord from
// its first to its last point and the farthest its points stray from that chord, and inside a
// box (far runs are told apart by their boxes, near ones by their capsules). The region must
// outlive it.
// clearance(inner, outer, cap): when inner lies inside outer, the distance from inner to outer's
// outside (the least distance between their boundaries), or cap if that is at least cap;
// -1 when inner does not lie inside outer, or their boundaries touch. An empty inner lies in
// anything (cap); a non-empty one in no empty outer (-1). In Clipper units, exact up to the
// doubles' rounding of the distances (crossings are found in exact integer arithmetic).
#include <clipper.hpp>

#include <cstdint>
#include <vector>

namespace slicereuse {

struct IndexedRegion {
  struct Run {
    uint32_t loop, first, edges;  // edges first .. first + edges - 1 of loop
    double ax, ay, bx, by;        // the chord
    double stray;                 // the farthest point from it
    double x0, y0, x1, y1;        // its points' bounding box
  };
  const ClipperLib::Paths* region = nullptr;
  std::vector<Run> runs;
};

IndexedRegion index_region(const ClipperLib::Paths& region);
double clearance(const IndexedRegion& inner, const IndexedRegion& outer, double cap);

}  // namespace slicereuse
