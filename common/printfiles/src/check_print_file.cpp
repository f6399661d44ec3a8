#include "slicereuse/printfiles/check_print_file.h"

#include <omp.h>

#include <algorithm>
#include <vector>

#include "mask_stack.h"
#include "slicereuse/png/mask_png.h"
#include "slicereuse/printability/check_layers.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse {

PrintabilityReport check_print_file(const std::string& path, double pixel_x_mm, double pixel_y_mm,
                                    double layer_height_mm, const std::string& report_csv,
                                    const Progress& progress) {
  static const char* const kPhase = "checking printability";
  if (!report_csv.empty()) check_writable(report_csv);
  LayerChecker checker(pixel_x_mm, pixel_y_mm, layer_height_mm);
  MaskStack stack(path);
  const size_t layers = stack.layers();
  // The file is read on this thread (one handle); a batch is decoded into runs and prepared for the
  // checks on all cores, then checked in order, since the checks stream from the bottom up.
  const size_t batch = size_t(2) * size_t(omp_get_max_threads());
  std::vector<std::vector<uint8_t>> bytes(batch);
  std::vector<PreparedLayer> masks(batch);
  for (size_t first = 0; first < layers; first += batch) {
    report_progress(progress, double(first) / double(layers), kPhase);
    const size_t n = std::min(batch, layers - first);
    for (size_t i = 0; i < n; ++i) stack.read(first + i, bytes[i]);
    parallel_blocks(
        n,
        [&](size_t i) {
          thread_local MaskImage image;
          stack.decode(first + i, bytes[i], image);
          masks[i] = prepare_layer(mask_runs_of(image));
        },
        {}, kPhase);
    for (size_t i = 0; i < n; ++i) {
      try {
        checker.add_layer(std::move(masks[i]));
      } catch (const Error& e) {
        throw Error("'" + stack.layer_name(first + i) + "': " + e.what());
      }
    }
  }
  PrintabilityReport report = checker.finish();
  report_progress(progress, 1, kPhase);
  if (!report_csv.empty()) write_printability_csv(report, report_csv);
  return report;
}

}  // namespace slicereuse
