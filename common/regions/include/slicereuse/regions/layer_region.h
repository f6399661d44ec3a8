#pragma once
// layer_region: one layer's filled region as Clipper polygons (integer coordinates, kRegionScale
// units per mm), and back.
//
// layer_paths: the layer's closed contours as they are (open contours are ignored: they bound
// nothing), in kRegionScale units, rounded to the nearest unit (1 nm).
// layer_region: the region those contours fill by the nonzero winding rule (the masks' rule,
// rasterize_layer.h) as simple polygons: outer loops counter-clockwise, holes clockwise, none
// crossing another. Overlapping members or supports merge into one region.
// layer_regions: every layer of s as its region (layer_region), on all cores (phase names them
// in the progress); layers_paths: every layer's closed contours as they are (layer_paths), for
// those who clip or simplify them anyway and need no union first.
// region_into_layer: polygons (any orientation convention Clipper gives, outer CCW) as layer 0 of
// out (replaced): one closed contour per polygon at height z, xyz only, no encoding.
#include <clipper.hpp>
#include <cmath>
#include <vector>

#include "slicereuse/slicing/layer_view.h"
#include "slicereuse/slicing/slices.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

constexpr double kRegionScale = 1e6;  // Clipper units per mm (1 nm)

inline ClipperLib::cInt region_units(double mm) { return ClipperLib::cInt(std::llround(mm * kRegionScale)); }

ClipperLib::Paths layer_paths(const LayerView& layer);
ClipperLib::Paths layer_region(const LayerView& layer);
std::vector<ClipperLib::Paths> layer_regions(const Slices& s, const Progress& progress = {},
                                             const char* phase = "regions");
std::vector<ClipperLib::Paths> layers_paths(const Slices& s);
void region_into_layer(const ClipperLib::Paths& region, double z, Slices& out);

// Area in mm^2 of a region (outer loops positive, holes negative).
double region_area_mm2(const ClipperLib::Paths& region);

// Whether point p (Clipper units) lies in a region whose loops do not cross: inside an odd
// number of them (on a loop counts as inside it).
// region_covers_strictly: the same, p on none of the loops (then every piece with p as a corner
// overlaps the region).
inline bool region_covers(const ClipperLib::Paths& region, const ClipperLib::IntPoint& p) {
  bool in = false;
  for (const ClipperLib::Path& loop : region) in ^= ClipperLib::PointInPolygon(p, loop) != 0;
  return in;
}

inline bool region_covers_strictly(const ClipperLib::Paths& region, const ClipperLib::IntPoint& p) {
  bool in = false;
  for (const ClipperLib::Path& loop : region) {
    const int at = ClipperLib::PointInPolygon(p, loop);
    if (at < 0) return false;
    in ^= at == 1;
  }
  return in;
}

}  // namespace slicereuse
