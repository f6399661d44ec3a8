#include "slicereuse/hollowing/cavity.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "region_clearance.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/regions/simplify_paths.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse {
namespace {

using ClipperLib::cInt;
using ClipperLib::Paths;

// A region offset by delta_mm (negative: inwards) with round joins, as ClipperOffset does (its
// steps per radian from kCavityArcToleranceMm, its union of the raw loops), except at a corner
// the offset turns inside of: where the two shifted edges meet within the first half of each, it
// takes their meeting point, where ClipperOffset adds a small loop through the corner for the
// union to resolve into that same point. A dense smooth contour turns inside at nearly every
// vertex, and those loops' crossings were most of its offsets' cost.
Paths offset_region(const Paths& region, double delta_mm) {
  const double delta = delta_mm * kRegionScale, size = std::fabs(delta);
  if (region.empty() || size < 1) return region;
  const double tolerance = std::min(kCavityArcToleranceMm * kRegionScale, size / 4);
  const double steps = std::min(M_PI / std::acos(1 - tolerance / size), size * M_PI);
  const double step_sin = std::sin(2 * M_PI / steps) * (delta < 0 ? -1 : 1), step_cos = std::cos(2 * M_PI / steps);
  const double steps_per_radian = steps / (2 * M_PI);
  const auto at = [](const ClipperLib::IntPoint& p, double dx, double dy) {
    return ClipperLib::IntPoint(std::llround(double(p.X) + dx), std::llround(double(p.Y) + dy));
  };
  Paths raw;
  std::vector<double> nx, ny, length;
  for (const ClipperLib::Path& loop : region) {
    const size_t n = loop.size();
    if (n < 3) continue;
    nx.resize(n), ny.resize(n), length.resize(n);
    for (size_t j = 0; j < n; ++j) {
      const double dx = double(loop[(j + 1) % n].X - loop[j].X), dy = double(loop[(j + 1) % n].Y - loop[j].Y);
      length[j] = std::hypot(dx, dy);
      nx[j] = length[j] > 0 ? dy / length[j] : 0, ny[j] = length[j] > 0 ? -dx / length[j] : 0;
    }
    ClipperLib::Path out;
    out.reserve(n + n / 2);
    size_t k = n - 1;  // the edge before, skipping nearly straight corners as ClipperOffset does
    for (size_t j = 0; j < n; ++j) {
      const ClipperLib::IntPoint& p = loop[j];
      double sin_a = nx[k] * ny[j] - nx[j] * ny[k];
      const double cos_a = nx[k] * nx[j] + ny[k] * ny[j];
      if (std::fabs(sin_a * delta) < 1 && cos_a > 0) {
        out.push_back(at(p, nx[k] * delta, ny[k] * delta));
        continue;
      }
      sin_a = std::clamp(sin_a, -1.0, 1.0);
      if (sin_a * delta < 0) {
        const double r = 1 + cos_a;  // the shifted edges meet delta tan(angle / 2) from p's
        if (r > 1e-9 && size * std::fabs(sin_a) / r <= 0.5 * std::min(length[k], length[j])) {
          out.push_back(at(p, (nx[k] + nx[j]) * delta / r, (ny[k] + ny[j]) * delta / r));
        } else {
          out.push_back(at(p, nx[k] * delta, ny[k] * delta));
          out.push_back(p);
          out.push_back(at(p, nx[j] * delta, ny[j] * delta));
        }
      } else {
        const int arc = std::max(1, int(std::lround(steps_per_radian * std::fabs(std::atan2(sin_a, cos_a)))));
        double x = nx[k], y = ny[k];
        for (int i = 0; i < arc; ++i) {
          out.push_back(at(p, x * delta, y * delta));
          const double x2 = x;
          x = x * step_cos - step_sin * y;
          y = x2 * step_sin + y * step_cos;
        }
        out.push_back(at(p, nx[j] * delta, ny[j] * delta));
      }
      k = j;
    }
    raw.push_back(std::move(out));
  }
  ClipperLib::Clipper clipper;
  clipper.AddPaths(raw, ClipperLib::ptSubject, true);
  Paths out;
  if (delta > 0) {
    clipper.Execute(ClipperLib::ctUnion, out, ClipperLib::pftPositive, ClipperLib::pftPositive);
    return out;
  }
  // Inwards, the loops' union reversed inside a box around them all, less the box.
  const ClipperLib::IntRect b = clipper.GetBounds();
  clipper.AddPath({{b.left - 10, b.bottom + 10}, {b.right + 10, b.bottom + 10}, {b.right + 10, b.top - 10},
                   {b.left - 10, b.top - 10}},
                  ClipperLib::ptSubject, true);
  clipper.ReverseSolution(true);
  clipper.Execute(ClipperLib::ctUnion, out, ClipperLib::pftNegative, ClipperLib::pftNegative);
  if (!out.empty()) out.erase(out.begin());
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

// The layers within a ball of radius r of a layer, and their disk's radius at d layers away, plus
// slack (the error the layers' simplification may have made, so that erosion stays inside).
struct LayeredBall {
  LayeredBall(double radius_mm, double thickness_mm, double slack_mm = 0)
      : r(radius_mm), h(thickness_mm), slack(slack_mm), reach(long(std::floor(radius_mm / thickness_mm + 1e-9))) {}
  double radius(long d) const { return std::sqrt(std::max(0.0, r * r - double(d * d) * h * h)) + slack; }
  double r, h, slack;
  long reach;  // layers each way
};

// A layer's loops, each turned to start at its least point (by y, then x) and in the order of
// those points: what a simplification keeps then depends on the loops' points alone, not on where
// a slicer began them (a member's contours by reuse and by direct slicing are the same points).
Paths canonical_loops(const Paths& loops) {
  const auto less = [](const ClipperLib::IntPoint& a, const ClipperLib::IntPoint& b) {
    return a.Y < b.Y || (a.Y == b.Y && a.X < b.X);
  };
  Paths out;
  for (const ClipperLib::Path& loop : loops) {
    if (loop.empty()) continue;
    out.emplace_back(loop.size());
    std::rotate_copy(loop.begin(), std::min_element(loop.begin(), loop.end(), less), loop.end(), out.back().begin());
  }
  std::sort(out.begin(), out.end(), [&](const ClipperLib::Path& a, const ClipperLib::Path& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), less);
  });
  return out;
}

