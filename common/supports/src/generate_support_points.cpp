#include "slicereuse/supports/generate_support_points.h"

#include <cmath>

#include "support_areas.h"
#include "support_points_for_areas.h"

namespace slicereuse {

double SupportPointOptions::held_area_mm2() const { return 10 / density_relative; }

double SupportPointOptions::support_radius_mm() const { return std::sqrt(held_area_mm2() / M_PI); }

double SupportPointOptions::point_reach_mm() const { return head_reach_mm + head_front_diameter_mm / 2 - 0.05; }

double SupportPointOptions::self_supporting_mm(double thickness) const {
  return thickness / std::tan(critical_angle_deg * M_PI / 180);
}

SupportPoints generate_support_points(const Mesh& mesh, const Slices& slicing, const SupportPointOptions& options,
                                      const SupportPoints* existing, const Progress& progress) {
  check_support_input(mesh, slicing, options);
  const std::vector<LayerAreas> areas = support_areas(slicing, options, sub_progress(progress, 0, 0.5));
  return support_points_for_areas(mesh, slicing, areas, options, existing, sub_progress(progress, 0.5, 1));
}

}  // namespace slicereuse
