#pragma once
// transfer_support_points: a family source's support points on a member, the way contours are
// transferred: each point keeps its face and area coordinates and takes the member's vertices
// (the same faces: the member has the points' fingerprint), or goes through a cross-
// parameterization map (another connectivity: the map's images of its face's corners,
// interpolated, then the target face under them). Then, on the member:
//   certified (kept): the point still lies on a surface that needs support: its xy is inside an
//     island, overhang or far area of its layer on the member's own slicing (generate_support_
//     points.h), or within the support radius of one; its layer is its own (the plate's planes
//     are the source's) or, failing that, the layer whose plane is the first at or above its z
//     or one next to that, as long as its z lies where a point of that layer may (from the plane
//     below that layer's minus a layer to its own plus one), and its surface does not face up
//     (faces_up, support_points.h);
//   otherwise dropped;
//   added: the member's own islands and overhangs that no kept point covers get new points
//     (generate_support_points with the kept points as existing);
//   moved: an added point within minimal_distance_mm of a dropped one counts as that point moved
//     (and neither as added nor dropped).
// Output: the member's points (kept first, then added), with its fingerprint; stats.
// Throws Error when the member is neither of the points' family nor the map's target, or as
// generate_support_points does.
#include <cstddef>

#include "slicereuse/crossparam/surface_map.h"
#include "slicereuse/mesh/mesh.h"
#include "slicereuse/slicing/slices.h"
#include "slicereuse/supports/generate_support_points.h"
#include "slicereuse/supports/support_points.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

struct SupportTransferStats {
  size_t transferred = 0;  // the source's points
  size_t kept = 0, moved = 0, added = 0, dropped = 0;
};

SupportPoints transfer_support_points(const SupportPoints& source, const Mesh& member, const Slices& member_slicing,
                                      const SupportPointOptions& options, SupportTransferStats* stats = nullptr,
                                      const SurfaceMap* map = nullptr, const Progress& progress = {});

}  // namespace slicereuse
