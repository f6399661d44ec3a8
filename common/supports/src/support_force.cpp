#include "support_force.h"

#include <algorithm>
#include <cmath>

namespace slicereuse {

std::vector<double> inherited_force(const LayerAreas& areas, const std::vector<double>& force_below) {
  std::vector<double> shared(force_below.size(), 0);  // each part below: its overlaps above, summed
  for (const PartLink& l : areas.links) shared[l.below] += l.overlap_mm2;
  std::vector<double> force(areas.parts.size(), 0);
  for (const PartLink& l : areas.links) {
    const double growth = std::min(1.0, 20 * l.below_mm2 / areas.part_mm2[l.part]);
    force[l.part] += force_below[l.below] * growth * l.overlap_mm2 / shared[l.below];
  }
  return force;
}

size_t slope_points_needed(double slope_mm2, double part_mm2, double force, double point_force) {
  if (!(force < part_mm2) || !(slope_mm2 > 0)) return 0;
  return size_t(std::ceil(slope_mm2 * (1 - force / part_mm2) / point_force));
}

}  // namespace slicereuse
