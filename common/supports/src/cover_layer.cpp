#include "cover_layer.h"

#include <algorithm>
#include <cmath>

#include "slicereuse/regions/layer_region.h"
#include "slicereuse/supports/support_points.h"

namespace slicereuse {
namespace {

struct Candidates {
  std::vector<std::array<double, 2>> lattice, boundary;
};

std::array<double, 2> mm(const ClipperLib::IntPoint& p) {
  return {double(p.X) / kRegionScale, double(p.Y) / kRegionScale};
}

Candidates candidates_of(const ClipperLib::Paths& part, double g) {
  Candidates c;
  double y_lo = INFINITY, y_hi = -INFINITY;
  for (const ClipperLib::Path& loop : part)
    for (const ClipperLib::IntPoint& p : loop) y_lo = std::min(y_lo, mm(p)[1]), y_hi = std::max(y_hi, mm(p)[1]);
  std::vector<double> xs;
  for (double j = std::ceil(y_lo / g); j * g <= y_hi; ++j) {
    const double y = j * g;
    xs.clear();
    for (const ClipperLib::Path& loop : part)
      for (size_t i = 0; i < loop.size(); ++i) {
        const std::array<double, 2> a = mm(loop[i]), b = mm(loop[(i + 1) % loop.size()]);
        if ((a[1] <= y) != (b[1] <= y)) xs.push_back(a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]));
      }
    std::sort(xs.begin(), xs.end());
    for (size_t i = 0; i + 1 < xs.size(); i += 2)
      for (double k = std::ceil(xs[i] / g); k * g <= xs[i + 1]; ++k) c.lattice.push_back({k * g, y});
  }
  const double step = g / 4;
  for (const ClipperLib::Path& loop : part)
    for (size_t i = 0; i < loop.size(); ++i) {
      const std::array<double, 2> a = mm(loop[i]), b = mm(loop[(i + 1) % loop.size()]);
      const int pieces = std::max(1, int(std::ceil(std::hypot(b[0] - a[0], b[1] - a[1]) / step)));
      for (int s = 0; s < pieces; ++s) {
        const double t = double(s) / pieces;
        c.boundary.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
      }
    }
  return c;
}

std::array<double, 2> centroid(const ClipperLib::Paths& part) {
  double a = 0, cx = 0, cy = 0;
  for (const ClipperLib::Path& loop : part)
    for (size_t i = 0; i < loop.size(); ++i) {
      const std::array<double, 2> p = mm(loop[i]), q = mm(loop[(i + 1) % loop.size()]);
      const double w = p[0] * q[1] - q[0] * p[1];
      a += w, cx += (p[0] + q[0]) * w, cy += (p[1] + q[1]) * w;
    }
  if (a == 0) return mm(part[0][0]);
  return {cx / (3 * a), cy / (3 * a)};
}

}  // namespace

void HeldSurface::add(double x, double y, double z) {
  grid_.add(points_.size(), x, y);
  points_.push_back({x, y, z});
}

double HeldSurface::nearest2(double x, double y, double z) const {
  double best = INFINITY;
  grid_.for_each_near(x, y, [&](size_t i) {
    const std::array<double, 3>& p = points_[i];
    const double dx = p[0] - x, dy = p[1] - y, dz = z - p[2];
    if (dz >= 0) best = std::min(best, dx * dx + dy * dy + dz * dz);
  });
  return best;
}

bool HeldSurface::holds(double x, double y, double z, double reach) const { return nearest2(x, y, z) <= reach * reach; }

double HeldSurface::distance(double x, double y, double z) const {
  const double d = std::sqrt(nearest2(x, y, z));
  return d <= radius_ ? d : INFINITY;
}

std::vector<PlanePoint> hold_slopes(const std::vector<const ClipperLib::Paths*>& slopes,
                                    const std::vector<std::array<double, 2>>& layer, const HeldSurface& held, double z,
                                    const CoverReach& reach, size_t count) {
  const double g = std::min(reach.head, reach.support) / 2;
  const double support_reach = reach.support - (g * std::sqrt(0.5) + g / 8);
  // Each candidate with its distance to the nearest point held or of this layer.
  std::vector<std::array<double, 2>> candidates;
  for (const ClipperLib::Paths* slope : slopes) {
    const Candidates c = candidates_of(*slope, g);
    candidates.insert(candidates.end(), c.lattice.begin(), c.lattice.end());
    candidates.insert(candidates.end(), c.boundary.begin(), c.boundary.end());
  }
  std::vector<double> nearest(candidates.size());
  for (size_t i = 0; i < candidates.size(); ++i) {
    const std::array<double, 2>& q = candidates[i];
    nearest[i] = held.distance(q[0], q[1], z);
    for (const std::array<double, 2>& p : layer) nearest[i] = std::min(nearest[i], std::hypot(p[0] - q[0], p[1] - q[1]));
  }
  std::vector<PlanePoint> out;
  while (out.size() < count) {
    // The first of the farthest, so that the result is fixed.
    size_t best = candidates.size();
    for (size_t i = 0; i < candidates.size(); ++i)
      if (nearest[i] > support_reach && (best == candidates.size() || nearest[i] > nearest[best])) best = i;
    if (best == candidates.size()) break;
    const std::array<double, 2> p = candidates[best];
    out.push_back({p[0], p[1], uint8_t(SupportKind::Overhang)});
    for (size_t i = 0; i < candidates.size(); ++i)
      nearest[i] = std::min(nearest[i], std::hypot(candidates[i][0] - p[0], candidates[i][1] - p[1]));
  }
  return out;
}

