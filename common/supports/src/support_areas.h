#pragma once
// support_areas: where each layer of a part's slicing needs support (generate_support_points.h):
//   islands:   each connected part of layer k's region (outer loop with its holes) that does not
//              overlap layer k-1's region; on layer 0 every part when options.raised, else none;
//   overhangs: each connected part of region_k minus region_{k-1} grown by
//              options.self_supporting_mm(thickness) (round joins), k > 0;
//   far:       the same with region_{k-1} grown by options.far_reach_mm.
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

struct LayerAreas {
  std::vector<ClipperLib::Paths> islands;
  std::vector<ClipperLib::Paths> overhangs;
  std::vector<ClipperLib::Paths> far;
};

// Throws Error when the slicing has no points or no encoding, or is not a slicing of mesh, or
// the options are not usable (a support radius that is not positive).
void check_support_input(const Mesh& mesh, const Slices& slicing, const SupportPointOptions& options);

// Every layer's areas; the layers' regions and then their areas on all cores.
std::vector<LayerAreas> support_areas(const Slices& slicing, const SupportPointOptions& options,
                                      const Progress& progress);

// Whether (x, y) (mm) lies in a part (outer loop, then holes), its boundary included.
bool part_contains(const ClipperLib::Paths& part, double x, double y);

// Distance in mm from (x, y) (mm) to the layer's islands, overhangs and far areas (at small
// critical angles a far area need not lie in an overhang): 0 inside one.
double distance_to_areas(const LayerAreas& areas, double x, double y);

// The z range in which a point supports layer k: from plane_{k-1} - h to plane_k + h (plane_{-1}
// = plane_0 - h), where a vertical ray under layer k's area meets the part.
struct LayerSpan {
  double lo, hi;
};
LayerSpan layer_span(const Slices& slicing, size_t k);

}  // namespace slicereuse
