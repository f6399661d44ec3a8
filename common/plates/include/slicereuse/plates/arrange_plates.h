#pragma once
// arrange_plates: places family members on build plates without overlap, as many per plate as
// fit, so that a lab prints a plate of members at once.
//
// Input: the members' meshes and names, the platform (the printer's display in model
// coordinates, printer_platform), and options: the spacing kept between members' footprints and
// from the platform's edges, the footprint cell size, and the rotation step.
// Method: each member's footprint (footprint.h: the cells its projection touches, not a bounding
// box) is tried at every rotation k * rotation_step_deg about z; members are placed largest
// footprint first, each on the first plate where it fits, at the bottom-left-most free
// position (lowest top edge, then lowest right edge, over all rotations) on the plate's grid of
// cells, whose first cell starts spacing_mm inside the platform's corner. A member is free at a
// position when no cell of its footprint dilated by the spacing holds a cell of a member already
// there, so the members' triangles end up >= spacing_mm apart and >= spacing_mm inside the
// platform's edges (within the footprints' 1e-6 mm slack). A member that fits no plate starts a
// new one.
// Output: per member its placement (placement.h) and plate; per plate its members in placing
// order and the area used: the members' footprint cells' area over the platform's area.
// Throws Error naming the member, its size and the usable platform's size when a member fits an
// empty plate at no rotation, naming the member when it is no valid mesh (validate_mesh), and for
// bad options (naming the option) or a platform narrower
// than twice the spacing.
#include <string>
#include <vector>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/plates/placement.h"
#include "slicereuse/printer/printer_profile.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

// A rectangle of the build plate in model coordinates, mm.
struct Platform {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// The area a profile's display covers, in model coordinates (printer_profile.h: the model's
// origin at the display centre shifted by the offset).
Platform printer_platform(const PrinterProfile& profile);

struct ArrangeOptions {
  double spacing_mm = 2;
  double cell_mm = 0.25;
  double rotation_step_deg = 15;  // 360: no rotation
};

struct Arrangement {
  std::vector<Placement> placement;          // per member
  std::vector<size_t> plate;                 // per member, from 0
  std::vector<std::vector<size_t>> members;  // per plate, in placing order
  std::vector<double> area_used;             // per plate, 0..1
};

Arrangement arrange_plates(const std::vector<const Mesh*>& members, const std::vector<std::string>& names,
                           const Platform& platform, const ArrangeOptions& options, const Progress& progress = {});

}  // namespace slicereuse
