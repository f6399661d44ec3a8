#pragma once
// PrintabilityReport: what check_layers.h finds in a stack of masks, in UVtools' terms.
//
// Each Finding: its kind, the layers it spans (first..last, both included), its bounding box in
// pixels (x0, y0 the top-left pixel, x1, y1 one past the bottom-right; x from the image's left,
// y from its top row), the box's centre and size in mm (pixels times the pixel size; z from
// layer * layer height, the centre halfway between the bottom of the first layer and the top of
// the last), its area in mm² (islands and overhangs: of the layer where found) or its volume in
// mm³ (resin traps and suction cups: pixels times pixel area times layer height); touching
// bounds has the area of its pixels at or above the brightness, summed over its layers.
// write_printability_csv: the report -> a CSV file (atomically), one row per finding
// (docs/formats.md, "Printability report"); throws Error naming the path on failure.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace slicereuse {

enum class FindingKind { Island, Overhang, ResinTrap, SuctionCup, TouchingBounds };
constexpr size_t kFindingKinds = 5;

// "island", "overhang", "resin_trap", "suction_cup", "touching_bounds".
const char* finding_kind_name(FindingKind kind);

// Whether a finding of this kind makes a print fail (an island, a resin trap, a suction cup);
// overhangs and parts near the display's edges are warnings.
inline bool blocks_printing(FindingKind kind) {
  return kind == FindingKind::Island || kind == FindingKind::ResinTrap || kind == FindingKind::SuctionCup;
}

struct Finding {
  FindingKind kind = FindingKind::Island;
  size_t first_layer = 0, last_layer = 0;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;   // pixels, [x0, x1) x [y0, y1)
  double center_mm[3] = {0, 0, 0};
  double size_mm[3] = {0, 0, 0};
  double area_mm2 = 0;    // islands, overhangs, touching bounds
  double volume_mm3 = 0;  // resin traps, suction cups
};

struct PrintabilityReport {
  size_t layers = 0;
  std::vector<Finding> findings;  // by kind, then first layer
  std::array<size_t, kFindingKinds> counts{};  // per FindingKind

  size_t count(FindingKind kind) const { return counts[size_t(kind)]; }
  double trapped_mm3() const;  // the resin traps' volumes summed
  bool blocks_printing() const;  // holds a finding that makes a print fail
};

void write_printability_csv(const PrintabilityReport& report, const std::string& path);

}  // namespace slicereuse
