#pragma once
// base_label: where a member's label goes on its base (#36), as the jobs cut it (plate_job.h,
// options.labels) and Add Labels shows it.
//
// engraved_layers: a label depth_mm deep cuts a member's own layers [0, engraved_layers(...)):
// those whose bottom lies less than the depth above its base (3 mm of 0.05 mm layers: 60).
// place_base_label: the member's first layers (Slices from its own layer 0: engraved_layers of
// them), its height in mm, the text, the member's name (for the reason) and the options -> the
// label placed (place_label.h, mirrored: it is read from below) on the region those layers
// share, inside options.margin_mm of its edges, as large as fits from options.height_mm down to
// options.min_height_mm; not placed (layers 0), with `why` saying so in words, when the member
// stands less than 1 mm above the label's depth (the letters would cut through it) or the
// label fits at no height, place and turn. Throws Error as place_label does (a text the font
// cannot print, heights that are not positive).
#include <string>

#include "slicereuse/plates/plate_job.h"
#include "slicereuse/regions/place_label.h"
#include "slicereuse/slicing/slices.h"

namespace slicereuse {

constexpr double kLabelRoofMm = 1;  // of the part behind a label's letters, at least

struct BaseLabel {
  size_t layers = 0;  // its own layers [0, layers) are cut; 0: not placed
  LabelPlacement placement;
  std::string why;    // not placed: why
};

size_t engraved_layers(double depth_mm, double thickness_mm, size_t member_layers);
BaseLabel place_base_label(const Slices& first_layers, double member_height_mm, const std::string& text,
                           const std::string& name, const LabelOptions& o);

}  // namespace slicereuse
