#pragma once
// region_clearance: how far a region lies inside another, for proving that a cavity already lies
// within an offset it has not been clipped by (cavity.cpp), without computing that offset.
//
// IndexedRegion: a region (Clipper loops: outer counter-clockwise, holes clockwise, none crossing;
// any loops for boundaries_apart) with its loops cut into runs of a few edges, each bounded by a
// box and a capsule (the chord from its first to its last point and the farthest its points stray
// from that chord), and the runs into groups and those into supergroups, bounded by boxes: far
// parts are told apart by their boxes, near runs by their capsules, and only runs nearer than the
// distance asked are compared edge by edge. The region must outlive it.
// clears(inner, outer, distance): whether inner lies inside outer with at least distance between
// their boundaries, i.e. inside outer offset inwards by distance (distance 0: inside, boundaries
// not touching). An empty inner lies inside anything; a non-empty one inside no empty outer. In
// Clipper units, exact up to the doubles' rounding of the distances (crossings are found in
// exact integer arithmetic).
// boundaries_apart(a, b, distance): whether no edge of a comes nearer than distance to an edge of
// b, nor meets one (distance 0: none meets); a's and b's loops may be any, crossing or not.
// winding_number(loops, p): how many times loops (any) wind counter-clockwise around p, a point
// on none of their edges (exact).
#include <clipper.hpp>

#include <cstdint>
#include <vector>

namespace slicereuse {

struct IndexedRegion {
  static constexpr uint32_t kRunEdges = 3;  // edges a run holds (the last of a loop may hold fewer)
  struct Run {
    uint32_t loop, first, edges;  // edges first .. first + edges - 1 of loop
    double ax, ay, bx, by;        // the chord
    double stray;                 // the farthest point from it
    double x0, y0, x1, y1;        // its points' bounding box
  };
  // A run's points as doubles, and each edge's direction over its squared length (0 for none),
  // padded to kRunEdges edges with the last point: compared with a fixed count, no branches.
  // Apart from Run, whose boxes and capsules most comparisons end at.
  struct RunPoints {
    double px[kRunEdges + 1], py[kRunEdges + 1], ux[kRunEdges], uy[kRunEdges];
  };
  struct Group {
    uint32_t first, count;     // runs (or groups) first .. first + count - 1
    double x0, y0, x1, y1;     // their bounding box
  };
  const ClipperLib::Paths* region = nullptr;
  std::vector<Run> runs;
  std::vector<RunPoints> points;  // of each run
  std::vector<Group> groups;       // of runs
  std::vector<Group> supergroups;  // of groups
};

IndexedRegion index_region(const ClipperLib::Paths& region);
bool clears(const IndexedRegion& inner, const IndexedRegion& outer, double distance);
bool boundaries_apart(const IndexedRegion& a, const IndexedRegion& b, double distance);
int winding_number(const ClipperLib::Paths& loops, const ClipperLib::IntPoint& p);

}  // namespace slicereuse
