#include "slicereuse/supports/support_keep_out.h"

#include <algorithm>

namespace slicereuse {
namespace {

// The squared distance from p to the segment [a, b].
double squared_distance(const double* p, const std::array<double, 3>& a, const std::array<double, 3>& b) {
  double ab[3], ap[3], len2 = 0, dot = 0;
  for (int j = 0; j < 3; ++j) ab[j] = b[j] - a[j], ap[j] = p[j] - a[j], len2 += ab[j] * ab[j], dot += ab[j] * ap[j];
  const double t = len2 > 0 ? std::clamp(dot / len2, 0.0, 1.0) : 0;
  double d2 = 0;
  for (int j = 0; j < 3; ++j) d2 += (ap[j] - t * ab[j]) * (ap[j] - t * ab[j]);
  return d2;
}

}  // namespace

size_t drop_points_in(SupportPoints& points, const std::vector<KeepOutCylinder>& cylinders, double head_radius_mm) {
  if (cylinders.empty()) return 0;
  SupportPoints kept;
  kept.fingerprint = points.fingerprint;
  for (size_t i = 0; i < points.size(); ++i) {
    bool clear = true;
    for (const KeepOutCylinder& c : cylinders) {
      const double reach = c.radius_mm + head_radius_mm;
      clear = clear && squared_distance(&points.xyz[3 * i], c.from, c.to) >= reach * reach;
    }
    if (clear) kept.push_back_from(points, i);
  }
  const size_t dropped = points.size() - kept.size();
  points = std::move(kept);
  return dropped;
}

}  // namespace slicereuse
