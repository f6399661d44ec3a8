#pragma once
// check_print_file: a print file or mask folder (whatever MaskStack reads: PNG folders, .sl1 and
// .sl1s archives, .goo, .ctb and Anycubic files) -> UVtools' printability checks of its masks
// (check_layers.h), with the printer's pixel size (mm, x and y) and the layer height (mm).
// Layers are decoded on all cores a batch at a time and fed to the checker in order; memory is
// that of a batch of images, whatever the number of layers. With report_csv not empty, the
// findings go (atomically) to that CSV file (printability_report.h).
// Throws Error naming the file when it cannot be read or its layers differ in size; Cancelled
// when progress says so.
#include <string>

#include "slicereuse/printability/printability_report.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

PrintabilityReport check_print_file(const std::string& path, double pixel_x_mm, double pixel_y_mm,
                                    double layer_height_mm, const std::string& report_csv,
                                    const Progress& progress = {});

}  // namespace slicereuse
