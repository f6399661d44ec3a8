#include "slicereuse/printer/print_estimate.h"

#include <algorithm>
#include <cmath>

namespace slicereuse {

double layer_exposure_s(const PrinterProfile& p, size_t k) {
  const size_t bottom = size_t(p.bottom_layers), faded = size_t(p.faded_layers);
  if (k < bottom) return p.bottom_exposure_s;
  if (k - bottom < faded)
    return p.bottom_exposure_s +
           (p.exposure_s - p.bottom_exposure_s) * double(k - bottom + 1) / double(faded + 1);
  return p.exposure_s;
}

double print_seconds(const PrinterProfile& p, size_t layers) {
  double s = double(layers) * p.layer_move_s;
  for (size_t k = 0; k < layers; ++k) s += layer_exposure_s(p, k);
  return s;
}

double print_height_mm(size_t layers, double layer_height_mm) {
  return std::max(150.0, std::ceil(double(layers) * layer_height_mm));
}

}  // namespace slicereuse
