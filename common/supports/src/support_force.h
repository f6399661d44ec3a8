#pragma once
// support_force: how much of each part of a layer (its structures, support_areas.h) the support
// points hold, in mm2 of its area, after PrusaSlicer's SupportPointGenerator (our own code): the
// peel pulls on a layer's whole area, a point holds point_force of it
// (SupportPointOptions::held_area_mm2), and a part holds what its own points hold plus what it
// inherits from the parts below it.
//
// inherited_force: areas (one layer's), force_below (per part of the layer below, the force each
//   ended with) -> per part of this layer, what it inherits: each part below shares its force
//   among the parts above it in proportion to their overlaps, cut in proportion where the part
//   above is more than 20 times its area. A part with no link inherits nothing. (PrusaSlicer
//   also divides by max(1, 0.17 x overhangs / area), which never exceeds 1: left out.)
// slope_points_needed: a part's slopes (their area), its area and its force so far -> the points
//   its slopes get: ceil(slope x (1 - force / area) / point_force) while force < area, else 0.
#include <cstddef>
#include <vector>

#include "support_areas.h"

namespace slicereuse {

std::vector<double> inherited_force(const LayerAreas& areas, const std::vector<double>& force_below);

size_t slope_points_needed(double slope_mm2, double part_mm2, double force, double point_force);

}  // namespace slicereuse
