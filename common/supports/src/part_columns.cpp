#include "part_columns.h"

#include <algorithm>
#include <array>
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

PartColumns::PartColumns(const Mesh& part, bool downward_only, double z_below) : part_(part) {
  // The kept faces and their x-y boxes, read from the vertices once.
  std::vector<uint32_t> faces;
  std::vector<std::array<double, 4>> boxes;  // x0, x1, y0, y1
  double x1 = -HUGE_VAL, y1 = -HUGE_VAL;
  x0_ = y0_ = HUGE_VAL;
  for (size_t f = 0; f < part.faces(); ++f) {
    const double* v[3];
    for (int j = 0; j < 3; ++j) v[j] = &part.V[3 * size_t(part.F[3 * f + j])];
    if (std::min({v[0][2], v[1][2], v[2][2]}) >= z_below) continue;
    const Vec3 n = cross(sub(v[1], v[0]), sub(v[2], v[0]));
    const double nz = n[2] / norm(n);  // NaN for a degenerate face: not kept
    if (!(std::fabs(nz) > kWallNormalZ) || (downward_only && !(nz < 0))) continue;
    faces.push_back(uint32_t(f));
    std::array<double, 4> box{std::min({v[0][0], v[1][0], v[2][0]}), std::max({v[0][0], v[1][0], v[2][0]}),
                              std::min({v[0][1], v[1][1], v[2][1]}), std::max({v[0][1], v[1][1], v[2][1]})};
    // Grown by the edge tolerance's reach, so that a ray it admits finds the face in its cell.
    const double grow = kEdgeTolerance * std::max(box[1] - box[0], box[3] - box[2]);
    boxes.push_back({box[0] - grow, box[1] + grow, box[2] - grow, box[3] + grow});
    x0_ = std::min(x0_, boxes.back()[0]), x1 = std::max(x1, boxes.back()[1]);
    y0_ = std::min(y0_, boxes.back()[2]), y1 = std::max(y1, boxes.back()[3]);
  }
  const size_t nf = faces.size();
  if (nf == 0 || !(x1 >= x0_)) {
    x0_ = y0_ = 0;
    cell_begin_.assign(2, 0);
    return;
  }
  const double w = x1 - x0_, h = y1 - y0_;
  cell_ = std::max({std::sqrt(w * h / double(nf)), w / kMaxGridSide, h / kMaxGridSide, 1e-9});
  nx_ = std::clamp(int64_t(w / cell_) + 1, int64_t(1), kMaxGridSide);
  ny_ = std::clamp(int64_t(h / cell_) + 1, int64_t(1), kMaxGridSide);
  auto face_cells = [&](size_t i, auto&& visit) {
    const std::array<double, 4>& b = boxes[i];
    for (int64_t cy = column(b[2], y0_, ny_); cy <= column(b[3], y0_, ny_); ++cy)
      for (int64_t cx = column(b[0], x0_, nx_); cx <= column(b[1], x0_, nx_); ++cx) visit(size_t(cy * nx_ + cx));
  };
  cell_begin_.assign(size_t(nx_ * ny_) + 1, 0);
  for (size_t i = 0; i < nf; ++i) face_cells(i, [&](size_t c) { ++cell_begin_[c + 1]; });
  for (size_t c = 0; c + 1 < cell_begin_.size(); ++c) cell_begin_[c + 1] += cell_begin_[c];
  cell_faces_.resize(cell_begin_.back());
  std::vector<uint32_t> fill(cell_begin_.begin(), cell_begin_.end() - 1);
  for (size_t i = 0; i < nf; ++i) face_cells(i, [&](size_t c) { cell_faces_[fill[c]++] = faces[i]; });
}

double PartColumns::highest_hit(double x, double y, double z_from, double z_floor) const {
  double best = std::numeric_limits<double>::quiet_NaN();
  for_each_hit(x, y, [&](uint32_t, const double*, double z) {
    if (z < z_from && z > z_floor && !(z <= best)) best = z;
  });
  return best;
}

double PartColumns::lowest_hit_above(double x, double y, double z_from) const {
  double best = std::numeric_limits<double>::quiet_NaN();
  for_each_hit(x, y, [&](uint32_t, const double*, double z) {
    if (z > z_from && !(z >= best)) best = z;
  });
  return best;
}

bool PartColumns::inside(double x, double y, double z) const {
  double lowest = INFINITY;
  bool up = false;
  for_each_hit(x, y, [&](uint32_t f, const double*, double zf) {
    if (!(zf > z && zf < lowest)) return;
    lowest = zf;
    const double* a = &part_.V[3 * size_t(part_.F[3 * f])];
    const double* b = &part_.V[3 * size_t(part_.F[3 * f + 1])];
    const double* d = &part_.V[3 * size_t(part_.F[3 * f + 2])];
    up = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]) > 0;
  });
  return up;
}

}  // namespace slicereuse