// The layers (loops filled by the nonzero rule: contours as sliced, or regions) simplified to
// within kCavitySimplifyMm (simplify_paths.h), and the farthest any dropped vertex lay from its
// chord: a layer's region then lies within that of the original's boundary. A loop too thin to
// keep three vertices stays as it was (it may be a hole, which must not fill).
std::vector<Paths> simplified_layers(const std::vector<Paths>& layers, double& deviation_mm) {
  std::vector<Paths> out(layers.size());
  std::vector<double> deviation(layers.size(), 0);
  parallel_blocks(
      layers.size(),
      [&](size_t k) {
        ClipperLib::Clipper clipper;
        for (const ClipperLib::Path& loop : canonical_loops(layers[k])) {
          double d = 0;
          const Paths simple = simplify_paths({loop}, kCavitySimplifyMm * kRegionScale, &d);
          clipper.AddPaths(simple.empty() ? Paths{loop} : simple, ClipperLib::ptSubject, true);
          deviation[k] = std::max(deviation[k], d);
        }
        // Simplified loops may touch or cross where the originals came near (simplify_paths.h).
        clipper.Execute(ClipperLib::ctUnion, out[k], ClipperLib::pftNonZero, ClipperLib::pftNonZero);
      },
      {}, "hollowing");
  deviation_mm = *std::max_element(deviation.begin(), deviation.end()) / kRegionScale;
  return out;
}

// A term binds when the result comes this near its offset's edge (in Clipper units, the offsets'
// arc tolerance): it is tried first on the next layer, whose result it likely bounds too.
constexpr double kBindingUnits = kCavityArcToleranceMm * kRegionScale;
// Layers a thread works through in order, handing on the terms that bind from one to the next:
// each run starts cold, with no binding term known (a 35 mm sphere, 700 layers: 16 a run 11 %
// slower than 64, 128 no faster, and fewer runs than threads would idle some).
constexpr size_t kBlockLayers = 64;

