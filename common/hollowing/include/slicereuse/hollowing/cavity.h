#pragma once
// cavity_regions: the hollow inside a part, computed on its layers' regions (PrusaSlicer 2.5
// hollows on a voxel distance field; the layers' contours give the same cavity exactly).
//
// Input: the part's layers as loops filled by the nonzero rule (its contours as sliced,
// layers_paths, or its regions, layer_region.h: the same cavity, whatever point each loop starts
// at), layer j being the slab of height thickness_mm above layer j - 1, from the bottom, with no
// gap; options.wall_mm (t, PrusaSlicer's hollowing_min_thickness) and options.closing_mm (D, its
// hollowing_closing_distance).
// Output: each layer's cavity region (empty where there is none); all empty when t is 0.
//
// The cavity is the set of points farther than t inside the part: a 3-D erosion by a ball of
// radius t, not a 2-D offset per layer (which thins sloping walls). On layers it is exact:
//   erode(T)[k] = the intersection, over the layers j with |j - k| h <= T, of layer j's region
//                 offset inwards by sqrt(T^2 - ((j - k) h)^2), layers beyond the stack being
//                 empty (so no cavity lies within T of the bottom or the top);
// and, as PrusaSlicer's closing distance does, the cavity is the part eroded by t + D, then
// dilated by D (the union over the layers within D of the eroded layers offset outwards by
// sqrt(D^2 - dz^2)): an opening, which drops the cavity's features narrower than 2 D and rounds
// its edges, and keeps the walls at least t thick (a ball of t + D holds every sum of a ball of t
// and one of D at the same heights). D = 0 gives erode(t) itself.
// Offsets are ClipperOffset's (round joins within kCavityArcToleranceMm, on Clipper's 1 nm grid).
// The layers are first simplified to within kCavitySimplifyMm and eroded by as much more as they
// strayed, and a term that comes within kCavityProofSlackMm of binding is left out of the
// dilation, or taken that much deeper into the erosion (but for the layer's own): the cavity lies
// inside the exact one (walls at least t) and within the simplification and the slack of it
// (the slack twice with a closing; 0 on a prism, whose cavity is its layers offset by the wall),
// for a fraction of the points and the time.
// Cost: per layer, the offsets of the few layers that bound its cavity, and proofs that the
// others do not (cavity.cpp); a prism costs one offset a layer whatever t.
// Throws Error for a wall or closing distance negative or not finite, or a thickness not
// positive.
#include <clipper.hpp>

#include <vector>

#include "slicereuse/util/progress.h"

namespace slicereuse {

// PrusaSlicer's defaults (PrintConfig.cpp): hollowing_min_thickness 3 mm, hollowing_closing_distance
// 2 mm; hollowing itself is off by default, as here.
constexpr double kPrusaHollowingWallMm = 3;
constexpr double kPrusaHollowingClosingMm = 2;
// How far a round offset's chords may stray from the true arc (1 um, a 50th of a 50 um pixel;
// 0.1 um gave 1.4 times the points and cost 7-11 % more, bench/RESULTS.md).
constexpr double kCavityArcToleranceMm = 1e-3;
// How far the layers' simplified contours may stray before eroding (5 um, a tenth of a 50 um
// pixel): a dense mesh's contours then cost what a coarse one's do.
constexpr double kCavitySimplifyMm = 5e-3;
// How near a term of the erosion or dilation may come to binding and still be left out (10 um, a
// fifth of a 50 um pixel; see above): on a sphere, 1.4x to 2.3x faster (bench/RESULTS.md).
constexpr double kCavityProofSlackMm = 1e-2;

struct HollowingOptions {
  double wall_mm = 0;                              // 0: solid, no cavity
  double closing_mm = kPrusaHollowingClosingMm;
};

// Throws Error naming the value when options cannot be used (see above).
void check_hollowing(const HollowingOptions& options);

std::vector<ClipperLib::Paths> cavity_regions(const std::vector<ClipperLib::Paths>& layers, double thickness_mm,
                                              const HollowingOptions& options, const Progress& progress = {});

}  // namespace slicereuse
