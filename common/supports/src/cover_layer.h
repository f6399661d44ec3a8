#pragma once
// cover_layer: one layer's support points in the plane, for its islands and overhangs
// (support_areas.h), so that every point of those areas lies within radius of one.
//
// Candidates: the points of the global lattice of spacing g = radius / 2 (x = i*g, y = j*g: the
// same on every layer) inside each part, then the part's boundary, its vertices and points
// between them at most g/4 apart (slivers narrower than g hold no lattice point). Every point of
// a part is then within g/sqrt(2) + g/8 of a candidate (its nearest lattice point, or where the
// way to it leaves the part), so a greedy pass that takes each candidate farther than
// reach = radius - g/sqrt(2) - g/8 from every point taken so far covers the part within radius.
// Points taken are more than reach apart; that is what minimal_distance_mm comes to when it is
// larger (coverage wins). Existing points (mm) count as taken first. An island that holds no
// existing point first gets the lattice point nearest its centroid (or its first vertex), so
// every island has a point of its own. Islands come first, then overhangs; the order is fixed,
// so the result is too.
#include <array>
#include <cstdint>
#include <vector>

#include "support_areas.h"

namespace slicereuse {

struct PlanePoint {
  double x, y;
  uint8_t kind;  // SupportKind
};

std::vector<PlanePoint> cover_layer(const LayerAreas& areas, const std::vector<std::array<double, 2>>& existing,
                                    double radius);

}  // namespace slicereuse
