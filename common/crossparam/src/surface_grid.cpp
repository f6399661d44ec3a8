#include "slicereuse/crossparam/surface_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "slicereuse/mesh/vec3.h"

namespace slicereuse {
namespace {

// Closest point of triangle (a, b, c) to p (Ericson, Real-Time Collision Detection 5.1.5), as
// barycentric coordinates.
void closest_on_triangle(const double* p, const double* a, const double* b, const double* c, double w[3]) {
  const Vec3 ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return void((w[0] = 1, w[1] = 0, w[2] = 0));
  const Vec3 bp = sub(p, b), cp = sub(p, c);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return void((w[0] = 0, w[1] = 1, w[2] = 0));
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return void((w[0] = 1 - v, w[1] = v, w[2] = 0));
  }
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return void((w[0] = 0, w[1] = 0, w[2] = 1));
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double v = d2 / (d2 - d6);
    return void((w[0] = 1 - v, w[1] = 0, w[2] = v));
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const double v = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return void((w[0] = 0, w[1] = 1 - v, w[2] = v));
  }
  const double denom = 1 / (va + vb + vc), v = vb * denom, t = vc * denom;
  w[0] = 1 - v - t;
  w[1] = v;
  w[2] = t;
}

}  // namespace

SurfaceGrid::SurfaceGrid(const Mesh& mesh, double cell_size) : mesh_(mesh) {
  const size_t nf = mesh.faces();
  const double* V = mesh.V.data();
  zlo_.resize(nf);
  zhi_.resize(nf);
  normal_.resize(3 * nf);
  double edge_sum = 0;
  double hi[3];
  for (int a = 0; a < 3; ++a) lo_[a] = hi[a] = V[3 * size_t(mesh.F[0]) + a];
  for (size_t f = 0; f < nf; ++f) {
    const double* p[3] = {V + 3 * size_t(mesh.F[3 * f]), V + 3 * size_t(mesh.F[3 * f + 1]),
                          V + 3 * size_t(mesh.F[3 * f + 2])};
    zlo_[f] = std::min({p[0][2], p[1][2], p[2][2]});
    zhi_[f] = std::max({p[0][2], p[1][2], p[2][2]});
    for (int a = 0; a < 3; ++a)
      for (int j = 0; j < 3; ++j) lo_[a] = std::min(lo_[a], p[j][a]), hi[a] = std::max(hi[a], p[j][a]);
    const Vec3 n = cross(sub(p[1], p[0]), sub(p[2], p[0]));
    const double len = norm(n);
    for (int a = 0; a < 3; ++a) normal_[3 * f + a] = len > 0 ? n[a] / len : 0;
    for (int j = 0; j < 3; ++j) edge_sum += std::sqrt(squared_distance(p[(j + 1) % 3], p[j]));
  }
  mean_edge_ = edge_sum / double(3 * nf);
  const double extent = std::max({hi[0] - lo_[0], hi[1] - lo_[1], hi[2] - lo_[2], 1e-9});
  h_ = cell_size > 0 ? cell_size : 2 * mean_edge_;
  // At most about 4 cells per face: a finer grid only costs memory and empty cells.
  const double max_cells = std::max(64.0, 4.0 * double(nf));
  h_ = std::max({h_, extent / 4096, 1e-12});
  while ((std::floor((hi[0] - lo_[0]) / h_) + 1) * (std::floor((hi[1] - lo_[1]) / h_) + 1) *
             (std::floor((hi[2] - lo_[2]) / h_) + 1) > max_cells)
    h_ *= 1.25;
  for (int a = 0; a < 3; ++a) n_[a] = int(std::floor((hi[a] - lo_[a]) / h_)) + 1;

  // Counting sort of (cell, face) pairs, face bounding boxes rasterized into cells.
  auto range = [&](size_t f, int lo[3], int hi_c[3]) {
    for (int a = 0; a < 3; ++a) {
      double mn = V[3 * size_t(mesh.F[3 * f]) + a], mx = mn;
      for (int j = 1; j < 3; ++j) {
        const double v = V[3 * size_t(mesh.F[3 * f + j]) + a];
        mn = std::min(mn, v), mx = std::max(mx, v);
      }
      lo[a] = std::clamp(int(std::floor((mn - lo_[a]) / h_)), 0, n_[a] - 1);
      hi_c[a] = std::clamp(int(std::floor((mx - lo_[a]) / h_)), 0, n_[a] - 1);
    }
  };
  const size_t cells = size_t(n_[0]) * n_[1] * n_[2];
  begin_.assign(cells + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    for (size_t f = 0; f < nf; ++f) {
      int a[3], b[3];
      range(f, a, b);
      for (int k = a[2]; k <= b[2]; ++k)
        for (int j = a[1]; j <= b[1]; ++j)
          for (int i = a[0]; i <= b[0]; ++i) {
            const size_t c = (size_t(k) * n_[1] + j) * n_[0] + i;
            if (pass == 0)
              ++begin_[c + 1];
            else
              faces_[begin_[c]++] = uint32_t(f);
          }
    }
    if (pass == 0) {
      for (size_t c = 0; c < cells; ++c) begin_[c + 1] += begin_[c];
      faces_.resize(begin_[cells]);
    } else {
      // begin_[c] now holds the end of cell c: shift back.
      for (size_t c = cells; c > 0; --c) begin_[c] = begin_[c - 1];
      begin_[0] = 0;
    }
  }
}

