#include "bridge_path.h"

#include <algorithm>
#include <cmath>

#include "pillar_path.h"

namespace slicereuse {

bool bridge_is_clear(const PartColumns& part, const Point3& u, const Point3& l, double radius) {
  const double dx = l[0] - u[0], dy = l[1] - u[1], dz = u[2] - l[2];
  const double run = std::hypot(dx, dy), length = std::hypot(run, dz);
  const double reach = radius + kRimClearanceMm;
  // On a vertical line through the axis the grown cylinder spans reach / cos(slope) above and
  // below it; its ends' sections reach reach / sin(slope) beyond them along the run.
  const double half_height = reach * length / run, beyond = reach * length / dz;
  const double ax = dx / run, ay = dy / run;
  const double span = run + 2 * beyond;
  const int steps = std::max(1, int(std::ceil(span / kBridgeStepMm)));
  for (int i = 0; i <= steps; ++i) {
    const double s = -beyond + span * i / steps;
    const double z_axis = u[2] - dz * s / run;
    const double top = std::min(u[2], z_axis + half_height), bottom = std::max(l[2], z_axis - half_height);
    if (!(top > bottom)) continue;
    for (const double w : {-reach, -reach / 2, 0.0, reach / 2, reach}) {
      const double x = u[0] + ax * s - ay * w, y = u[1] + ay * s + ax * w;
      // A surface within the span, or none and the span inside (entered through a wall).
      if (!std::isnan(part.highest_hit(x, y, top, bottom)) || part.inside(x, y, top)) return false;
    }
  }
  return true;
}

}  // namespace slicereuse
