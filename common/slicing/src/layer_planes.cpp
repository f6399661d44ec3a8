#include "slicereuse/slicing/layer_planes.h"

#include <algorithm>
#include <cmath>

#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {

std::vector<double> layer_planes(double z_start, double thickness, double zmax) {
  if (!(thickness > 0) || !std::isfinite(thickness))
    throw Error(format("layer thickness must be a positive number, got %g", thickness));
  if (!std::isfinite(z_start) || !std::isfinite(zmax))
    throw Error("slicing range is not finite");
  if (!(z_start < zmax))
    throw Error(format("no layers: z_start %g mm is not below the top of the mesh at z = %g mm", z_start, zmax));
  const double estimate = std::ceil((zmax - z_start) / thickness);
  if (!(estimate <= double(kMaxLayers)))
    throw Error(format("a layer thickness of %g mm gives %.4g layers over the part's %g mm, more than the "
                       "limit of %zu (check the units: thickness is in mm)",
                       thickness, estimate, zmax - z_start, kMaxLayers));
  size_t n = size_t(estimate);
  // The rounded quotient can be one off either way; the definition is the slab bottom test.
  while (n > 0 && z_start + double(n - 1) * thickness >= zmax) --n;
  while (z_start + double(n) * thickness < zmax) ++n;
  std::vector<double> z(n);
  for (size_t k = 0; k < n; ++k) z[k] = layer_plane(z_start, thickness, double(k));
  return z;
}

size_t first_plane_above(const std::vector<double>& layer_z, double z) {
  const size_t n = layer_z.size();
  if (n == 0) return 0;
  // Evenly spaced planes (the usual case): an arithmetic guess, checked against the stored
  // planes; anything else (a sparse list of planes, rounding at the ends) by binary search.
  if (n > 1) {
    const double g = std::floor((z - layer_z[0]) / (layer_z[1] - layer_z[0])) + 1;
    if (g >= 0 && g <= double(n)) {
      const size_t k = size_t(g);
      if ((k == 0 || layer_z[k - 1] <= z) && (k == n || layer_z[k] > z)) return k;
    }
  }
  return size_t(std::upper_bound(layer_z.begin(), layer_z.end(), z) - layer_z.begin());
}

}  // namespace slicereuse