// The squared distance from p to the nearest grid cell outside the block of cells within
// Chebyshev distance r of cell c, over the first `axes` axes (infinite when there is none).
double SurfaceGrid::unvisited_bound(const double p[3], const int c[3], int r, int axes) const {
  double bound = std::numeric_limits<double>::infinity();
  for (int a = 0; a < axes; ++a) {
    if (c[a] - r > 0) bound = std::min(bound, std::max(0.0, p[a] - (lo_[a] + (c[a] - r) * h_)));
    if (c[a] + r < n_[a] - 1) bound = std::min(bound, std::max(0.0, lo_[a] + (c[a] + r + 1) * h_ - p[a]));
  }
  return bound * bound;
}

size_t SurfaceGrid::cell_of(const double p[3], int c[3]) const {
  for (int a = 0; a < 3; ++a) c[a] = std::clamp(int(std::floor((p[a] - lo_[a]) / h_)), 0, n_[a] - 1);
  return (size_t(c[2]) * n_[1] + c[1]) * n_[0] + c[0];
}

SurfacePoint SurfaceGrid::nearest_on_level(const double p[3], double z, const double* normal, double min_dot,
                                           double max_distance) const {
  SurfacePoint best;
  double best_d2 = max_distance * max_distance;
  const double q[3] = {p[0], p[1], z};
  int c[3];
  cell_of(q, c);
  if (z < lo_[2] - h_ || z > lo_[2] + n_[2] * h_ + h_) return best;
  const double* V = mesh_.V.data();
  auto test_face = [&](uint32_t f) {
    if (z < zlo_[f] || z > zhi_[f]) return;
    if (normal && dot(&normal_[3 * size_t(f)], normal) < min_dot) return;
    const uint32_t* F = &mesh_.F[3 * size_t(f)];
    const double* v[3] = {V + 3 * size_t(F[0]), V + 3 * size_t(F[1]), V + 3 * size_t(F[2])};
    // The face's section by the plane: corners on it and strict edge crossings.
    double pts[3][3], bar[3][3];
    int np = 0;
    for (int j = 0; j < 3 && np < 3; ++j) {
      const double za = v[j][2], zb = v[(j + 1) % 3][2];
      if (za == z) {
        for (int a = 0; a < 3; ++a) pts[np][a] = v[j][a], bar[np][a] = a == j;
        ++np;
      } else if ((za < z && zb > z) || (za > z && zb < z)) {
        const double t = (z - za) / (zb - za);
        for (int a = 0; a < 3; ++a) {
          pts[np][a] = v[j][a] + t * (v[(j + 1) % 3][a] - v[j][a]);
          bar[np][a] = a == j ? 1 - t : a == (j + 1) % 3 ? t : 0;
        }
        pts[np][2] = z;
        ++np;
      }
    }
    double w[3], d2;
    if (np == 3) {  // a horizontal face in the plane: its closest point is in the plane too
      closest_on_triangle(q, v[0], v[1], v[2], w);
    } else {
      const int k = np == 2 ? 1 : 0;
      const double dx = pts[k][0] - pts[0][0], dy = pts[k][1] - pts[0][1], len2 = dx * dx + dy * dy;
      const double t = len2 > 0 ? std::clamp(((q[0] - pts[0][0]) * dx + (q[1] - pts[0][1]) * dy) / len2, 0.0, 1.0) : 0;
      for (int a = 0; a < 3; ++a) w[a] = (1 - t) * bar[0][a] + t * bar[k][a];
    }
    double x = 0, y = 0;
    for (int j = 0; j < 3; ++j) x += w[j] * v[j][0], y += w[j] * v[j][1];
    d2 = (x - q[0]) * (x - q[0]) + (y - q[1]) * (y - q[1]);
    if (d2 < best_d2) {
      best_d2 = d2;
      best.face = f;
      for (int j = 0; j < 3; ++j) best.bary[j] = w[j];
      best.xyz[0] = x, best.xyz[1] = y, best.xyz[2] = z;
    }
  };
  const size_t slab = size_t(c[2]) * n_[1];
  for (int r = 0;; ++r) {
    for (int j = c[1] - r; j <= c[1] + r; ++j) {
      if (j < 0 || j >= n_[1]) continue;
      const bool edge_row = j == c[1] - r || j == c[1] + r;
      for (int i = c[0] - r; i <= c[0] + r; i += edge_row ? 1 : 2 * r) {
        if (i >= 0 && i < n_[0]) {
          const size_t cell = (slab + j) * n_[0] + i;
          for (uint32_t k = begin_[cell]; k < begin_[cell + 1]; ++k) test_face(faces_[k]);
        }
        if (r == 0) break;
      }
    }
    // Everything not yet visited lies outside the (2r+1)^2 block of cells around q.
    if (unvisited_bound(q, c, r, 2) >= best_d2) break;
  }
  if (best.face != kNoFace) best.distance = std::sqrt(best_d2);
  return best;
}

