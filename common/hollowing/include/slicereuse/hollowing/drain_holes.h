#pragma once
// drain_holes: drain holes into a hollowed part's cavity, so that no cavity stays sealed (#36):
// the resin drains, and the printability check finds no trap. Each hole is taken into the cavity
// (layers_cavity, hollow_layers.h; layer 0 the part's lowest), so that taking the cavity out of
// the layers (subtract_cavity) also drills the holes. Holes are 24-sided polygons inscribed in
// their circle, corners from square roots (turns_by_15_degrees.h): the same on every machine.
//
// add_drain_holes (automatic): in, each layer's cavity, the holes' diameter and how many per
// cavity; out, the cavity with the holes added, and the holes. A cavity begins on the layer where
// a piece of cavity overlaps none of the layer below's; under each such piece a vertical hole
// runs from the layer below it down through the bottom wall to layer 0, centred where the hole
// lies inside the piece (its region shrunk by the hole's radius: the point of it nearest its
// centroid, else the centroid itself); with count > 1, each further hole where the shrunk piece
// lies farthest from the holes placed (its corners are the candidates), so they spread over the
// cavity's lowest layer.
//
// check_drain_holes_fit: throws Error when an automatic hole is wider than the part's face it is
// drilled through, so that it would cut through the part's side rather than open its base (part:
// the part's layers, as the cavity's): its 24-gon reaches outside the part on the layer right
// under its cavity, or further down outside where the layer above holds it. A hole whose mouth
// spreads over a base that curves up (a sphere's) passes. Names the hole, the layer and the area.
//
// find_drain_hole_mouths: see below.
//
// add_drain_holes_at (the user's): in, each layer's cavity and mid-plane z (Slices::layer_z),
// each hole's mouth on the part's surface and its unit outward axis (the surface's normal), the
// diameter and how deep the hole reaches in from the surface; out, the cavity with the holes
// added. A hole is the 24-gon swept along its axis from kHoleStickOutMm outside the surface to
// depth_mm inside it, a convex prism: its section by each layer's plane (a convex polygon, exact
// up to Clipper's 1 nm grid) is added to that layer's cavity. Throws Error naming the hole (1 up,
// its mouth) when it meets no layer's cavity (it ends in the wall), before anything is changed.
#include <clipper.hpp>

#include <array>
#include <vector>

#include "slicereuse/hollowing/cavity.h"
#include "slicereuse/mesh/mesh.h"
#include "slicereuse/slicing/slices.h"

namespace slicereuse {

constexpr double kDrainHoleMm = 4;  // PrusaSlicer's drain holes' diameter
// How far a user's hole starts outside the surface, so that it opens cleanly (PrusaSlicer's
// HoleStickOutLength).
constexpr double kHoleStickOutMm = 1;

// How deep a user's hole reaches in from the surface: the cavity lies the wall in from a flat
// surface, and up to the closing distance deeper where the part bends; 1 mm more opens into it.
inline double drain_hole_depth_mm(const HollowingOptions& o) { return o.wall_mm + o.closing_mm + 1; }

struct DrainHole {
  size_t first = 0;  // the layers [first, layer) it runs through
  size_t layer = 0;  // automatic: the cavity's lowest layer
  double x_mm = 0, y_mm = 0;  // automatic: its axis; the user's: its mouth
  double z_mm = 0;            // the user's: its mouth (automatic: 0, the filters find it)
  std::array<double, 3> axis{0, 0, -1};  // outwards
  bool automatic = true;                 // add_drain_holes', or the user's
};

std::vector<DrainHole> add_drain_holes(std::vector<ClipperLib::Paths>& cavity, double diameter_mm, size_t count = 1);

void check_drain_holes_fit(const std::vector<DrainHole>& holes, double diameter_mm, const Slices& part);

// find_drain_hole_mouths: where each automatic hole opens, for showing it: its z_mm set to the
// highest point of the mesh's surface on its axis below its cavity (layer hole.layer of the
// slicing from z_start at thickness), or the bottom of layer 0 when the axis meets none there.
void find_drain_hole_mouths(const Mesh& mesh, double z_start, double thickness, std::vector<DrainHole>& holes);

// drain_hole_axis: a hole's axis as a segment, for what must keep clear of it (support heads):
// an automatic hole's from kHoleStickOutMm under layer 0 (of the slicing from z_start at
// thickness) up to its cavity, a user's from kHoleStickOutMm outside its mouth to depth_mm in.
std::array<std::array<double, 3>, 2> drain_hole_axis(const DrainHole& hole, double z_start, double thickness,
                                                     double depth_mm);

std::vector<DrainHole> add_drain_holes_at(std::vector<ClipperLib::Paths>& cavity, const std::vector<double>& layer_z,
                                          const std::vector<double>& mouths, const std::vector<double>& axes,
                                          double diameter_mm, double depth_mm);

}  // namespace slicereuse
