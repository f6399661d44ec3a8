#pragma once
// drop_points_in: support points taken out where a head would collide with something the part
// must keep clear, such as a drain hole (#36). PrusaSlicer generates its support points on the
// drilled mesh, so none lies on a hole's mouth, and a head it cannot place is dropped; here the
// points are found on the undrilled part, and those whose head would reach into a hole are
// dropped the same way.
// Input: the points, cylinders (an axis segment and a radius, mm) and the head's radius (mm).
// Output: the points kept, in their order; returns how many were dropped: those nearer a
// cylinder's axis segment than its radius plus the head's.
#include <array>
#include <cstddef>
#include <vector>

#include "slicereuse/supports/support_points.h"

namespace slicereuse {

struct KeepOutCylinder {
  std::array<double, 3> from{}, to{};
  double radius_mm = 0;
};

size_t drop_points_in(SupportPoints& points, const std::vector<KeepOutCylinder>& cylinders, double head_radius_mm);

}  // namespace slicereuse
