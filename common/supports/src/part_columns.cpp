#include "part_columns.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "slicereuse/mesh/vec3.h"

namespace slicereuse {

namespace {
// A grid finer than this per side gains nothing for pillars and costs memory for huge parts.
constexpr int64_t kMaxGridSide = 4096;
}  // namespace

int64_t PartColumns::column(double v, double v0, int64_t n) const {
  return std::clamp(int64_t(std::floor((v - v0) / cell_)), int64_t(0), n - 1);
}

PartColumns::PartColumns(const Mesh& part, bool downward_only) : part_(part) {
  std::vector<uint32_t> faces;
  for (size_t f = 0; f < part.faces(); ++f) {
    const double* v[3];
    for (int j = 0; j < 3; ++j) v[j] = &part.V[3 * size_t(part.F[3 * f + j])];
    if (!downward_only || cross(sub(v[1], v[0]), sub(v[2], v[0]))[2] < 0) faces.push_back(uint32_t(f));
  }
  const size_t nf = faces.size();
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
  for (const uint32_t f : faces) face_cells(f, [&](size_t c) { ++cell_begin_[c + 1]; });
  for (size_t c = 0; c + 1 < cell_begin_.size(); ++c) cell_begin_[c + 1] += cell_begin_[c];
  cell_faces_.resize(cell_begin_.back());
  std::vector<uint32_t> fill(cell_begin_.begin(), cell_begin_.end() - 1);
  for (const uint32_t f : faces) face_cells(f, [&](size_t c) { cell_faces_[fill[c]++] = f; });
}

double PartColumns::highest_hit(double x, double y, double z_from, double z_floor) const {
  double best = std::numeric_limits<double>::quiet_NaN();
  for_each_hit(x, y, [&](uint32_t, const double*, double z) {
    if (z < z_from && z > z_floor && !(z <= best)) best = z;
  });
  return best;
}

}  // namespace slicereuse
