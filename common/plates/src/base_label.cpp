#include "slicereuse/plates/base_label.h"

#include <algorithm>
#include <cmath>

#include "slicereuse/regions/clip_regions.h"
#include "slicereuse/regions/label_region.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/util/format.h"

namespace slicereuse {

size_t engraved_layers(double depth_mm, double thickness_mm, size_t member_layers) {
  // A 1e-9 tolerance: 3 mm of 0.05 mm layers is 60 layers, not 61.
  return std::min(member_layers, size_t(std::ceil(depth_mm / thickness_mm - 1e-9)));
}

BaseLabel place_base_label(const Slices& first_layers, double member_height_mm, const std::string& text,
                           const std::string& name, const LabelOptions& o) {
  BaseLabel b;
  // A label cut through the part, or nearly, would leave holes or a skin.
  if (member_height_mm < o.depth_mm + kLabelRoofMm) {
    label_box_mm(text, o.height_mm);  // a text the font cannot print is refused all the same
    b.why = format("the label '%s' does not fit %s: %s is %.3g mm tall, and a label %.3g mm deep needs %.3g mm",
                   text.c_str(), name.c_str(), name.c_str(), member_height_mm, o.depth_mm, o.depth_mm + kLabelRoofMm);
    return b;
  }
  ClipperLib::Paths face;
  for (size_t k = 0; k < first_layers.layers(); ++k) {
    const ClipperLib::Paths region = layer_region(LayerView(first_layers, k));
    face = k == 0 ? region : clip_regions(face, region, ClipperLib::ctIntersection);
  }
  b.placement = place_label(face, text, o.height_mm, o.min_height_mm, o.margin_mm, true);
  if (b.placement.placed) {
    b.layers = first_layers.layers();
    return b;
  }
  const std::array<double, 2> least = label_box_mm(text, o.min_height_mm);
  b.why = format("the label '%s' does not fit on the base of %s: even %.3g mm high it is %.3g mm long, and the base's "
                 "first %.3g mm, %.3g mm inside their edges, hold it at no place and turn",
                 text.c_str(), name.c_str(), o.min_height_mm, least[0], o.depth_mm, o.margin_mm);
  return b;
}

}  // namespace slicereuse
