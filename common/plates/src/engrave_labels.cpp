#include "engrave_labels.h"

#include <algorithm>
#include <cmath>

#include "slicereuse/regions/clip_regions.h"
#include "slicereuse/regions/layer_region.h"

namespace slicereuse {

size_t engraved_layers(double depth_mm, double thickness_mm, size_t member_layers) {
  // The layers whose bottom lies above the base by less than the depth (a 1e-9 mm tolerance:
  // 3 mm of 0.05 mm layers is 60 layers, not 61).
  return std::min(member_layers, size_t(std::ceil(depth_mm / thickness_mm - 1e-9)));
}

Engraving label_engraving(const Slices& first_layers, const std::string& text, const LabelOptions& o) {
  Engraving e;
  if (first_layers.layers() == 0) return e;
  ClipperLib::Paths face = layer_region(LayerView(first_layers, 0));
  for (size_t k = 1; k < first_layers.layers(); ++k)
    face = clip_regions(face, layer_region(LayerView(first_layers, k)), ClipperLib::ctIntersection);
  e.placement = place_label(face, text, o.height_mm, o.min_height_mm, o.margin_mm, true);
  if (e.placement.placed) e.layers = first_layers.layers();
  return e;
}

void engrave_part(SlicePart& part, size_t own_first, const Engraving& e) {
  if (own_first >= e.layers || part.slices.layers() == 0) return;
  const Slices& s = part.slices;
  const size_t cut = std::min(e.layers - own_first, s.layers());
  Slices made, layer;
  made.z_start = s.z_start;
  made.thickness = s.thickness;
  for (size_t k = 0; k < cut; ++k) {
    region_into_layer(clip_regions(layer_region(LayerView(s, k)), e.placement.region, ClipperLib::ctDifference), s.layer_z[k],
                      layer);
    append_layers(layer, 0, 1, made);
  }
  append_layers(s, cut, s.layers(), made);
  made.fingerprint = s.fingerprint;
  part.slices = std::move(made);
}

}  // namespace slicereuse
