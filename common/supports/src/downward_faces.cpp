#include "downward_faces.h"

#include <algorithm>
#include <cmath>

#include "slicereuse/mesh/vec3.h"

namespace slicereuse {

DownwardFaces::DownwardFaces(const Mesh& mesh) : mesh_(mesh) {
  const size_t nf = mesh.faces();
  std::vector<uint32_t> down;
  std::vector<double> box;  // x0, y0, x1, y1 per downward face
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY}, extent_sum = 0;
  for (size_t f = 0; f < nf; ++f) {
    const double* v[3];
    for (int j = 0; j < 3; ++j) v[j] = &mesh.V[3 * size_t(mesh.F[3 * f + j])];
    if (cross(sub(v[1], v[0]), sub(v[2], v[0]))[2] >= 0) continue;
    down.push_back(uint32_t(f));
    double l[2], h[2];
    for (int a = 0; a < 2; ++a) {
      l[a] = std::min({v[0][a], v[1][a], v[2][a]}), h[a] = std::max({v[0][a], v[1][a], v[2][a]});
      lo[a] = std::min(lo[a], l[a]), hi[a] = std::max(hi[a], h[a]);
      extent_sum += h[a] - l[a];
    }
    box.insert(box.end(), {l[0], l[1], h[0], h[1]});
  }
  if (down.empty()) return;
  // About one face's box per cell, and at most 4 cells per face (memory).
  cell_ = std::max(extent_sum / double(2 * down.size()), 1e-9);
  while ((std::floor((hi[0] - lo[0]) / cell_) + 1) * (std::floor((hi[1] - lo[1]) / cell_) + 1) >
         std::max(64.0, 4.0 * double(down.size())))
    cell_ *= 1.25;
  x0_ = lo[0], y0_ = lo[1];
  nx_ = int(std::floor((hi[0] - lo[0]) / cell_)) + 1;
  ny_ = int(std::floor((hi[1] - lo[1]) / cell_)) + 1;
  auto cells = [&](size_t i, int c[4]) {
    c[0] = std::clamp(int(std::floor((box[4 * i] - x0_) / cell_)), 0, nx_ - 1);
    c[1] = std::clamp(int(std::floor((box[4 * i + 1] - y0_) / cell_)), 0, ny_ - 1);
    c[2] = std::clamp(int(std::floor((box[4 * i + 2] - x0_) / cell_)), 0, nx_ - 1);
    c[3] = std::clamp(int(std::floor((box[4 * i + 3] - y0_) / cell_)), 0, ny_ - 1);
  };
  begin_.assign(size_t(nx_) * ny_ + 1, 0);
  int c[4];
  for (size_t i = 0; i < down.size(); ++i) {
    cells(i, c);
    for (int y = c[1]; y <= c[3]; ++y)
      for (int x = c[0]; x <= c[2]; ++x) ++begin_[size_t(y) * nx_ + x + 1];
  }
  for (size_t i = 1; i < begin_.size(); ++i) begin_[i] += begin_[i - 1];
  faces_.resize(begin_.back());
  std::vector<uint32_t> fill(begin_.begin(), begin_.end() - 1);
  for (size_t i = 0; i < down.size(); ++i) {
    cells(i, c);
    for (int y = c[1]; y <= c[3]; ++y)
      for (int x = c[0]; x <= c[2]; ++x) faces_[fill[size_t(y) * nx_ + x]++] = down[i];
  }
}

bool DownwardFaces::hit(double x, double y, const LayerSpan& span, const LayerSpan& inner, uint32_t& face,
                        double bary[3]) const {
  if (begin_.empty()) return false;
  const int cx = int(std::floor((x - x0_) / cell_)), cy = int(std::floor((y - y0_) / cell_));
  if (cx < 0 || cy < 0 || cx >= nx_ || cy >= ny_) return false;
  const size_t cell = size_t(cy) * nx_ + cx;
  bool found = false, found_inner = false;
  double best_z = 0;
  for (uint32_t m = begin_[cell]; m < begin_[cell + 1]; ++m) {
    const uint32_t f = faces_[m];
    const double* v[3];
    for (int j = 0; j < 3; ++j) v[j] = &mesh_.V[3 * size_t(mesh_.F[3 * size_t(f) + j])];
    const double area = (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[2][0] - v[0][0]) * (v[1][1] - v[0][1]);
    if (area == 0) continue;
    double w[3];
    for (int j = 0; j < 3; ++j) {
      const double* a = v[(j + 1) % 3];
      const double* b = v[(j + 2) % 3];
      w[j] = ((a[0] - x) * (b[1] - y) - (b[0] - x) * (a[1] - y)) / area;
    }
    // Rays through a shared edge or corner hit both faces: either will do.
    if (w[0] < -1e-12 || w[1] < -1e-12 || w[2] < -1e-12) continue;
    double sum = 0;
    for (double& wj : w) sum += (wj = std::max(wj, 0.0));
    for (double& wj : w) wj /= sum;
    const double z = w[0] * v[0][2] + w[1] * v[1][2] + w[2] * v[2][2];
    if (z < span.lo || z > span.hi) continue;
    const bool in_inner = z > inner.lo && z <= inner.hi;
    if (found && (found_inner && !in_inner)) continue;
    if (found && found_inner == in_inner && !(z < best_z)) continue;
    found = true, found_inner = in_inner, best_z = z, face = f;
    for (int j = 0; j < 3; ++j) bary[j] = w[j];
  }
  return found;
}

}  // namespace slicereuse
