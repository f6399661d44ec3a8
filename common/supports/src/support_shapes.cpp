#include "support_shapes.h"

#include <cmath>

namespace slicereuse {

Outline circle_outline(double x, double y, double r) {
  Outline out(kSupportSides);
  for (int i = 0; i < kSupportSides; ++i) {
    const double a = 2 * M_PI * i / kSupportSides;
    out[i] = {x + r * std::cos(a), y + r * std::sin(a)};
  }
  return out;
}

Outline section_outline(double x, double y, double r, double dx, double dy, double dz) {
  const double run = std::hypot(dx, dy);
  if (run == 0) return circle_outline(x, y, r);
  const double ax = dx / run, ay = dy / run, along = r * std::hypot(run, dz) / std::fabs(dz);
  Outline out(kSupportSides);
  for (int i = 0; i < kSupportSides; ++i) {
    const double a = 2 * M_PI * i / kSupportSides, u = along * std::cos(a), v = r * std::sin(a);
    out[i] = {x + ax * u - ay * v, y + ay * u + ax * v};
  }
  return out;
}

void append_loft(Mesh& mesh, const Outline& bottom, double z_bottom, const Outline& top, double z_top) {
  const uint32_t n = uint32_t(bottom.size());
  const uint32_t b = uint32_t(mesh.vertices()), t = b + n;
  for (const auto& p : bottom) mesh.V.insert(mesh.V.end(), {p[0], p[1], z_bottom});
  for (const auto& p : top) mesh.V.insert(mesh.V.end(), {p[0], p[1], z_top});
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t j = (i + 1) % n;
    mesh.F.insert(mesh.F.end(), {b + i, b + j, t + j, b + i, t + j, t + i});
  }
  // The caps as fans from corner 0: the bottom seen from below (clockwise from +z), the top from above.
  for (uint32_t i = 1; i + 1 < n; ++i) {
    mesh.F.insert(mesh.F.end(), {b, b + i + 1, b + i});
    mesh.F.insert(mesh.F.end(), {t, t + i, t + i + 1});
  }
}

void append_frustum(Mesh& mesh, double x, double y, double z_bottom, double r_bottom, double z_top, double r_top) {
  append_loft(mesh, circle_outline(x, y, r_bottom), z_bottom, circle_outline(x, y, r_top), z_top);
}

}  // namespace slicereuse
