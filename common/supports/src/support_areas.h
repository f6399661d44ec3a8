#pragma once
// support_areas: where each layer of a part's slicing needs support (generate_support_points.h):
//   islands:   each connected part of layer k's region (outer loop with its holes) that rests
//              on layer k-1's region with less than half its area (UVtools' island check asks a
//              quarter of its pixels); on layer 0 every part when options.raised, else none;
//   overhangs: each connected part of region_k minus region_{k-1} grown by the larger of
//              options.self_supporting_mm(thickness) and flat_reach_mm(thickness) (round joins),
//              k > 0: the surface flatter than 15 degrees, or than the critical angle if less;
//   slopes:    the rest of region_k beyond region_{k-1} grown by the self-supporting distance:
//              the surface between the critical angle and 15 degrees, each with its part;
//   far:       the part of region_k beyond region_{k-1} grown by options.far_reach_mm, once
//              region_{k-1}'s parts narrower than 0.1 mm are left out (its mask may not light them);
//   parts:     the region's parts (its structures, support_force.h), their areas, and how each
//              overlaps the parts of layer k-1 (links, with the overlap's area).
// Polygons in kRegionScale units (layer_region.h), outer loop first, then its holes, found on the
// layers' contours simplified to within 5 um (simplify_paths.h).
// Also the checks both generation and transfer make on a slicing, and the heights that tie a
// point to a layer.
#include <cstddef>
#include <vector>

#include <clipper.hpp>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/slicing/slices.h"
#include "slicereuse/supports/generate_support_points.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

// How far a layer reaches beyond the one below before its surface is flatter than 15 degrees
// (PrusaSlicer's SupportPointGenerator covers its overhangs beyond thickness x tan 75 degrees in
// full, and the slopes short of that only as their support force asks).
double flat_reach_mm(double thickness);

struct PartLink {
  size_t part, below;  // a part of this layer, one of the layer below
  double overlap_mm2;
  double below_mm2;    // the area of the part below
};

struct LayerAreas {
  std::vector<ClipperLib::Paths> islands;
  std::vector<ClipperLib::Paths> overhangs;
  std::vector<ClipperLib::Paths> slopes;
  std::vector<size_t> slope_part;  // the part of parts each slope lies in
  std::vector<ClipperLib::Paths> far;
  std::vector<ClipperLib::Paths> parts;
  std::vector<double> part_mm2;
  std::vector<PartLink> links;
};

// Throws Error when the slicing has no points or no encoding, or is not a slicing of mesh, or
// the options are not usable (a support radius that is not positive).
void check_support_input(const Mesh& mesh, const Slices& slicing, const SupportPointOptions& options);

// Every layer's areas; the layers' regions and then their areas on all cores.
std::vector<LayerAreas> support_areas(const Slices& slicing, const SupportPointOptions& options,
                                      const Progress& progress);

// Whether (x, y) (mm) lies in a part (outer loop, then holes), its boundary included.
bool part_contains(const ClipperLib::Paths& part, double x, double y);
// The part of parts (x, y) (mm) lies in, parts.size() when none.
size_t part_at(const std::vector<ClipperLib::Paths>& parts, double x, double y);

// Distance in mm from (x, y) (mm) to the layer's islands, overhangs, slopes and far areas (at
// small critical angles a far area need not lie in an overhang): 0 inside one.
double distance_to_areas(const LayerAreas& areas, double x, double y);

// The z range in which a point supports layer k: from plane_{k-1} - h to plane_k + h (plane_{-1}
// = plane_0 - h), where a vertical ray under layer k's area meets the part.
struct LayerSpan {
  double lo, hi;
};
LayerSpan layer_span(const Slices& slicing, size_t k);

}  // namespace slicereuse
