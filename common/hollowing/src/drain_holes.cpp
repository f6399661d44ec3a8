#include "slicereuse/hollowing/drain_holes.h"

#include <cmath>

#include "slicereuse/regions/clip_regions.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/regions/turns_by_15_degrees.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {
namespace {

// The pieces of a region: each outer loop with the holes inside it.
std::vector<ClipperLib::Paths> pieces_of(const ClipperLib::Paths& region) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(region, ClipperLib::ptSubject, true);
  ClipperLib::PolyTree tree;
  clipper.Execute(ClipperLib::ctUnion, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  std::vector<ClipperLib::Paths> pieces;
  std::vector<const ClipperLib::PolyNode*> outers;
  for (const ClipperLib::PolyNode* n = tree.GetFirst(); n; n = n->GetNext())
    if (!n->IsHole()) outers.push_back(n);
  for (const ClipperLib::PolyNode* outer : outers) {
    ClipperLib::Paths piece{outer->Contour};
    for (const ClipperLib::PolyNode* hole : outer->Childs) piece.push_back(hole->Contour);
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

// The centroid of a piece (outer loop less its holes), in Clipper units.
std::array<double, 2> centroid(const ClipperLib::Paths& piece) {
  double area = 0, cx = 0, cy = 0;
  for (const ClipperLib::Path& loop : piece)
    for (size_t i = 0; i < loop.size(); ++i) {
      const ClipperLib::IntPoint& p = loop[i];
      const ClipperLib::IntPoint& q = loop[(i + 1) % loop.size()];
      const double cross = double(p.X) * double(q.Y) - double(q.X) * double(p.Y);
      area += cross;
      cx += (double(p.X) + double(q.X)) * cross;
      cy += (double(p.Y) + double(q.Y)) * cross;
    }
  return {cx / (3 * area), cy / (3 * area)};
}

// Where a hole of radius r (Clipper units) under the piece goes.
ClipperLib::IntPoint hole_centre(const ClipperLib::Paths& piece, double r) {
  const std::array<double, 2> c = centroid(piece);
  const ClipperLib::IntPoint middle{ClipperLib::cInt(std::llround(c[0])), ClipperLib::cInt(std::llround(c[1]))};
  ClipperLib::ClipperOffset offset;
  offset.AddPaths(piece, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
  ClipperLib::Paths room;
  offset.Execute(room, -r);
  if (room.empty() || region_covers(room, middle)) return middle;
  // The vertex of the shrunk piece nearest the centroid: the hole lies inside the piece there.
  ClipperLib::IntPoint best = room[0][0];
  double nearest = INFINITY;
  for (const ClipperLib::Path& loop : room)
    for (const ClipperLib::IntPoint& p : loop) {
      const double dx = double(p.X) - c[0], dy = double(p.Y) - c[1];
      if (dx * dx + dy * dy < nearest) nearest = dx * dx + dy * dy, best = p;
    }
  return best;
}

}  // namespace

std::vector<DrainHole> add_drain_holes(std::vector<ClipperLib::Paths>& cavity, double diameter_mm) {
  if (!(std::isfinite(diameter_mm) && diameter_mm > 0))
    throw Error(format("a drain hole's diameter is %g mm; it must be a positive number", diameter_mm));
  const double r = 0.5 * double(region_units(diameter_mm));
  std::vector<DrainHole> holes;
  std::vector<ClipperLib::Path> discs;
  for (size_t k = 0; k < cavity.size(); ++k) {
    if (cavity[k].empty()) continue;
    for (const ClipperLib::Paths& piece : pieces_of(cavity[k])) {
      if (k > 0 && !clip_regions(piece, cavity[k - 1], ClipperLib::ctIntersection).empty()) continue;
      const ClipperLib::IntPoint c = hole_centre(piece, r);
      ClipperLib::Path disc;
      for (int i = 0; i < 24; ++i) {
        const std::array<double, 2> t = turn_by_15_degrees(i);
        disc.push_back({c.X + ClipperLib::cInt(std::llround(r * t[0])), c.Y + ClipperLib::cInt(std::llround(r * t[1]))});
      }
      holes.push_back({k, double(c.X) / kRegionScale, double(c.Y) / kRegionScale});
      discs.push_back(std::move(disc));
    }
  }
  // Each hole into the layers under its cavity (after all are found: a hole is no cavity's start).
  for (size_t h = 0; h < holes.size(); ++h)
    for (size_t k = 0; k < holes[h].layer; ++k) cavity[k] = clip_regions(cavity[k], {discs[h]}, ClipperLib::ctUnion);
  return holes;
}

}  // namespace slicereuse
