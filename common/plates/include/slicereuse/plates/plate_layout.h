#pragma once
// plate_layout: a picture of a plate seen from above, written beside its print file so that a
// person sees what is on it before printing.
//
// write_plate_layout(path, placed, names, platform, mm_per_pixel): an 8-bit grey PNG of the
// platform (platform.x0 at the left, platform.y1 at the top row; pixel size mm_per_pixel):
// white, a black frame at the platform's edge, each placed member's footprint (footprint.h, on
// the image's pixels) light grey with its outline black, and its name in black capitals of a
// built-in 3 x 5 pixel font (letters, digits, "_", "-", "."; other characters as "?"), scaled
// with the image, centred on the footprint. Atomic. Throws Error for a pixel size that is not
// positive, an image larger than 20000 pixels a side, or names and members that differ in count.
#include <string>
#include <vector>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/plates/arrange_plates.h"

namespace slicereuse {

void write_plate_layout(const std::string& path, const std::vector<Mesh>& placed, const std::vector<std::string>& names,
                        const Platform& platform, double mm_per_pixel = 0.1);

}  // namespace slicereuse
