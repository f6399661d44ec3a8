#include "region_clearance.h"

#include <algorithm>
#include <cmath>

#include "slicereuse/regions/layer_region.h"
#include "slicereuse/regions/segment_distance.h"

namespace slicereuse {
namespace {

// Runs short enough that a run of a smooth contour hugs its chord (its stray is what every bound
// between runs loses), long enough that few runs are compared (bench/RESULTS.md, "Measurements
// behind design choices"); groups of runs, and groups of groups, so that few are compared pairwise.
constexpr uint32_t kRunEdges = IndexedRegion::kRunEdges;
constexpr uint32_t kGroupSize = 4;

using ClipperLib::IntPoint;

int orientation(const IntPoint& a, const IntPoint& b, const IntPoint& c) {
  const __int128 x = __int128(b.X - a.X) * (c.Y - a.Y) - __int128(b.Y - a.Y) * (c.X - a.X);
  return (x > 0) - (x < 0);
}

bool on_segment(const IntPoint& a, const IntPoint& b, const IntPoint& p) {
  return std::min(a.X, b.X) <= p.X && p.X <= std::max(a.X, b.X) && std::min(a.Y, b.Y) <= p.Y &&
         p.Y <= std::max(a.Y, b.Y);
}

// Whether segments ab and cd meet (cross or touch), exactly.
bool segments_meet(const IntPoint& a, const IntPoint& b, const IntPoint& c, const IntPoint& d) {
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d), o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) || (o3 == 0 && on_segment(c, d, a)) ||
         (o4 == 0 && on_segment(c, d, b));
}

double point_segment2(const IntPoint& p, const IntPoint& a, const IntPoint& b) {
  return segment_distance2(double(p.X), double(p.Y), double(a.X), double(a.Y), double(b.X), double(b.Y));
}

double segments_distance2(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
  return std::min({segment_distance2(ax, ay, cx, cy, dx, dy), segment_distance2(bx, by, cx, cy, dx, dy),
                   segment_distance2(cx, cy, ax, ay, bx, by), segment_distance2(dx, dy, ax, ay, bx, by)});
}

// Whether the chords of two runs cross: then their distance is 0, which the four end-point
// distances would not say.
bool chords_cross(const IndexedRegion::Run& r, const IndexedRegion::Run& s) {
  const auto side = [](double ax, double ay, double bx, double by, double px, double py) {
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
  };
  const double o1 = side(r.ax, r.ay, r.bx, r.by, s.ax, s.ay), o2 = side(r.ax, r.ay, r.bx, r.by, s.bx, s.by);
  const double o3 = side(s.ax, s.ay, s.bx, s.by, r.ax, r.ay), o4 = side(s.ax, s.ay, s.bx, s.by, r.bx, r.by);
  return ((o1 > 0) != (o2 > 0)) && ((o3 > 0) != (o4 > 0));
}

// The least squared distance from a point of run r to an edge of run s (RunPoints'
// padding repeats points and adds edges of no length: nothing nearer than the run's own).
double nearest2(const IndexedRegion::RunPoints& r, const IndexedRegion::RunPoints& s) {
  double least = INFINITY;
  for (uint32_t i = 0; i <= kRunEdges; ++i)
    for (uint32_t j = 0; j < kRunEdges; ++j) {
      const double qx = r.px[i] - s.px[j], qy = r.py[i] - s.py[j];
      double t = qx * s.ux[j] + qy * s.uy[j];
      t = t < 0 ? 0 : (t > 1 ? 1 : t);
      const double ex = qx - t * (s.px[j + 1] - s.px[j]), ey = qy - t * (s.py[j + 1] - s.py[j]);
      least = std::min(least, ex * ex + ey * ey);
    }
  return least;
}

// Consecutive items (runs or groups) kGroupSize at a time, with their boxes.
template <class Item>
std::vector<IndexedRegion::Group> grouped(const std::vector<Item>& items) {
  std::vector<IndexedRegion::Group> groups;
  for (uint32_t first = 0; first < items.size(); first += kGroupSize) {
    IndexedRegion::Group g{first, std::min(kGroupSize, uint32_t(items.size()) - first), INFINITY, INFINITY, -INFINITY,
                           -INFINITY};
    for (uint32_t i = first; i < first + g.count; ++i) {
      const Item& r = items[i];
      g.x0 = std::min(g.x0, r.x0), g.y0 = std::min(g.y0, r.y0), g.x1 = std::max(g.x1, r.x1), g.y1 = std::max(g.y1, r.y1);
    }
    groups.push_back(g);
  }
  return groups;
}

}  // namespace

