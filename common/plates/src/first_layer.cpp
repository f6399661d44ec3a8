#include "slicereuse/plates/first_layer.h"

#include "slicereuse/regions/elephant_foot.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {

void compensate_first_layer(std::vector<SlicePart>& parts, const std::vector<size_t>& owners,
                            const PrinterProfile& profile, double z0, double bottom0, double thickness) {
  if (!(profile.elephant_foot_mm > 0)) return;
  if (!owners.empty() && owners.size() != parts.size())
    throw Error(format("internal error: %zu owners for %zu parts of the first layer", owners.size(), parts.size()));
  auto owner = [&](size_t i) { return owners.empty() ? size_t(0) : owners[i]; };
  std::vector<SlicePart> out;
  std::vector<bool> done(parts.size(), false);
  for (size_t i = 0; i < parts.size(); ++i) {
    if (done[i] || parts[i].first != 0 || parts[i].slices.layers() == 0) continue;
    std::vector<LayerPart> together;
    for (size_t j = i; j < parts.size(); ++j)
      if (!done[j] && owner(j) == owner(i) && parts[j].first == 0 && parts[j].slices.layers() > 0) {
        together.push_back({&parts[j].slices, 0});
        done[j] = true;
      }
    out.emplace_back();
    compensate_elephant_foot(LayerView(together.data(), together.size()), z0, profile.elephant_foot_mm,
                             profile.elephant_foot_min_width_mm, out.back().slices);
    out.back().slices.z_start = bottom0;
    out.back().slices.thickness = thickness;
  }
  for (SlicePart& p : parts) {
    if (p.first > 0) {
      out.push_back(std::move(p));
    } else if (p.slices.layers() > 1) {
      out.emplace_back();
      layers_into(p.slices, 1, p.slices.layers(), out.back().slices, true);
      out.back().first = 1;
    }
  }
  parts = std::move(out);
}

}  // namespace slicereuse
