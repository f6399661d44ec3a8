#include "slicereuse/plates/faded_elephant_foot.h"

#include <algorithm>

#include "slicereuse/regions/elephant_foot.h"
#include "slicereuse/slicing/layer_planes.h"

namespace slicereuse {

double faded_elephant_foot_mm(const PrinterProfile& p, size_t k, size_t layers) {
  if (!(p.elephant_foot_mm > 0)) return 0;
  const size_t faded = std::min(layers, size_t(std::max(p.faded_layers, 0)));
  if (k >= std::max<size_t>(faded, 1)) return 0;
  const size_t steps = std::max<size_t>(1, faded > 0 ? faded - 1 : 0);
  return double(steps - std::min(k, steps)) * p.elephant_foot_mm / double(steps);
}

void compensate_faded_layers(std::vector<SlicePart>& parts, const PrinterProfile& profile, const StackLayers& stack) {
  // The layers that shrink are the stack's first ones: those of the range make a prefix of it.
  size_t shrunk = 0;
  while (shrunk < stack.count && faded_elephant_foot_mm(profile, stack.begin + shrunk, stack.layers) > 0) ++shrunk;
  if (shrunk == 0) return;
  std::vector<SlicePart> out(shrunk);
  for (size_t j = 0; j < shrunk; ++j) {
    std::vector<LayerPart> layer;
    for (const SlicePart& p : parts)
      if (p.first <= j && j < p.first + p.slices.layers()) layer.push_back({&p.slices, j - p.first});
    const size_t k = stack.begin + j;
    compensate_elephant_foot(LayerView(layer.data(), layer.size()), layer_plane(stack.bottom, stack.thickness, double(k)),
                             faded_elephant_foot_mm(profile, k, stack.layers), profile.elephant_foot_min_width_mm,
                             out[j].slices);
    out[j].slices.z_start = stack.bottom + double(k) * stack.thickness;
    out[j].slices.thickness = stack.thickness;
    out[j].first = j;
  }
  for (SlicePart& p : parts) {
    if (p.first >= shrunk) {
      out.push_back(std::move(p));
    } else if (p.first + p.slices.layers() > shrunk) {
      out.emplace_back();
      layers_into(p.slices, shrunk - p.first, p.slices.layers(), out.back().slices, true);
      out.back().first = shrunk;
    }
  }
  parts = std::move(out);
}

}  // namespace slicereuse
