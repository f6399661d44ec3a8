#include "slicereuse/supports/locate_support_points.h"

#include <cmath>
#include <limits>

#include "slicereuse/crossparam/surface_grid.h"
#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {

SupportPoints locate_support_points(const Mesh& mesh, const std::vector<double>& xyz, std::vector<uint8_t> kinds,
                                    double max_distance_mm, const char* noun) {
  const size_t n = xyz.size() / 3;
  if (xyz.size() % 3) throw Error(format("%s positions come 3 numbers a point; %zu is not a multiple of 3", noun, xyz.size()));
  if (kinds.empty()) kinds.assign(n, uint8_t(SupportKind::Overhang));
  if (kinds.size() != n) throw Error(format("%zu %s positions but %zu kinds", n, noun, kinds.size()));
  for (size_t i = 0; i < n; ++i)
    if (kinds[i] > 1) throw Error(format("%s %zu has kind %u; 0 (island) and 1 (overhang) exist", noun, i + 1, kinds[i]));
  for (size_t i = 0; i < xyz.size(); ++i)
    if (!std::isfinite(xyz[i])) throw Error(format("%s %zu has a coordinate that is not a finite number", noun, i / 3 + 1));
  validate_mesh(mesh);
  SupportPoints points;
  points.fingerprint = mesh_fingerprint(mesh);
  points.kind = std::move(kinds);
  points.layer.assign(n, 0);
  points.face.resize(n);
  points.bary.resize(3 * n);
  std::vector<double> distance(n, 0);
  if (n) {
    const SurfaceGrid grid(mesh);
#pragma omp parallel for schedule(dynamic, 256)
    for (long long i = 0; i < (long long)n; ++i) {
      const SurfacePoint s = grid.nearest_on_surface(&xyz[3 * i], nullptr, 0, std::numeric_limits<double>::infinity());
      points.face[i] = s.face;
      distance[i] = s.distance;
      for (int j = 0; j < 3; ++j) points.bary[3 * i + j] = s.bary[j];
    }
  }
  for (size_t i = 0; i < n; ++i)
    if (distance[i] > max_distance_mm)
      throw Error(format("%s %zu at (%g, %g, %g) mm is %g mm from the mesh's surface, farther than the "
                         "%g mm a point may be moved onto it: the points are not this mesh's, or were moved off it",
                         noun, i + 1, xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], distance[i], max_distance_mm));
  place_support_points(points, mesh);
  return points;
}

}  // namespace slicereuse
