#include "engrave_labels.h"

#include <algorithm>

#include "slicereuse/regions/clip_regions.h"
#include "slicereuse/regions/layer_region.h"

namespace slicereuse {
namespace {

// region less what of cut lies within skin_mm of region's outer loops. Only the outside near the
// cut is eroded: what lies farther from it than the skin cannot matter (a millimetre more to spare).
ClipperLib::Paths cut_skin(const ClipperLib::Paths& region, const ClipperLib::Paths& cut, double skin_mm) {
  ClipperLib::Paths filled;
  for (const ClipperLib::Path& loop : region)
    if (ClipperLib::Orientation(loop)) filled.push_back(loop);
  ClipperLib::Clipper bounds;
  bounds.AddPaths(cut, ClipperLib::ptSubject, true);
  const ClipperLib::IntRect b = bounds.GetBounds();
  const ClipperLib::cInt e = region_units(skin_mm + 1);
  const ClipperLib::Path near{{b.left - e, b.top - e}, {b.right + e, b.top - e}, {b.right + e, b.bottom + e},
                              {b.left - e, b.bottom + e}};
  ClipperLib::ClipperOffset offset(2, double(region_units(0.002)));
  offset.AddPaths(clip_regions(filled, {near}, ClipperLib::ctIntersection), ClipperLib::jtRound,
                  ClipperLib::etClosedPolygon);
  ClipperLib::Paths deep;
  offset.Execute(deep, -double(region_units(skin_mm)));
  return clip_regions(region, clip_regions(cut, deep, ClipperLib::ctDifference), ClipperLib::ctDifference);
}

}  // namespace

void engrave_part(SlicePart& part, size_t own_first, const LabelCut& label) {
  const Slices& s = part.slices;
  const size_t a = std::max(own_first, label.first), b = std::min(own_first + s.layers(), label.first + label.layers);
  if (a >= b) return;
  Slices made, layer;
  made.z_start = s.z_start;
  made.thickness = s.thickness;
  append_layers(s, 0, a - own_first, made);
  for (size_t j = a; j < b; ++j) {
    const size_t k = j - own_first;
    const ClipperLib::Paths& cut = label.regions[label.regions.size() == 1 ? 0 : j - label.first];
    if (cut.empty()) {
      append_layers(s, k, k + 1, made);
      continue;
    }
    const ClipperLib::Paths region = layer_region(LayerView(s, k));
    region_into_layer(label.skin_mm > 0 ? cut_skin(region, cut, label.skin_mm)
                                        : clip_regions(region, cut, ClipperLib::ctDifference),
                      s.layer_z[k], layer);
    append_layers(layer, 0, 1, made);
  }
  append_layers(s, b - own_first, s.layers(), made);
  made.fingerprint = s.fingerprint;
  part.slices = std::move(made);
}

}  // namespace slicereuse
