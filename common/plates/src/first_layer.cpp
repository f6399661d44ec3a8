#include "slicereuse/plates/first_layer.h"

#include "slicereuse/regions/elephant_foot.h"

namespace slicereuse {

void compensate_first_layer(std::vector<SlicePart>& parts, const PrinterProfile& profile, double z0, double bottom0,
                            double thickness) {
  if (!(profile.elephant_foot_mm > 0)) return;
  std::vector<LayerPart> first;
  for (const SlicePart& p : parts)
    if (p.first == 0 && p.slices.layers() > 0) first.push_back({&p.slices, 0});
  std::vector<SlicePart> out(1);
  compensate_elephant_foot(LayerView(first.data(), first.size()), z0, profile.elephant_foot_mm,
                           profile.elephant_foot_min_width_mm, out[0].slices);
  out[0].slices.z_start = bottom0;
  out[0].slices.thickness = thickness;
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
