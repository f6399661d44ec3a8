#include "slicereuse/hollowing/cavity.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "slicereuse/regions/layer_region.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse {
namespace {

using ClipperLib::cInt;
using ClipperLib::Paths;

// Twice a region's area, exactly (its vertices' products need 128 bits): two regions, one
// inside the other, are the same exactly when this is equal.
__int128 twice_area(const Paths& region) {
  __int128 a = 0;
  for (const ClipperLib::Path& path : region)
    for (size_t i = 0, n = path.size(); i < n; ++i) {
      const ClipperLib::IntPoint& p = path[i];
      const ClipperLib::IntPoint& q = path[(i + 1) % n];
      a += __int128(p.X) * q.Y - __int128(q.X) * p.Y;
    }
  return a;
}

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
      : r(radius_mm), h(thickness_mm), reach(size_t(std::floor(radius_mm / thickness_mm + 1e-9))) {}
  double radius(size_t d) const { return std::sqrt(std::max(0.0, r * r - double(d * d) * h * h)); }
  double r, h;
  size_t reach;  // layers each way
};

// Layer k of the stack eroded by the ball: the ball is the union of the cylinders of radius
// radius(d) and half-height d layers, so the erosion is the intersection over d of the window
// of layers k - d .. k + d (their intersection) offset inwards by radius(d). When adding layers
// k -+ d leaves the window as it was, that cylinder's offset holds the one before it (a smaller
// offset of the same region) and is skipped: a prism costs one offset, whatever the reach.
Paths eroded_layer(const std::vector<Paths>& layers, size_t k, const LayeredBall& ball) {
  if (k < ball.reach || k + ball.reach >= layers.size() || layers[k].empty()) return {};
  Paths window = layers[k];
  __int128 area = twice_area(window);
  Paths eroded = offset_region(window, -ball.r);
  for (size_t d = 1; d <= ball.reach && !eroded.empty(); ++d) {
    Paths wider = intersect_all({&window, &layers[k - d], &layers[k + d]});
    const __int128 a = twice_area(wider);
    if (a == area) continue;
    window = std::move(wider);
    area = a;
    const Paths cylinder = offset_region(window, -ball.radius(d));
    eroded = intersect_all({&eroded, &cylinder});
  }
  return eroded;
}

// Layer k of the stack dilated by the ball: the union over d of the window's union offset
// outwards by radius(d), skipping the windows that adding layers k -+ d left as they were.
Paths dilated_layer(const std::vector<Paths>& layers, size_t k, const LayeredBall& ball) {
  Paths window = layers[k];
  __int128 area = twice_area(window);
  std::vector<Paths> cylinders;
  if (!window.empty()) cylinders.push_back(offset_region(window, ball.r));
  for (size_t d = 1; d <= ball.reach; ++d) {
    std::vector<const Paths*> more{&window};
    if (k >= d) more.push_back(&layers[k - d]);
    if (k + d < layers.size()) more.push_back(&layers[k + d]);
    Paths wider = unite_all(more);
    const __int128 a = twice_area(wider);
    if (a == area) continue;
    window = std::move(wider);
    area = a;
    cylinders.push_back(offset_region(window, ball.radius(d)));
  }
  std::vector<const Paths*> all;
  for (const Paths& c : cylinders) all.push_back(&c);
  return all.empty() ? Paths{} : unite_all(all);
}

std::vector<Paths> each_layer(size_t n, const std::function<Paths(size_t)>& layer, const Progress& progress) {
  std::vector<Paths> out(n);
  parallel_blocks(n, [&](size_t k) { out[k] = layer(k); }, progress, "hollowing");
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
  std::vector<Paths> eroded = each_layer(
      n, [&](size_t k) { return eroded_layer(layers, k, eroding); }, sub_progress(progress, 0, closing ? 0.5 : 1));
  if (!closing) return eroded;
  const LayeredBall dilating(options.closing_mm, thickness_mm);
  return each_layer(
      n, [&](size_t k) { return dilated_layer(eroded, k, dilating); }, sub_progress(progress, 0.5, 1));
}

}  // namespace slicereuse