// The stack's layers and, for every aligned run of 2^s of them (s >= 1) up to the ball's reach,
// their intersection (eroding) or union (dilating): a run's whole set of terms is proved at once
// against it (see StackByBall).
class LayerBlocks {
 public:
  LayerBlocks(const std::vector<Paths>& layers, long reach, bool grow, const Progress& progress) : layers_(layers) {
    const size_t n = layers.size();
    index_.emplace_back(n);
    parallel_blocks(n, [&](size_t k) { index_[0][k] = index_region(layers[k]); }, {}, "hollowing");
    for (size_t s = 1; (long(1) << s) <= reach; ++s) {
      const size_t count = (n + (size_t(1) << s) - 1) >> s;
      blocks_.emplace_back(count);
      index_.emplace_back(count);
      parallel_blocks(
          count,
          [&](size_t i) {
            const Paths& a = region(s - 1, 2 * i);
            Paths& out = blocks_[s - 1][i];
            if (2 * i + 1 < index_[s - 1].size()) {
              const Paths& b = region(s - 1, 2 * i + 1);
              out = grow ? unite_all({&a, &b}) : intersect_all({&a, &b});
            } else {
              out = a;
            }
            index_[s][i] = index_region(out);
          },
          progress, "hollowing");
    }
  }
  size_t size() const { return layers_.size(); }
  size_t levels() const { return index_.size(); }
  const Paths& region(size_t s, size_t i) const { return s == 0 ? layers_[i] : blocks_[s - 1][i]; }
  const IndexedRegion& indexed(size_t s, size_t i) const { return index_[s][i]; }

 private:
  const std::vector<Paths>& layers_;
  std::vector<std::vector<Paths>> blocks_;  // levels 1, 2, ...
  std::vector<std::vector<IndexedRegion>> index_;
};

// Layer k of the stack eroded (grow false) or dilated by the ball (cavity.h): the intersection
// (or union) over the layers k + e within it of their regions offset inwards (or outwards) by
// radius(|e|), layers beyond the stack being empty. The terms that bound the layer below (or,
// when none did, e = 0) give a candidate; every other term is then proved to change nothing, a run of layers at
// once where it can: eroding, when the candidate lies at least radius(d) inside the run's
// intersection, d being its layer nearest to k, it lies inside each of the run's terms;
// dilating, when the run's union lies at least radius(d) inside the candidate, so does each of
// the run's terms' offsets (region_clearance.h). A run that fails is split in two, and a single
// layer that fails is offset and taken in. So the result is the whole intersection (or union),
// while a smooth part costs a few offsets and proofs a layer; but for the slack
// (kCavityProofSlackMm): on a curved surface the terms next to the one that binds come within
// nanometres of binding, and proving or taking each of them was most of the cost.
class StackByBall {
 public:
  StackByBall(const LayerBlocks& blocks, const LayeredBall& ball, bool grow)
      : blocks_(blocks), ball_(ball), grow_(grow) {}

  // Layers [a, b) into out, in order.
  void layers(size_t a, size_t b, std::vector<Paths>& out) {
    const long n = long(blocks_.size());
    std::vector<long> binding;
    for (long k = long(a); k < long(b); ++k) {
      if (binding.empty()) binding.push_back(0);
      if (!grow_ && (k < ball_.reach || k + ball_.reach >= n)) continue;  // within reach of the empty outside
      k_ = k;
      terms_.clear();
      result_.clear();
      for (long e : binding)
        if (k + e >= 0 && k + e < n) take(e);
      candidate_ = index_region(result_);
      prove(std::max(0L, k - ball_.reach), k);
      prove(k + 1, std::min(n - 1, k + ball_.reach));
      binding.clear();
      for (long e : terms_)
        if (!holds(blocks_.indexed(0, size_t(k + e)), taken_radius(e) * kRegionScale + kBindingUnits))
          binding.push_back(e);
      out[size_t(k)] = std::move(result_);
    }
  }

 private:
  // Whether the candidate lies at least distance inside the run (eroding), or the run inside the
  // candidate (dilating).
  bool holds(const IndexedRegion& run, double distance) const {
    return grow_ ? clears(run, candidate_, distance) : clears(candidate_, run, distance);
  }

