#include "slicereuse/printfiles/check_stack.h"

#include <omp.h>

#include <algorithm>

#include "slicereuse/png/mask_png.h"
#include "slicereuse/printability/check_layers.h"
#include "slicereuse/raster/rasterize_layer.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse {

PrintabilityReport check_stack(const std::vector<SlicePart>& parts, size_t layers, double thickness,
                               const PrinterProfile& profile, const Progress& progress) {
  static const char* const kPhase = "checking printability";
  validate_printer_profile(profile);
  if (layers == 0) throw Error("printability check: the stack has no layers");
  for (const SlicePart& p : parts) validate_slices(p.slices);
  const MaskImageLayout layout = mask_image_layout(profile);
  LayerChecker checker(layout.column_um / 1000, layout.row_um / 1000, thickness);
  // A batch is drawn and prepared for the checks on all cores, then checked in order: the checks
  // stream from the bottom up.
  const size_t batch = size_t(2) * size_t(omp_get_max_threads());
  std::vector<PreparedLayer> masks(batch);
  for (size_t first = 0; first < layers; first += batch) {
    report_progress(progress, double(first) / double(layers), kPhase);
    const size_t n = std::min(batch, layers - first);
    parallel_blocks(
        n,
        [&](size_t i) {
          const size_t k = first + i;
          std::vector<LayerPart> view;
          for (const SlicePart& p : parts)
            if (k >= p.first && k - p.first < p.slices.layers()) view.push_back({&p.slices, k - p.first});
          const LayerView layer(view.data(), view.size());
          MaskRuns mask;
          if (profile.antialiasing)
            rasterize_layer_antialiased_runs(layer, profile, mask);
          else
            rasterize_layer_runs(layer, profile, mask);
          masks[i] = prepare_layer(std::move(mask));
        },
        {}, kPhase);
    for (size_t i = 0; i < n; ++i) checker.add_layer(std::move(masks[i]));
  }
  report_progress(progress, 1, kPhase);
  return checker.finish();
}

}  // namespace slicereuse
