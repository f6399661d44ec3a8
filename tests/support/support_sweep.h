#pragma once
// support_sweep: the supports' property tests over many parts (issue #35, item 5), shared by the
// small sweep in the unit tests (test_support_sweep.cpp) and the large one (tests/support_sweep.cpp,
// driven by bench/support_sweep.py, which adds PrusaSlicer's resin).
//
// A SweepPart is a family member (family.h) tilted about x (FamilyTilt), centred on the display,
// and the support point options it is supported with. random_sweep_part(seed, index) draws one:
// any shape, family seed 1..1000, member 1..3, tilt 0..90 degrees, critical angle 10..80
// degrees, density 50..300 %, height 6..12 mm, 6000 faces; the same on every platform.
//
// check_sweep_part: the part's supports generated on it (make_member_supports), the print file
// written by the product's plate job (export_plate, the SL1S preset and its anti-aliased masks,
// the display cropped to the part and 5 mm around, layers of `thickness`) into folder, and
// checked:
//   island, resin trap: UVtools' findings in the print file (check_print_file.h);
//   far reach: a lit pixel more than 1 mm from a lit pixel of the layer below (support_checks.h);
//   foot in air: a foot whose tip is off the part, or a piece of the supports' sections resting
//     on nothing (support_tree_checks.h);
//   pillar into part: part and supports overlapping outside the head zones (more than 1e-9 mm²).
// With resin, the part is also printed alone (no supports, no elephant foot) so that the
// supports' resin is the difference of the two stacks' lit volumes (pixels >= 128: the binary
// threshold, as support_checks.h). A step that throws is the
// finding `error` (its message).
// failed_properties: the names of the properties a part fails ("error" when it threw).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse::test {

struct SweepPart {
  std::string shape = "sphere";
  uint64_t family_seed = 1;
  int member = 1;
  double tilt_deg = 0;
  double critical_angle_deg = 45;
  double density = 1;  // support_points_density_relative / 100
  double height_mm = 8;
  size_t faces = 6000;
};

SweepPart random_sweep_part(uint64_t seed, size_t index);
// The part's parameters, as support_sweep's --part takes them back: "shape family_seed member
// tilt critical_angle density height faces".
std::string sweep_part_text(const SweepPart& part);
// Throws Error in words when text is not such a line.
SweepPart sweep_part_from_text(const std::string& text);
Mesh make_sweep_part(const SweepPart& part);

struct SweepFindings {
  size_t layers = 0, points = 0, pillars = 0, on_part = 0, up_facing = 0;
  int display_px = 0;  // the cropped display's side, in pixels
  size_t islands = 0, resin_traps = 0;
  double far_mm = 0;
  size_t far_layer = 0;
  size_t feet = 0, feet_in_air = 0, support_islands = 0;
  size_t support_island_layer = 0;  // the first, counted from the tree's ground (when support_islands > 0)
  double foot_off_mm = 0;
  double outside_zones_mm2 = 0;
  double outside_zones_xyz[3] = {0, 0, 0};  // where, in the part's frame
  double supported_mm3 = 0, part_mm3 = 0;  // lit volumes: part and supports, part alone (with resin)
  double support_mm3() const { return supported_mm3 - part_mm3; }
  double seconds = 0;
  std::string error;
};

SweepFindings check_sweep_part(const SweepPart& part, double thickness, const std::string& folder, bool resin);
std::vector<std::string> failed_properties(const SweepFindings& findings);
// The properties in the order failed_properties names them.
const std::vector<std::string>& sweep_properties();

}  // namespace slicereuse::test
