#include "engrave_labels.h"

#include <algorithm>

#include "slicereuse/regions/clip_regions.h"
#include "slicereuse/regions/layer_region.h"

namespace slicereuse {

void engrave_part(SlicePart& part, size_t own_first, const BaseLabel& label) {
  if (own_first >= label.layers || part.slices.layers() == 0) return;
  const Slices& s = part.slices;
  const size_t cut = std::min(label.layers - own_first, s.layers());
  Slices made, layer;
  made.z_start = s.z_start;
  made.thickness = s.thickness;
  for (size_t k = 0; k < cut; ++k) {
    region_into_layer(clip_regions(layer_region(LayerView(s, k)), label.placement.region, ClipperLib::ctDifference),
                      s.layer_z[k], layer);
    append_layers(layer, 0, 1, made);
  }
  append_layers(s, cut, s.layers(), made);
  made.fingerprint = s.fingerprint;
  part.slices = std::move(made);
}

}  // namespace slicereuse