std::vector<PlanePoint> cover_layer(const LayerAreas& areas, const std::vector<std::array<double, 2>>& existing,
                                    const HeldSurface& held, double z, const CoverReach& reach) {
  // The lattice is fine enough for the smaller reach: every reach less the margin stays
  // positive (0.90 of it at least), at any density; finer than half the reach (0.58 of it)
  // since the points' count goes with the inverse square of what is left.
  const double g = std::min(reach.head, reach.support) / 8;
  const double margin = g * std::sqrt(0.5) + g / 8;
  const double support_reach = reach.support - margin;
  // This layer's points: held in its plane (dz 0) within the head reach, an overhang's within
  // the support radius too when that is smaller.
  const double head_reach = reach.head - margin;
  const double overhang_reach = std::min(reach.head, reach.support) - margin;
  HeldSurface taken(head_reach);
  for (const std::array<double, 2>& p : existing) taken.add(p[0], p[1], z);
  std::vector<PlanePoint> out;
  auto take = [&](const std::array<double, 2>& p, SupportKind kind) {
    taken.add(p[0], p[1], z);
    out.push_back({p[0], p[1], uint8_t(kind)});
  };
  auto cover = [&](const std::vector<ClipperLib::Paths>& parts, SupportKind kind, double own_reach, bool held_counts) {
    for (const ClipperLib::Paths& part : parts) {
      const Candidates c = candidates_of(part, g);
      if (kind == SupportKind::Island &&
          std::none_of(existing.begin(), existing.end(),
                       [&](const std::array<double, 2>& p) { return part_contains(part, p[0], p[1]); })) {
        std::array<double, 2> seed = mm(part[0][0]);
        const std::array<double, 2> m = centroid(part);
        double best = INFINITY;
        for (const std::array<double, 2>& p : c.lattice) {
          const double d = std::hypot(p[0] - m[0], p[1] - m[1]);
          if (d < best) best = d, seed = p;
        }
        take(seed, kind);
      }
      // Each candidate not yet held, in order, gets held by the candidate within reach of it
      // that holds the most of those not yet held (the first on a tie): taking the candidate
      // itself, at the edge of what is held, would spend half its disc on held ground.
      const size_t lattice = c.lattice.size();
      std::vector<std::array<double, 2>> all = std::move(c.lattice);
      all.insert(all.end(), c.boundary.begin(), c.boundary.end());
      std::vector<uint8_t> held_now(all.size());
      for (size_t i = 0; i < all.size(); ++i)
        held_now[i] = taken.holds(all[i][0], all[i][1], z, own_reach) ||
                      (held_counts && held.holds(all[i][0], all[i][1], z, support_reach));
      CellGrid grid(own_reach);
      for (size_t i = 0; i < all.size(); ++i) grid.add(i, all[i][0], all[i][1]);
      const auto within_reach = [&](size_t of, auto f) {
        grid.for_each_near(all[of][0], all[of][1], [&](size_t q) {
          if (std::hypot(all[q][0] - all[of][0], all[q][1] - all[of][1]) <= own_reach) f(q);
        });
      };
      // In rows, the boundary's candidates among the lattice's: a boundary candidate left for
      // after the lattice, however near what its row took, would take a point of its own.
      std::vector<size_t> order(all.size());
      for (size_t i = 0; i < order.size(); ++i) order[i] = i;
      std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return all[a][1] != all[b][1] ? all[a][1] < all[b][1] : all[a][0] < all[b][0];
      });
      for (const size_t i : order) {
        if (held_now[i]) continue;
        size_t best = i, most = 0;
        within_reach(i, [&](size_t p) {
          // A layer's points stand apart; a point on the boundary may miss the face under it
          // (placed then at the nearest contour point), so only the candidate itself takes one.
          if ((p >= lattice && p != i) || taken.holds(all[p][0], all[p][1], z, own_reach / 2)) return;
          size_t n = 0;
          within_reach(p, [&](size_t q) { n += !held_now[q]; });
          if (n > most || (n == most && p < best)) most = n, best = p;
        });
        take(all[best], kind);
        within_reach(best, [&](size_t q) { held_now[q] = 1; });
      }
    }
  };
  cover(areas.islands, SupportKind::Island, head_reach, false);
  cover(areas.far, SupportKind::Overhang, head_reach, false);
  cover(areas.overhangs, SupportKind::Overhang, overhang_reach, true);
  return out;
}

}  // namespace slicereuse
