#include "slicereuse/hollowing/cavity.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "region_clearance.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse {
namespace {

using ClipperLib::cInt;
using ClipperLib::Paths;

Paths offset_region(const Paths& region, double delta_mm) {
  ClipperLib::ClipperOffset offset(2, kCavityArcToleranceMm * kRegionScale);
  offset.AddPaths(region, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  Paths out;
  offset.Execute(out, delta_mm * kRegionScale);
  return out;
}

Paths unite_all(const std::vector<const Paths*>& regions) {
  ClipperLib::Clipper clipper;
  for (const Paths* r : regions) clipper.AddPaths(*r, ClipperLib::ptSubject, true);
  Paths out;
  clipper.Execute(ClipperLib::ctUnion, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return out;
}

// The intersection of regions (each covered once by its loops: outer loops counter-clockwise,
// holes clockwise) in one sweep: every loop, and count - 1 clockwise boxes around them all, so
// that the winding number is positive exactly where all regions cover.
Paths intersect_all(const std::vector<const Paths*>& regions) {
  cInt x0 = std::numeric_limits<cInt>::max(), y0 = x0, x1 = std::numeric_limits<cInt>::min(), y1 = x1;
  for (const Paths* r : regions) {
    if (r->empty()) return {};
    for (const ClipperLib::Path& path : *r)
      for (const ClipperLib::IntPoint& p : path)
        x0 = std::min(x0, p.X), y0 = std::min(y0, p.Y), x1 = std::max(x1, p.X), y1 = std::max(y1, p.Y);
  }
  if (regions.size() == 1) return *regions[0];
  ClipperLib::Clipper clipper;
  for (const Paths* r : regions) clipper.AddPaths(*r, ClipperLib::ptSubject, true);
  const ClipperLib::Path box{{x0 - 1, y0 - 1}, {x0 - 1, y1 + 1}, {x1 + 1, y1 + 1}, {x1 + 1, y0 - 1}};
  for (size_t i = 1; i < regions.size(); ++i) clipper.AddPath(box, ClipperLib::ptSubject, true);
  Paths out;
  clipper.Execute(ClipperLib::ctUnion, out, ClipperLib::pftPositive, ClipperLib::pftPositive);
  return out;
}

// The layers within a ball of radius r of a layer, and their disk's radius at d layers away.
struct LayeredBall {
  LayeredBall(double radius_mm, double thickness_mm)
      : r(radius_mm), h(thickness_mm), reach(long(std::floor(radius_mm / thickness_mm + 1e-9))) {}
  double radius(long d) const { return std::sqrt(std::max(0.0, r * r - double(d * d) * h * h)); }
  double r, h;
  long reach;  // layers each way
};

// A term binds when the result comes this near its offset's edge (in Clipper units, 1 um): it is
// tried first on the next layer, whose result it likely bounds too.
constexpr double kBindingUnits = 1e-3 * kRegionScale;
// Layers a thread works through in order, handing on the terms that bind from one to the next.
constexpr size_t kBlockLayers = 16;

// The terms (offsets e, layer k + e) to try first on a layer: those that bound the layer below,
// and e = 0.
void start_terms(std::vector<long>& terms) {
  if (std::find(terms.begin(), terms.end(), 0) == terms.end()) terms.insert(terms.begin(), 0);
}

// Layers [a, b) of the stack eroded by the ball (cavity.h: the intersection over the layers
// k + e within it of their regions offset inwards by radius(|e|)). The intersection of a few of
// those terms (those that bound the layer below, and e = 0) is the candidate; every other term is
// then proved to hold it already (its layer's boundary lies at least the term's radius from the
// candidate, region_clearance.h: so the candidate lies inside that offset) or, failing that,
// offset and intersected. So the result is the whole intersection, while a smooth part costs a
// few offsets a layer instead of one per layer within the ball.
void erode_layers(const std::vector<Paths>& layers, const std::vector<IndexedRegion>& indexed,
                  const LayeredBall& ball, size_t a, size_t b, std::vector<Paths>& out) {
  const long n = long(layers.size()), R = ball.reach;
  std::vector<long> terms;
  for (long k = long(a); k < long(b); ++k) {
    start_terms(terms);
    if (k < R || k + R >= n) continue;  // within the ball of the stack's empty outside
    Paths cavity;
    bool first = true;
    for (long e : terms) {
      const Paths term = offset_region(layers[size_t(k + e)], -ball.radius(std::labs(e)));
      cavity = first ? term : intersect_all({&cavity, &term});
      first = false;
      if (cavity.empty()) break;
    }
    IndexedRegion candidate = index_region(cavity);
    for (long d = 1; d <= R && !cavity.empty(); ++d)
      for (long e : {-d, d}) {
        if (cavity.empty() || std::find(terms.begin(), terms.end(), e) != terms.end()) continue;
        const double r = ball.radius(d);
        if (clearance(candidate, indexed[size_t(k + e)], r * kRegionScale) >= r * kRegionScale) continue;
        const Paths term = offset_region(layers[size_t(k + e)], -r);
        cavity = intersect_all({&cavity, &term});
        candidate = index_region(cavity);
        terms.push_back(e);
      }
    std::vector<long> binding;
    for (long e : terms) {
      const double cap = ball.radius(std::labs(e)) * kRegionScale + kBindingUnits;
      if (clearance(candidate, indexed[size_t(k + e)], cap) < cap) binding.push_back(e);
    }
    terms = std::move(binding);
    out[size_t(k)] = std::move(cavity);
  }
}

// Layers [a, b) of the stack dilated by the ball: the union over the layers k + e within it of
// their regions offset outwards by radius(|e|), found as erode_layers finds its intersection: a
// term whose layer lies at least its radius inside the candidate adds nothing to it.
void dilate_layers(const std::vector<Paths>& layers, const std::vector<IndexedRegion>& indexed,
                   const LayeredBall& ball, size_t a, size_t b, std::vector<Paths>& out) {
  const long n = long(layers.size()), R = ball.reach;
  std::vector<long> terms;
  for (long k = long(a); k < long(b); ++k) {
    start_terms(terms);
    Paths grown;
    std::vector<long> used;
    for (long e : terms) {
      if (k + e < 0 || k + e >= n || layers[size_t(k + e)].empty()) continue;
      const Paths term = offset_region(layers[size_t(k + e)], ball.radius(std::labs(e)));
      grown = unite_all({&grown, &term});
      used.push_back(e);
    }
    IndexedRegion candidate = index_region(grown);
    for (long d = 0; d <= R; ++d)
      for (long side = d == 0 ? 1 : -1; side <= 1; side += 2) {
        const long e = side * d;
        if (k + e < 0 || k + e >= n) continue;
        if (std::find(used.begin(), used.end(), e) != used.end()) continue;
        const double r = ball.radius(d);
        if (clearance(indexed[size_t(k + e)], candidate, r * kRegionScale) >= r * kRegionScale) continue;
        const Paths term = offset_region(layers[size_t(k + e)], r);
        grown = unite_all({&grown, &term});
        candidate = index_region(grown);
        used.push_back(e);
      }
    std::vector<long> binding;
    for (long e : used) {
      const double cap = ball.radius(std::labs(e)) * kRegionScale + kBindingUnits;
      if (clearance(indexed[size_t(k + e)], candidate, cap) < cap) binding.push_back(e);
    }
    terms = std::move(binding);
    out[size_t(k)] = std::move(grown);
  }
}

using LayersByBall = void (*)(const std::vector<Paths>&, const std::vector<IndexedRegion>&, const LayeredBall&,
                              size_t, size_t, std::vector<Paths>&);

// The stack eroded or dilated by the ball, blocks of layers on all cores.
std::vector<Paths> by_ball(LayersByBall f, const std::vector<Paths>& layers, const LayeredBall& ball,
                           const Progress& progress) {
  const size_t n = layers.size();
  std::vector<IndexedRegion> indexed(n);
  for (size_t k = 0; k < n; ++k) indexed[k] = index_region(layers[k]);
  std::vector<Paths> out(n);
  const size_t blocks = (n + kBlockLayers - 1) / kBlockLayers;
  parallel_blocks(
      blocks,
      [&](size_t i) { f(layers, indexed, ball, i * kBlockLayers, std::min(n, (i + 1) * kBlockLayers), out); },
      progress, "hollowing");
  return out;
}

}  // namespace

void check_hollowing(const HollowingOptions& o) {
  if (!(std::isfinite(o.wall_mm) && o.wall_mm >= 0))
    throw Error(format("the hollowing wall thickness is %g mm; it must be a finite, non-negative number (0: solid)",
                       o.wall_mm));
  if (!(std::isfinite(o.closing_mm) && o.closing_mm >= 0))
    throw Error(format("the hollowing closing distance is %g mm; it must be a finite, non-negative number",
                       o.closing_mm));
}

std::vector<Paths> cavity_regions(const std::vector<Paths>& layers, double thickness_mm,
                                  const HollowingOptions& options, const Progress& progress) {
  check_hollowing(options);
  if (!(thickness_mm > 0 && std::isfinite(thickness_mm)))
    throw Error(format("hollowing needs a positive layer thickness, not %g mm", thickness_mm));
  const size_t n = layers.size();
  if (options.wall_mm == 0) return std::vector<Paths>(n);
  const LayeredBall eroding(options.wall_mm + options.closing_mm, thickness_mm);
  const bool closing = options.closing_mm > 0;
  std::vector<Paths> eroded = by_ball(erode_layers, layers, eroding, sub_progress(progress, 0, closing ? 0.5 : 1));
  if (!closing) return eroded;
  return by_ball(dilate_layers, eroded, LayeredBall(options.closing_mm, thickness_mm), sub_progress(progress, 0.5, 1));
}

}  // namespace slicereuse
