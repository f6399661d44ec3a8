#include "slicereuse/supports/generate_support_points.h"

#include <cmath>

#include "support_areas.h"
#include "support_points_for_areas.h"

namespace slicereuse {

double SupportPointOptions::support_radius_mm() const { return minimal_distance_mm / std::sqrt(density_relative); }

SupportPoints generate_support_points(const Mesh& mesh, const Slices& slicing, const SupportPointOptions& options,
                                      const SupportPoints* existing, const Progress& progress) {
  check_support_input(mesh, slicing, options);
  const std::vector<LayerAreas> areas = support_areas(slicing, options, sub_progress(progress, 0, 0.5));
  return support_points_for_areas(mesh, slicing, areas, options, existing, sub_progress(progress, 0.5, 1));
}

}  // namespace slicereuse
