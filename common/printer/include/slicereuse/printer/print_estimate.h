#pragma once
// What a print file says about the job besides the images, the same in every format that says
// it (.sl1's config.ini and prusaslicer.ini, .goo's header and layer definitions):
//   layer_exposure_s(p, k)         layer k's exposure: the first p.bottom_layers at
//                                  p.bottom_exposure_s, the next p.faded_layers stepping down
//                                  linearly towards p.exposure_s, the rest at p.exposure_s
//   print_seconds(p, layers)       the printer's estimate: every layer's exposure plus one
//                                  p.layer_move_s (tilt, or lift and retract) per layer
//   print_height_mm(layers, h)     the machine height a file claims: the stack's height, at
//                                  least 150 mm (what any resin printer reaches)
#include <cstddef>

#include "slicereuse/printer/printer_profile.h"

namespace slicereuse {

double layer_exposure_s(const PrinterProfile& p, size_t k);
double print_seconds(const PrinterProfile& p, size_t layers);
double print_height_mm(size_t layers, double layer_height_mm);

}  // namespace slicereuse
