#include "support_areas.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/regions/segment_distance.h"
#include "slicereuse/regions/simplify_paths.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse {
namespace {

// The areas are found on the layers' contours simplified to within this (mm): far below a
// head's or a pixel's size, and it divides the polygon work several times.
constexpr double kAreaToleranceMm = 0.005;

// The far reach is measured from the layer below less its parts narrower than twice this (mm):
// a mask lights a pixel only where the layer covers about half of it, so a sliver 0.1 mm wide
// (two pixels of 0.05 mm) may light nothing, and hold nothing above it.
constexpr double kUnlitHalfWidthMm = 0.05;

// A part resting on less than this share of its area is an island: UVtools' check counts a
// region an island unless a quarter of its pixels rest on lit ones below, and anti-aliased
// edges light less than their area.
constexpr double kRestingShare = 0.5;

// The outer loops of a PolyTree, each with its holes, at every depth (an outer loop inside a
// hole is a part of its own).
void collect_parts(const ClipperLib::PolyNode& node, std::vector<ClipperLib::Paths>& parts) {
  for (const ClipperLib::PolyNode* outer : node.Childs) {
    ClipperLib::Paths part{outer->Contour};
    for (const ClipperLib::PolyNode* hole : outer->Childs) {
      part.push_back(hole->Contour);
      collect_parts(*hole, parts);
    }
    parts.push_back(std::move(part));
  }
}

// Layer k's region, from its contours simplified: its loops, and its parts (outer loop with its
// holes), from one union.
struct LayerRegion {
  ClipperLib::Paths loops;
  std::vector<ClipperLib::Paths> parts;
};

LayerRegion simplified_region(const Slices& slicing, size_t k) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(simplify_paths(layer_paths(LayerView(slicing, k)), kAreaToleranceMm * kRegionScale),
                   ClipperLib::ptSubject, true);
  ClipperLib::PolyTree tree;
  clipper.Execute(ClipperLib::ctUnion, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  LayerRegion r;
  collect_parts(tree, r.parts);
  for (const ClipperLib::Paths& part : r.parts) r.loops.insert(r.loops.end(), part.begin(), part.end());
  return r;
}

ClipperLib::IntRect bounds(const ClipperLib::Paths& paths) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(paths, ClipperLib::ptSubject, true);
  return clipper.GetBounds();
}

// A Clipper coordinate in mm.
double mm_of(ClipperLib::cInt v) { return double(v) / kRegionScale; }

bool boxes_meet(const ClipperLib::IntRect& a, const ClipperLib::IntRect& b) {
  return !(a.right < b.left || b.right < a.left || a.bottom < b.top || b.bottom < a.top);
}

// The area (mm2) where part and other overlap; 0 when they do not.
double overlap_mm2(const ClipperLib::Paths& part, const ClipperLib::Paths& other) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(part, ClipperLib::ptSubject, true);
  clipper.AddPaths(other, ClipperLib::ptClip, true);
  ClipperLib::Paths common;
  clipper.Execute(ClipperLib::ctIntersection, common, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return common.empty() ? 0 : std::max(region_area_mm2(common), std::numeric_limits<double>::min());
}

ClipperLib::Paths loops_of(const std::vector<ClipperLib::Paths>& parts) {
  ClipperLib::Paths loops;
  for (const ClipperLib::Paths& part : parts) loops.insert(loops.end(), part.begin(), part.end());
  return loops;
}

// below offset by distance (negative: shrunk), with round joins or others.
ClipperLib::Paths offset(const ClipperLib::Paths& below, double distance, ClipperLib::JoinType join = ClipperLib::jtRound) {
  ClipperLib::ClipperOffset grow;
  // Arcs within the areas' tolerance of the true circle: finer only adds vertices.
  grow.ArcTolerance = kAreaToleranceMm * kRegionScale;
  grow.AddPaths(below, join, ClipperLib::etClosedPolygon);
  ClipperLib::Paths grown;
  grow.Execute(grown, distance * kRegionScale);
  return grown;
}

