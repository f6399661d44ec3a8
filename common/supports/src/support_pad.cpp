#include "support_pad.h"

#include <algorithm>
#include <cmath>

#include "support_shapes.h"

namespace slicereuse {

namespace {

using Point = std::array<double, 2>;

double turn(const Point& o, const Point& a, const Point& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Andrew's monotone chain: the hull's corners counter-clockwise, without collinear ones (one or
// two points when all axes coincide or lie on a line).
std::vector<Point> convex_hull(std::vector<Point> p) {
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Point> h(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && turn(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && turn(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

// The hull corner farthest in direction angle a; of several equally far (an edge of the hull
// facing exactly that way), the last counter-clockwise, so that the corners found for
// increasing angles advance counter-clockwise.
size_t extreme_corner(const std::vector<Point>& hull, double a) {
  const double c = std::cos(a), s = std::sin(a);
  const size_t n = hull.size();
  size_t best = 0;
  for (size_t i = 1; i < n; ++i)
    if (hull[i][0] * c + hull[i][1] * s > hull[best][0] * c + hull[best][1] * s) best = i;
  const double m = hull[best][0] * c + hull[best][1] * s;
  for (size_t steps = 1; steps < n; ++steps) {
    const size_t next = (best + 1) % n;
    if (hull[next][0] * c + hull[next][1] * s < m) break;
    best = next;
  }
  return best;
}

}  // namespace

void place_pad(const SupportTreeOptions& o, double ground_z, SupportStructure& s) {
  std::vector<Point> axes;
  for (const SupportPillar& p : s.pillars)
    if (p.end == PillarEnd::Ground) axes.push_back({p.x, p.y});
  if (!o.pad_enable || axes.empty()) return;
  const double r_top = o.base_diameter_mm / 2 + o.pad_brim_mm;
  const double r_bottom = r_top - o.pad_wall_thickness_mm / std::tan(o.pad_wall_slope_deg * M_PI / 180);
  const std::vector<Point> hull = convex_hull(axes);
  const size_t n = hull.size();
  // Polygon corner j (angle 2 pi j / sides) is the farthest in the directions between its two
  // edges' normals, at 2 pi (j -+ 1/2) / sides; the hull corners farthest in those directions
  // are the ones it is added to, in counter-clockwise order.
  std::vector<std::array<size_t, 2>> pairs;  // (hull corner, polygon corner)
  for (int j = 0; j < kSupportSides; ++j) {
    size_t i = extreme_corner(hull, 2 * M_PI * (j - 0.5) / kSupportSides);
    const size_t last = extreme_corner(hull, 2 * M_PI * (j + 0.5) / kSupportSides);
    pairs.push_back({i, size_t(j)});
    for (; i != last; pairs.push_back({i, size_t(j)})) i = (i + 1) % n;
  }
  const Outline unit = circle_outline(0, 0, 1);
  s.pad.z_bottom = ground_z;
  s.pad.z_top = ground_z + o.pad_wall_thickness_mm;
  for (const auto& [i, j] : pairs) {
    s.pad.bottom.push_back({hull[i][0] + r_bottom * unit[j][0], hull[i][1] + r_bottom * unit[j][1]});
    s.pad.top.push_back({hull[i][0] + r_top * unit[j][0], hull[i][1] + r_top * unit[j][1]});
  }
}

}  // namespace slicereuse
