#include "pillar_path.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slicereuse {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// A grid finer than this per side gains nothing for pillars and costs memory for huge parts.
constexpr int64_t kMaxGridSide = 4096;
// How far under the point the axis ray starts, so that the point's own face is not a hit.
constexpr double kBelowContactMm = 1e-6;
}  // namespace

int64_t PartColumns::column(double v, double v0, int64_t n) const {
  return std::clamp(int64_t(std::floor((v - v0) / cell_)), int64_t(0), n - 1);
}

PartColumns::PartColumns(const Mesh& part) : part_(part) {
  const size_t nf = part.faces();
  double x1 = -HUGE_VAL, y1 = -HUGE_VAL;
  x0_ = y0_ = HUGE_VAL;
  for (size_t v = 0; v < part.vertices(); ++v) {
    x0_ = std::min(x0_, part.V[3 * v]), x1 = std::max(x1, part.V[3 * v]);
    y0_ = std::min(y0_, part.V[3 * v + 1]), y1 = std::max(y1, part.V[3 * v + 1]);
  }
  if (nf == 0 || !(x1 >= x0_)) {
    x0_ = y0_ = 0;
    cell_begin_.assign(2, 0);
    return;
  }
  const double w = x1 - x0_, h = y1 - y0_;
  cell_ = std::max({std::sqrt(w * h / double(nf)), w / kMaxGridSide, h / kMaxGridSide, 1e-9});
  nx_ = std::clamp(int64_t(w / cell_) + 1, int64_t(1), kMaxGridSide);
  ny_ = std::clamp(int64_t(h / cell_) + 1, int64_t(1), kMaxGridSide);
  auto face_cells = [&](size_t f, auto&& visit) {
    double fx0 = HUGE_VAL, fx1 = -HUGE_VAL, fy0 = HUGE_VAL, fy1 = -HUGE_VAL;
    for (int j = 0; j < 3; ++j) {
      const double* p = &part.V[3 * size_t(part.F[3 * f + j])];
      fx0 = std::min(fx0, p[0]), fx1 = std::max(fx1, p[0]), fy0 = std::min(fy0, p[1]), fy1 = std::max(fy1, p[1]);
    }
    for (int64_t cy = column(fy0, y0_, ny_); cy <= column(fy1, y0_, ny_); ++cy)
      for (int64_t cx = column(fx0, x0_, nx_); cx <= column(fx1, x0_, nx_); ++cx) visit(size_t(cy * nx_ + cx));
  };
  cell_begin_.assign(size_t(nx_ * ny_) + 1, 0);
  for (size_t f = 0; f < nf; ++f) face_cells(f, [&](size_t c) { ++cell_begin_[c + 1]; });
  for (size_t c = 0; c + 1 < cell_begin_.size(); ++c) cell_begin_[c + 1] += cell_begin_[c];
  cell_faces_.resize(cell_begin_.back());
  std::vector<uint32_t> fill(cell_begin_.begin(), cell_begin_.end() - 1);
  for (size_t f = 0; f < nf; ++f) face_cells(f, [&](size_t c) { cell_faces_[fill[c]++] = uint32_t(f); });
}

double PartColumns::highest_hit(double x, double y, double z_from, double z_floor) const {
  if (part_.faces() == 0) return kNaN;
  const double cx = std::floor((x - x0_) / cell_), cy = std::floor((y - y0_) / cell_);
  if (cx < 0 || cy < 0 || cx >= double(nx_) || cy >= double(ny_)) return kNaN;
  const size_t c = size_t(cy) * size_t(nx_) + size_t(cx);
  double best = kNaN;
  for (uint32_t i = cell_begin_[c]; i < cell_begin_[c + 1]; ++i) {
    const uint32_t* f = &part_.F[3 * size_t(cell_faces_[i])];
    const double* a = &part_.V[3 * size_t(f[0])];
    const double* b = &part_.V[3 * size_t(f[1])];
    const double* d = &part_.V[3 * size_t(f[2])];
    const double area = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    if (area == 0) continue;
    // Area coordinates of (x, y) in the face's projection; inside (edges included) when all >= 0.
    const double la = ((b[0] - x) * (d[1] - y) - (b[1] - y) * (d[0] - x)) / area;
    const double lb = ((d[0] - x) * (a[1] - y) - (d[1] - y) * (a[0] - x)) / area;
    const double ld = 1 - la - lb;
    if (la < 0 || lb < 0 || ld < 0) continue;
    const double z = la * a[2] + lb * b[2] + ld * d[2];
    if (z < z_from && z > z_floor && !(z <= best)) best = z;
  }
  return best;
}

WayDown find_way_down(const PartColumns& part, double x, double y, double z, double z_head_bottom, double z_floor,
                      double rim_radius) {
  WayDown way{kNaN, part.highest_hit(x, y, z - kBelowContactMm, z_floor)};
  way.blocked_z = way.axis_z;
  for (int i = 0; i < kRimRays; ++i) {
    const double a = 2 * M_PI * i / kRimRays;
    const double hit = part.highest_hit(x + rim_radius * std::cos(a), y + rim_radius * std::sin(a), z_head_bottom, z_floor);
    if (!std::isnan(hit) && !(hit <= way.blocked_z)) way.blocked_z = hit;
  }
  return way;
}

}  // namespace slicereuse
