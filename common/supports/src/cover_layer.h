#pragma once
// cover_layer: one layer's support points in the plane, for its islands, far areas and
// overhangs (support_areas.h), as generate_support_points.h says.
//
// Candidates: the points of a global lattice of spacing g (x = i*g, y = j*g: the same on every
// layer) inside each part, then the part's boundary, its vertices and points between them at
// most g/4 apart (slivers narrower than g hold no lattice point). Every point of a part is then
// within m = g/sqrt(2) + g/8 of a candidate (its nearest lattice point, or where the way to it
// leaves the part), so a pass that holds every candidate within reach - m of a point covers the
// part within reach. Here g = min(head_reach, support_radius) / 8 (m leaves 0.90 of the reach; a
// lattice of half the reach, 0.58), and each candidate not yet held, in order, gets held by the
// lattice candidate within reach - m of it, not within half that of a point of the layer, that
// holds the most candidates not yet held (or by itself): taking each candidate not yet held
// itself spends half of each disc on ground already held. Boundary candidates take a point only
// for themselves: the face under one may be missed, and its point placed elsewhere.
//   islands and far areas: covered by points of this layer (existing ones first), reach
//     head_reach;
//   overhangs: within the smaller of head_reach and support_radius, also by the points held
//     (HeldSurface) within support_radius in space.
// An island that holds no existing point first gets the lattice point nearest its centroid (or
// its first vertex), so every island has a point of its own. Islands come first, then far
// areas, then overhangs; the order is fixed, so the result is too.
//
// hold_slopes: up to count points on the slopes given (of one part; support_force.h says how
// many), each the candidate (as above, on a lattice of g = min(head_reach, support_radius) / 2)
// farthest from the points held in space and this layer's (layer), among those neither holds
// within the support reach less the margin: spread over the slopes, and none where the surface
// is already held.
#include <array>
#include <cstdint>
#include <vector>

#include "cell_grid.h"
#include "support_areas.h"

namespace slicereuse {

struct PlanePoint {
  double x, y;
  uint8_t kind;  // SupportKind
};

// Points in space, by x-y cells of the radius (CellGrid): whether one at or below z lies within
// reach (at most the radius) of (x, y, z). The layers covered so far, and a layer's own points in
// its plane.
class HeldSurface {
 public:
  explicit HeldSurface(double radius) : radius_(radius), grid_(radius) {}
  bool holds(double x, double y, double z, double reach) const;
  // The distance to the nearest point at or below z, if within the radius; else infinity.
  double distance(double x, double y, double z) const;
  void add(double x, double y, double z);

 private:
  // The squared distance to the nearest point at or below z in the cells around (x, y).
  double nearest2(double x, double y, double z) const;
  double radius_;
  std::vector<std::array<double, 3>> points_;
  CellGrid grid_;
};

struct CoverReach {
  double head = 1;     // islands and far areas, by points of the layer
  double support = 1;  // overhangs, in space
};

std::vector<PlanePoint> hold_slopes(const std::vector<const ClipperLib::Paths*>& slopes,
                                    const std::vector<std::array<double, 2>>& layer, const HeldSurface& held, double z,
                                    const CoverReach& reach, size_t count);

std::vector<PlanePoint> cover_layer(const LayerAreas& areas, const std::vector<std::array<double, 2>>& existing,
                                    const HeldSurface& held, double z, const CoverReach& reach);

}  // namespace slicereuse
