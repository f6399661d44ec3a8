#pragma once
// side_label: where a member's label goes on one of its sides (#36), as the jobs cut it
// (plate_job.h, options.label.side) and Add Labels shows it.
//
// The side's frame: the member seen from outside that side (its own, before its placement turned
// it by turn_deg about z), u to the right along the side, z up, w into the part; the letters
// stand upright in the vertical plane facing out, readable from there (not mirrored).
// place_side_label: the member's layers (Slices from its own layer 0, all of them), their
// thickness, its turn, the text, its name (for the reason) and the options (side not Base) ->
// the label's box (label_box_mm: its height, then its width from the text) centred on the
// member's extent in u, at the largest height, from options.height_mm down by tenths to
// options.min_height_mm, and of the box's bottoms on the layers' boundaries (at least
// options.margin_mm above the member's bottom and below its top) the nearest to the member's
// middle height, at which on every layer whose plane the box spans, across the box's width and
// options.margin_mm either side: every u has the part, the part's outermost point at each u lies
// within half the depth of the outermost of all of them (the face's plane, p: a flat face), and
// the part is solid from the innermost of those points to the depth and kLabelRoofMm beyond (no
// letter, which lies within the depth of the face, cuts through). Exact on the layers' regions
// (Clipper; the face's points from the regions' edges): no sampling.
// Placed: per engraved layer (its own layers [first, first + cuts.size())), the letters' section
// at its plane (the horizontal line through the placed letters, label_region.h, cut by Clipper)
// as bands across the side from outside the part to depth and half the depth beyond p, in plate
// coordinates: engrave_part (engrave_labels.h) cuts what of them lies within the depth of the
// layer's outside. Not placed (cuts empty), with `why` saying so in words, when no height and
// place fits. Deterministic: quarter turns are exact, and the same layers give the same bands.
// Throws Error as label_region does (a text the font cannot print, heights that are not positive).
// The second form takes the layers as loops filled by the nonzero rule (their contours as
// sliced, layers_paths, or their regions, layer_region.h) and their mid-planes
// (Slices::layer_z), as a hollowed member's job has taken them for its cavity.
// side_name: "front", "back", "left" or "right" (and "base").
#include <array>
#include <clipper.hpp>
#include <string>
#include <vector>

#include "slicereuse/plates/plate_job.h"
#include "slicereuse/slicing/slices.h"

namespace slicereuse {

struct SideLabel {
  size_t first = 0;                     // its own layer of cuts[0]
  std::vector<ClipperLib::Paths> cuts;  // empty: not placed
  double height_mm = 0;
  double x_mm = 0, y_mm = 0, z_mm = 0;  // the centre of its box on the face's plane (plate)
  std::vector<std::vector<std::array<double, 3>>> outline;  // the letters' loops on the face (plate)
  std::string why;                      // not placed: why
};

const char* side_name(LabelSide side);
SideLabel place_side_label(const Slices& layers, double thickness_mm, double turn_deg, const std::string& text,
                           const std::string& name, const LabelOptions& o);
SideLabel place_side_label(std::vector<ClipperLib::Paths> regions, const std::vector<double>& layer_z,
                           double thickness_mm, double turn_deg, const std::string& text, const std::string& name,
                           const LabelOptions& o);

}  // namespace slicereuse
