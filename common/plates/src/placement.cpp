#include "slicereuse/plates/placement.h"

#include <cmath>

namespace slicereuse {

Turn turn_of(double theta_deg) {
  // Exact quarter turns: cos(pi/2) in double is 6e-17, not 0, and would move a point by that
  // much times its distance from the origin for no reason.
  const double q = theta_deg / 90;
  if (q == std::floor(q)) {
    static constexpr Turn kQuarter[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    return kQuarter[((long long)q % 4 + 4) % 4];
  }
  const double r = theta_deg * (M_PI / 180);
  return {std::cos(r), std::sin(r)};
}

Mesh place_mesh(const Mesh& mesh, const Placement& placement) {
  const Turn turn = turn_of(placement.theta_deg);
  Mesh out;
  out.F = mesh.F;
  out.V.resize(mesh.V.size());
  for (size_t i = 0; i < mesh.vertices(); ++i) {
    double x, y;
    turn.apply(mesh.V[3 * i], mesh.V[3 * i + 1], x, y);
    out.V[3 * i] = x + placement.tx_mm;
    out.V[3 * i + 1] = y + placement.ty_mm;
    out.V[3 * i + 2] = mesh.V[3 * i + 2];
  }
  return out;
}

}  // namespace slicereuse