  // The radius term e is offset by: eroding, an off-centre term goes kCavityProofSlackMm deeper,
  // so that the terms left out need only be proved at their own radius (see prove). Layer k's
  // own term stays exact, so that a prism's cavity is its layer offset by the wall.
  double taken_radius(long e) const { return ball_.radius(std::labs(e)) + (grow_ || e == 0 ? 0 : kCavityProofSlackMm); }

  // Term e offset and taken into the result.
  void take(long e) {
    const Paths& layer = blocks_.region(0, size_t(k_ + e));
    const double r = taken_radius(e);
    const Paths term = offset_region(layer, grow_ ? r : -r);
    if (terms_.empty()) result_ = term;
    else result_ = grow_ ? unite_all({&result_, &term}) : intersect_all({&result_, &term});
    terms_.push_back(e);
  }

  // Proves the terms of layers [lo, hi] (all on one side of k, or k itself), taking in those
  // that fail.
  void prove(long lo, long hi) {
    if (lo > hi) return;
    const size_t top = blocks_.levels() - 1;
    for (long i = lo >> top; i <= hi >> top; ++i) prove(top, i, lo, hi);
  }

  void prove(size_t s, long i, long lo, long hi) {
    if (!grow_ && result_.empty()) return;
    const long b0 = i << s, b1 = std::min(((i + 1) << s) - 1, long(blocks_.size()) - 1);
    if (b1 < lo || b0 > hi) return;
    // A run may reach past the range's far end, beyond the ball: its layers there add only
    // constraints, and proving it whole spares splitting it down to the range's end.
    if (lo > k_ ? lo <= b0 : b1 <= hi) {
      // Dilating, a run whose terms come within the slack of the candidate's edge is left out.
      const double r =
          std::max(0.0, ball_.radius(b0 > k_ ? b0 - k_ : k_ - b1) - (grow_ ? kCavityProofSlackMm : 0)) * kRegionScale;
      if (holds(blocks_.indexed(s, size_t(i)), r)) return;
      if (s == 0) {
        if (std::find(terms_.begin(), terms_.end(), b0 - k_) == terms_.end()) {
          take(b0 - k_);
          candidate_ = index_region(result_);
        }
        return;
      }
    }
    prove(s - 1, 2 * i, lo, hi);
    prove(s - 1, 2 * i + 1, lo, hi);
  }

  const LayerBlocks& blocks_;
  const LayeredBall ball_;
  const bool grow_;
  long k_ = 0;
  std::vector<long> terms_;
  Paths result_;
  IndexedRegion candidate_;
};

// The stack eroded or dilated by the ball, runs of layers on all cores.
std::vector<Paths> by_ball(const std::vector<Paths>& layers, const LayeredBall& ball, bool grow,
                           const Progress& progress) {
  const size_t n = layers.size();
  const LayerBlocks blocks(layers, ball.reach, grow, sub_progress(progress, 0, 0.2));
  std::vector<Paths> out(n);
  parallel_blocks(
      (n + kBlockLayers - 1) / kBlockLayers,
      [&](size_t i) { StackByBall(blocks, ball, grow).layers(i * kBlockLayers, std::min(n, (i + 1) * kBlockLayers), out); },
      sub_progress(progress, 0.2, 1), "hollowing");
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
  if (options.wall_mm == 0 || n == 0) return std::vector<Paths>(n);
  // Eroding each simplified layer by as much more as it strayed keeps the cavity inside the exact
  // one (a point that far inside the simplified region lies at least the radius inside the
  // original: the region between a dropped chain and its chord lies within the deviation of the
  // chord), so walls stay at least t thick; the dilation then adds no error of its own.
  double deviation_mm = 0;
  const std::vector<Paths> simple = simplified_layers(layers, deviation_mm);
  const LayeredBall eroding(options.wall_mm + options.closing_mm, thickness_mm, deviation_mm);
  const bool closing = options.closing_mm > 0;
  std::vector<Paths> eroded = by_ball(simple, eroding, false, sub_progress(progress, 0, closing ? 0.5 : 1));
  if (!closing) return eroded;
  return by_ball(eroded, LayeredBall(options.closing_mm, thickness_mm), true, sub_progress(progress, 0.5, 1));
}

}  // namespace slicereuse