IndexedRegion index_region(const ClipperLib::Paths& region) {
  IndexedRegion out;
  out.region = &region;
  for (uint32_t l = 0; l < region.size(); ++l) {
    const ClipperLib::Path& loop = region[l];
    const uint32_t n = uint32_t(loop.size());
    for (uint32_t first = 0; first < n; first += kRunEdges) {
      const uint32_t edges = std::min(kRunEdges, n - first);
      const IntPoint& a = loop[first];
      const IntPoint& b = loop[(first + edges) % n];
      double stray2 = 0;
      ClipperLib::cInt x0 = a.X, y0 = a.Y, x1 = a.X, y1 = a.Y;
      for (uint32_t i = 1; i <= edges; ++i) {
        const IntPoint& p = loop[(first + i) % n];
        stray2 = std::max(stray2, point_segment2(p, a, b));
        x0 = std::min(x0, p.X), y0 = std::min(y0, p.Y), x1 = std::max(x1, p.X), y1 = std::max(y1, p.Y);
      }
      out.runs.push_back({l, first, edges, double(a.X), double(a.Y), double(b.X), double(b.Y), std::sqrt(stray2),
                          double(x0), double(y0), double(x1), double(y1)});
      IndexedRegion::RunPoints run;
      for (uint32_t i = 0; i <= kRunEdges; ++i) {
        const IntPoint& p = loop[(first + std::min(i, edges)) % n];
        run.px[i] = double(p.X), run.py[i] = double(p.Y);
      }
      for (uint32_t i = 0; i < kRunEdges; ++i) {
        const double dx = run.px[i + 1] - run.px[i], dy = run.py[i + 1] - run.py[i], len2 = dx * dx + dy * dy;
        run.ux[i] = len2 > 0 ? dx / len2 : 0, run.uy[i] = len2 > 0 ? dy / len2 : 0;
      }
      out.points.push_back(run);
    }
  }
  out.groups = grouped(out.runs);
  out.supergroups = grouped(out.groups);
  return out;
}

bool boundaries_apart(const IndexedRegion& inner, const IndexedRegion& outer, double distance) {
  const ClipperLib::Paths& in = *inner.region;
  const ClipperLib::Paths& out = *outer.region;
  // Boxes or capsules this far apart or more hold nothing nearer than distance, nor any crossing.
  const double distance2 = distance * distance;
  const auto apart = [distance](double gap) { return gap >= distance && gap > 0; };
  const auto boxes_apart = [distance2](const auto& r, const auto& s) {
    const double gx = std::max({0.0, r.x0 - s.x1, s.x0 - r.x1}), gy = std::max({0.0, r.y0 - s.y1, s.y0 - r.y1});
    const double gap2 = gx * gx + gy * gy;
    return gap2 >= distance2 && gap2 > 0;
  };
  // Whether two runs come nearer than distance, or meet.
  const auto too_near = [&](uint32_t ri, uint32_t si) {
    const IndexedRegion::Run& r = inner.runs[ri];
    const IndexedRegion::Run& s = outer.runs[si];
    if (boxes_apart(r, s)) return false;
    const double chords =
        chords_cross(r, s) ? 0 : std::sqrt(segments_distance2(r.ax, r.ay, r.bx, r.by, s.ax, s.ay, s.bx, s.by));
    const double bound = chords - r.stray - s.stray;
    if (apart(bound)) return false;
    if (bound <= 0) {  // capsules apart hold no crossing
      const ClipperLib::Path& p = in[r.loop];
      const ClipperLib::Path& q = out[s.loop];
      for (uint32_t i = r.first; i < r.first + r.edges; ++i)
        for (uint32_t j = s.first; j < s.first + s.edges; ++j)
          if (segments_meet(p[i], p[(i + 1) % p.size()], q[j], q[(j + 1) % q.size()])) return true;
    }
    // Segments that do not meet are as near as an end of one to the other: every point of each
    // run against every edge of the other, all at once.
    const IndexedRegion::RunPoints& rp = inner.points[ri];
    const IndexedRegion::RunPoints& sp = outer.points[si];
    return std::min(nearest2(rp, sp), nearest2(sp, rp)) < distance2;
  };
  for (const IndexedRegion::Group& gg : inner.supergroups)
    for (const IndexedRegion::Group& hh : outer.supergroups) {
      if (boxes_apart(gg, hh)) continue;
      for (uint32_t gi = gg.first; gi < gg.first + gg.count; ++gi)
        for (uint32_t hi = hh.first; hi < hh.first + hh.count; ++hi) {
          const IndexedRegion::Group& g = inner.groups[gi];
          const IndexedRegion::Group& h = outer.groups[hi];
          if (boxes_apart(g, h)) continue;
          for (uint32_t ri = g.first; ri < g.first + g.count; ++ri) {
            if (boxes_apart(inner.runs[ri], h)) continue;
            for (uint32_t si = h.first; si < h.first + h.count; ++si)
              if (too_near(ri, si)) return false;
          }
        }
    }
  return true;
}

bool clears(const IndexedRegion& inner, const IndexedRegion& outer, double distance) {
  const ClipperLib::Paths& in = *inner.region;
  const ClipperLib::Paths& out = *outer.region;
  if (in.empty()) return true;
  if (out.empty()) return false;
  if (!boundaries_apart(inner, outer, distance)) return false;
  // The boundaries do not meet, so each loop lies wholly inside or outside the other region:
  // inner lies in outer when every inner loop does and no outer loop lies in inner.
  for (const ClipperLib::Path& loop : in)
    if (!region_covers(out, loop[0])) return false;
  for (const ClipperLib::Path& loop : out)
    if (region_covers(in, loop[0])) return false;
  return true;
}

int winding_number(const ClipperLib::Paths& loops, const IntPoint& p) {
  int w = 0;
  for (const ClipperLib::Path& loop : loops)
    for (size_t i = 0; i < loop.size(); ++i) {
      const IntPoint& a = loop[i];
      const IntPoint& b = loop[(i + 1) % loop.size()];
      if (a.Y <= p.Y) {
        if (b.Y > p.Y && orientation(a, b, p) > 0) ++w;  // upwards, p on its left
      } else if (b.Y <= p.Y && orientation(a, b, p) < 0) {
        --w;  // downwards, p on its right
      }
    }
  return w;
}

}  // namespace slicereuse