// The parts of region minus below grown by distance (round joins); with thin, below less its
// parts narrower than 2 thin first (shrunk by thin, then grown by distance + thin).
std::vector<ClipperLib::Paths> beyond(const ClipperLib::Paths& region, const ClipperLib::Paths& below, double distance,
                                      double thin = 0) {
  // Shrunk with mitred joins: round ones would add arcs at each of a dense contour's bends.
  const ClipperLib::Paths grown =
      thin > 0 ? offset(offset(below, -thin, ClipperLib::jtMiter), distance + thin) : offset(below, distance);
  ClipperLib::Clipper clipper;
  clipper.AddPaths(region, ClipperLib::ptSubject, true);
  clipper.AddPaths(grown, ClipperLib::ptClip, true);
  ClipperLib::PolyTree tree;
  clipper.Execute(ClipperLib::ctDifference, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  std::vector<ClipperLib::Paths> parts;
  collect_parts(tree, parts);
  return parts;
}

LayerAreas areas_of(const LayerRegion* below, const LayerRegion& region, double thickness,
                    const SupportPointOptions& o) {
  LayerAreas out;
  for (const ClipperLib::Paths& part : region.parts) out.part_mm2.push_back(region_area_mm2(part));
  if (!below) {
    if (o.raised) out.islands = region.parts;
    return out;
  }
  std::vector<ClipperLib::IntRect> below_bounds;
  for (const ClipperLib::Paths& part : below->parts) below_bounds.push_back(bounds(part));
  std::vector<double> below_mm2(below->parts.size(), -1);  // found when first linked
  for (size_t i = 0; i < region.parts.size(); ++i) {
    const ClipperLib::IntRect b = bounds(region.parts[i]);
    double resting = 0;
    for (size_t j = 0; j < below->parts.size(); ++j) {
      if (!boxes_meet(b, below_bounds[j])) continue;
      const double common = overlap_mm2(region.parts[i], below->parts[j]);
      if (!(common > 0)) continue;
      if (below_mm2[j] < 0) below_mm2[j] = region_area_mm2(below->parts[j]);
      out.links.push_back({i, j, common, below_mm2[j]});
      resting += common;
    }
    if (!(resting >= kRestingShare * out.part_mm2[i])) out.islands.push_back(region.parts[i]);
  }
  const double self_supporting = o.self_supporting_mm(thickness), flat = flat_reach_mm(thickness);
  const std::vector<ClipperLib::Paths> overhanging = beyond(region.loops, below->loops, self_supporting);
  if (flat > self_supporting && !overhanging.empty()) {
    // The slopes: what overhangs, less what reaches beyond the flat distance.
    out.overhangs = beyond(region.loops, below->loops, flat);
    ClipperLib::Clipper clipper;
    clipper.AddPaths(loops_of(overhanging), ClipperLib::ptSubject, true);
    clipper.AddPaths(loops_of(out.overhangs), ClipperLib::ptClip, true);
    ClipperLib::PolyTree tree;
    clipper.Execute(ClipperLib::ctDifference, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    collect_parts(tree, out.slopes);
    for (const ClipperLib::Paths& slope : out.slopes)
      out.slope_part.push_back(part_at(region.parts, mm_of(slope[0][0].X), mm_of(slope[0][0].Y)));
  } else {
    out.overhangs = overhanging;
  }
  // Far areas lie within what overhangs only when they reach no farther; at small critical
  // angles a ledge wider than the far reach may not overhang at all.
  if (!overhanging.empty() || o.far_reach_mm < self_supporting)
    out.far = beyond(region.loops, below->loops, o.far_reach_mm, kUnlitHalfWidthMm);
  return out;
}

double distance_to_parts(const std::vector<ClipperLib::Paths>& parts, double x, double y) {
  double best = std::numeric_limits<double>::infinity();
  for (const ClipperLib::Paths& part : parts) {
    if (part_contains(part, x, y)) return 0;
    for (const ClipperLib::Path& loop : part)
      for (size_t i = 0; i < loop.size(); ++i) {
        const ClipperLib::IntPoint &a = loop[i], &b = loop[(i + 1) % loop.size()];
        best = std::min(best, segment_distance2(x, y, mm_of(a.X), mm_of(a.Y), mm_of(b.X), mm_of(b.Y)));
      }
  }
  return std::sqrt(best);
}

}  // namespace

void check_support_input(const Mesh& mesh, const Slices& slicing, const SupportPointOptions& o) {
  if (!slicing.has_points()) throw Error("support points need the slicing's contour points (xyz), and it has none");
  if (!slicing.has_encoding()) throw Error("support points need the slicing's encoding (face, edge, t), and it has none");
  if (!(slicing.thickness > 0)) throw Error(format("support points need the slicing's layer thickness, and it is %g", slicing.thickness));
  const Fingerprint fp = mesh_fingerprint(mesh);
  if (slicing.fingerprint != fp)
    throw Error("the slicing is of a mesh of " + describe_fingerprint(slicing.fingerprint) + ", this one has " +
                describe_fingerprint(fp));
  if (!(o.density_relative > 0) || !std::isfinite(o.density_relative))
    throw Error(format("the support points' density must be a positive number, not %g %%", 100 * o.density_relative));
  if (!(o.critical_angle_deg > 0 && o.critical_angle_deg < 90))
    throw Error(format("the critical angle must lie between 0 and 90 degrees, not %g", o.critical_angle_deg));
  if (!(o.far_reach_mm > 0 && o.head_reach_mm > 0 && std::isfinite(o.far_reach_mm) && std::isfinite(o.head_reach_mm)))
    throw Error(format("the reach beyond the layer below (%g mm) and of a head (%g mm) must be positive",
                       o.far_reach_mm, o.head_reach_mm));
  if (!(o.head_front_diameter_mm >= 0) || !std::isfinite(o.head_front_diameter_mm) || !(o.point_reach_mm() > 0))
    throw Error(format("the heads' front diameter must be a number of mm that leaves a point some reach, not %g mm",
                       o.head_front_diameter_mm));
}

std::vector<LayerAreas> support_areas(const Slices& slicing, const SupportPointOptions& options,
                                      const Progress& progress) {
  const size_t n = slicing.layers();
  std::vector<LayerRegion> regions(n);
  parallel_blocks(n, [&](size_t k) { regions[k] = simplified_region(slicing, k); },
                  sub_progress(progress, 0, 0.5), "support regions");
  std::vector<LayerAreas> areas(n);
  parallel_blocks(n, [&](size_t k) { areas[k] = areas_of(k ? &regions[k - 1] : nullptr, regions[k], slicing.thickness, options); },
                  sub_progress(progress, 0.5, 1), "support areas");
  // Each region, no longer needed as the layer below, gives its parts to its areas.
  for (size_t k = 0; k < n; ++k) areas[k].parts = std::move(regions[k].parts);
  return areas;
}

bool part_contains(const ClipperLib::Paths& part, double x, double y) {
  const ClipperLib::IntPoint p(region_units(x), region_units(y));
  if (ClipperLib::PointInPolygon(p, part[0]) == 0) return false;
  for (size_t h = 1; h < part.size(); ++h)
    if (ClipperLib::PointInPolygon(p, part[h]) == 1) return false;
  return true;
}

size_t part_at(const std::vector<ClipperLib::Paths>& parts, double x, double y) {
  for (size_t i = 0; i < parts.size(); ++i)
    if (part_contains(parts[i], x, y)) return i;
  return parts.size();
}

double distance_to_areas(const LayerAreas& areas, double x, double y) {
  return std::min({distance_to_parts(areas.islands, x, y), distance_to_parts(areas.overhangs, x, y),
                   distance_to_parts(areas.slopes, x, y), distance_to_parts(areas.far, x, y)});
}

double flat_reach_mm(double thickness) { return thickness * std::tan(75 * M_PI / 180); }

LayerSpan layer_span(const Slices& s, size_t k) {
  const double h = s.thickness;
  const double below = k ? s.layer_z[k - 1] : s.layer_z[0] - h;
  return {below - h, s.layer_z[k] + h};
}

}  // namespace slicereuse
