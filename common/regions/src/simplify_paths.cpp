#include "slicereuse/regions/simplify_paths.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "slicereuse/regions/segment_distance.h"

namespace slicereuse {
namespace {

// Squared distance from p to the segment ab, in Clipper units squared.
double distance2(const ClipperLib::IntPoint& p, const ClipperLib::IntPoint& a, const ClipperLib::IntPoint& b) {
  return segment_distance2(double(p.X), double(p.Y), double(a.X), double(a.Y), double(b.X), double(b.Y));
}

// Marks the vertices of loop[first..last] (indices modulo n) that Douglas-Peucker keeps, and
// raises deviation2 to the farthest a dropped vertex lies from its chord, squared.
void mark(const ClipperLib::Path& loop, size_t first, size_t last, double tol2, std::vector<char>& keep,
          double& deviation2) {
  const size_t n = loop.size();
  std::vector<std::pair<size_t, size_t>> stack{{first, last}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    double worst = 0;
    size_t at = a;
    for (size_t i = a + 1; i < b; ++i) {
      const double d2 = distance2(loop[i % n], loop[a % n], loop[b % n]);
      if (d2 > worst) worst = d2, at = i;
    }
    if (worst <= tol2) {
      deviation2 = std::max(deviation2, worst);
      continue;
    }
    keep[at % n] = 1;
    stack.push_back({a, at});
    stack.push_back({at, b});
  }
}

}  // namespace

ClipperLib::Paths simplify_paths(const ClipperLib::Paths& paths, double tolerance, double* deviation) {
  const double tol2 = tolerance * tolerance;
  ClipperLib::Paths out;
  out.reserve(paths.size());
  std::vector<char> keep;
  double deviation2 = 0;
  for (const ClipperLib::Path& loop : paths) {
    const size_t n = loop.size();
    if (n < 3) continue;
    size_t far = 0;
    double far2 = -1;
    for (size_t i = 1; i < n; ++i) {
      const double dx = double(loop[i].X - loop[0].X), dy = double(loop[i].Y - loop[0].Y);
      if (dx * dx + dy * dy > far2) far2 = dx * dx + dy * dy, far = i;
    }
    keep.assign(n, 0);
    keep[0] = keep[far] = 1;
    mark(loop, 0, far, tol2, keep, deviation2);
    mark(loop, far, n, tol2, keep, deviation2);
    ClipperLib::Path simple;
    for (size_t i = 0; i < n; ++i)
      if (keep[i]) simple.push_back(loop[i]);
    if (simple.size() >= 3) out.push_back(std::move(simple));
  }
  if (deviation) *deviation = std::sqrt(deviation2);
  return out;
}

}  // namespace slicereuse