SurfacePoint SurfaceGrid::nearest_on_surface(const double p[3], const double* normal, double min_dot,
                                             double max_distance) const {
  SurfacePoint best;
  double best_d2 = max_distance * max_distance;
  int c[3];
  cell_of(p, c);
  const double* V = mesh_.V.data();
  auto test_face = [&](uint32_t f) {
    if (normal && dot(&normal_[3 * size_t(f)], normal) < min_dot) return;
    const uint32_t* F = &mesh_.F[3 * size_t(f)];
    const double* v[3] = {V + 3 * size_t(F[0]), V + 3 * size_t(F[1]), V + 3 * size_t(F[2])};
    double w[3], x[3] = {0, 0, 0};
    closest_on_triangle(p, v[0], v[1], v[2], w);
    for (int j = 0; j < 3; ++j)
      for (int a = 0; a < 3; ++a) x[a] += w[j] * v[j][a];
    const double d2 = squared_distance(x, p);
    if (d2 < best_d2) {
      best_d2 = d2;
      best.face = f;
      for (int j = 0; j < 3; ++j) best.bary[j] = w[j], best.xyz[j] = x[j];
    }
  };
  for (int r = 0;; ++r) {
    for (int k = c[2] - r; k <= c[2] + r; ++k) {
      if (k < 0 || k >= n_[2]) continue;
      for (int j = c[1] - r; j <= c[1] + r; ++j) {
        if (j < 0 || j >= n_[1]) continue;
        const bool shell = k == c[2] - r || k == c[2] + r || j == c[1] - r || j == c[1] + r;
        for (int i = c[0] - r; i <= c[0] + r; i += shell ? 1 : 2 * r) {
          if (i >= 0 && i < n_[0]) {
            const size_t cell = (size_t(k) * n_[1] + j) * n_[0] + i;
            for (uint32_t m = begin_[cell]; m < begin_[cell + 1]; ++m) test_face(faces_[m]);
          }
          if (r == 0) break;
        }
      }
    }
    if (unvisited_bound(p, c, r, 3) >= best_d2) break;
  }
  if (best.face != kNoFace) best.distance = std::sqrt(best_d2);
  return best;
}

}  // namespace slicereuse
