#include "lift_fields.h"

#include <algorithm>

namespace slicereuse {

LayerMoves layer_moves(const PrinterProfile& p, bool bottom) {
  return bottom ? LayerMoves{p.bottom_lift_mm, p.bottom_lift_speed_mm_min, p.bottom_retract_speed_mm_min,
                             p.bottom_light_off_s}
                : LayerMoves{p.lift_mm, p.lift_speed_mm_min, p.retract_speed_mm_min, p.light_off_s};
}

double wait_after_retract_s(const PrinterProfile& p, const LayerMoves& m) {
  const double moves_s = 60 * (m.lift_mm / m.lift_speed + m.lift_mm / m.retract_speed);
  return std::max(m.light_off_s, p.layer_move_s - moves_s);
}

unsigned antialiasing_level(const PrinterProfile& p) { return p.antialiasing && p.gamma > 0 ? 8 : 1; }

}  // namespace slicereuse
