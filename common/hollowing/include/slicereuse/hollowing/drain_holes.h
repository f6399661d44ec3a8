#pragma once
// drain_holes: a drain hole under every cavity of a hollowed part, so that no cavity stays sealed
// (#36): the resin drains through the part's base, and the printability check finds no trap.
//
// add_drain_holes: in, each of a part's layers' cavity (layers_cavity, hollow_layers.h; layer 0
// the part's lowest) and the holes' diameter in mm; out, the same cavity with each hole added to
// it, so that taking the cavity out of the layers (subtract_cavity) also drills the holes. A
// cavity begins on the layer where a piece of cavity overlaps none of the layer below's; under
// each such piece a vertical hole of that diameter (a 24-sided polygon inscribed in its circle,
// its corners from square roots: the same on every machine) runs from the layer below it down
// through the bottom wall to layer 0, centred where the hole lies inside the piece (its region
// shrunk by the hole's radius: the point of it nearest its centroid, else the centroid itself).
// Returns the holes: the layer each opens into, and its centre in mm.
#include <clipper.hpp>

#include <vector>

namespace slicereuse {

constexpr double kDrainHoleMm = 4;  // PrusaSlicer's drain holes' diameter

struct DrainHole {
  size_t layer = 0;  // the cavity's lowest layer: the hole runs through layers [0, layer)
  double x_mm = 0, y_mm = 0;
};

std::vector<DrainHole> add_drain_holes(std::vector<ClipperLib::Paths>& cavity, double diameter_mm);

}  // namespace slicereuse
