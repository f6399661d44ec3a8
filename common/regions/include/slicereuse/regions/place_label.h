#pragma once
// place_label: where a label (label_region.h) fits on a face of a part, largest first.
//
// In: the face, a region (Clipper polygons, kRegionScale units: for a label on a part's base, the
// region all the engraved layers share), the text, the preferred and the least height in mm,
// the margin in mm to keep from the face's edges, and whether the label is mirrored.
// Out: the placement with the greatest height, from height_mm down by tenths of it to no less
// than min_height_mm, at which the label's box (label_box_mm, holding its strokes), turned by one
// of 12 angles (0 first, then the nearest to 0, by 15 degrees) about a centre, lies inside the
// face shrunk by the margin (none of the face's holes among the letters);
// the centres tried are those of a grid over the face (a 250th of its larger side, 0.1 mm at
// least) farthest from its edges first, then nearest the middle of its box (a fit closer than a
// grid step either way may be missed: the next height then fits). The region is the
// label placed (kRegionScale units).
// Not placed when no height fits. Deterministic: the same face and text place the same way on
// every machine. Throws Error as label_region does, or for a least height above the height.
#include <clipper.hpp>
#include <string>

namespace slicereuse {

struct LabelPlacement {
  bool placed = false;
  double x_mm = 0, y_mm = 0, angle_deg = 0, height_mm = 0;
  ClipperLib::Paths region;
};

LabelPlacement place_label(const ClipperLib::Paths& face, const std::string& text, double height_mm,
                           double min_height_mm, double margin_mm, bool mirrored);

}  // namespace slicereuse
