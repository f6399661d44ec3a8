// Box, UV sphere and torus test meshes, the grid face builders they share with the family
// generator, and the manifold checks used by the tests.
#include "shapes.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "slicereuse/util/error.h"

namespace slicereuse::test {

namespace {
constexpr double kPi = 3.14159265358979323846;

void push_quad(std::vector<uint32_t>& F, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  F.insert(F.end(), {a, b, c, a, c, d});
}
}  // namespace

Mesh make_box(double x0, double y0, double z0, double x1, double y1, double z1, int n) {
  if (n < 1) throw Error("make_box: n must be >= 1");
  if (!(x0 < x1 && y0 < y1 && z0 < z1)) throw Error("make_box: empty box");
  const int m = n + 1;
  const double lo[3] = {x0, y0, z0}, hi[3] = {x1, y1, z1};
  Mesh mesh;
  // Lattice points on the boundary get one vertex each, shared by the sides meeting there.
  std::unordered_map<uint64_t, uint32_t> index;
  index.reserve(size_t(6) * m * m);
  auto vertex = [&](const int* ijk) {
    const uint64_t key = (uint64_t(ijk[0]) * m + ijk[1]) * m + ijk[2];
    auto [it, fresh] = index.try_emplace(key, uint32_t(mesh.V.size() / 3));
    if (fresh) {
      for (int a = 0; a < 3; ++a) {
        // Exact bounds at the ends so the box spans exactly [lo, hi].
        const double t = double(ijk[a]) / n;
        mesh.V.push_back(ijk[a] == n ? hi[a] : lo[a] + (hi[a] - lo[a]) * t);
      }
    }
    return it->second;
  };
  // Each side: fixed axis and value, then in-plane axes u, v with u x v pointing outward.
  struct Side { int axis, value, u, v; };
  const Side sides[6] = {{0, 0, 2, 1}, {0, n, 1, 2}, {1, 0, 0, 2},
                         {1, n, 2, 0}, {2, 0, 1, 0}, {2, n, 0, 1}};
  mesh.F.reserve(size_t(36) * n * n);
  for (const Side& s : sides) {
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        int p[4][3];
        const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
        for (int c = 0; c < 4; ++c) {
          p[c][s.axis] = s.value;
          p[c][s.u] = i + du[c];
          p[c][s.v] = j + dv[c];
        }
        push_quad(mesh.F, vertex(p[0]), vertex(p[1]), vertex(p[2]), vertex(p[3]));
      }
    }
  }
  return mesh;
}

std::vector<uint32_t> pole_grid_faces(int rings, int segments) {
  if (rings < 2 || segments < 3) throw Error("pole grid needs rings >= 2 and segments >= 3");
  std::vector<uint32_t> F;
  F.reserve(size_t(6) * segments * (rings - 1));
  const uint32_t south = uint32_t(1 + (rings - 1) * segments);
  auto ring = [&](int r, int s) { return uint32_t(1 + (r - 1) * segments + (s % segments)); };
  for (int s = 0; s < segments; ++s) F.insert(F.end(), {0u, ring(1, s), ring(1, s + 1)});
  for (int r = 1; r + 1 < rings; ++r)
    for (int s = 0; s < segments; ++s)
      push_quad(F, ring(r, s), ring(r + 1, s), ring(r + 1, s + 1), ring(r, s + 1));
  for (int s = 0; s < segments; ++s)
    F.insert(F.end(), {south, ring(rings - 1, s + 1), ring(rings - 1, s)});
  return F;
}

std::vector<uint32_t> torus_grid_faces(int rows, int cols) {
  if (rows < 3 || cols < 3) throw Error("torus grid needs at least 3 rows and 3 columns");
  std::vector<uint32_t> F;
  F.reserve(size_t(6) * rows * cols);
  auto at = [&](int r, int c) { return uint32_t((r % rows) * cols + (c % cols)); };
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) push_quad(F, at(r, c), at(r + 1, c), at(r + 1, c + 1), at(r, c + 1));
  return F;
}

void append_mesh(Mesh& a, const Mesh& b, bool inverted) {
  const uint32_t base = uint32_t(a.vertices());
  a.V.insert(a.V.end(), b.V.begin(), b.V.end());
  for (size_t f = 0; f < b.faces(); ++f) {
    const uint32_t* t = &b.F[3 * f];
    if (inverted)
      a.F.insert(a.F.end(), {base + t[0], base + t[2], base + t[1]});
    else
      a.F.insert(a.F.end(), {base + t[0], base + t[1], base + t[2]});
  }
}

Mesh make_hollow_box(double x0, double y0, double z0, double x1, double y1, double z1, double wall) {
  Mesh m = make_box(x0, y0, z0, x1, y1, z1);
  append_mesh(m, make_box(x0 + wall, y0 + wall, z0 + wall, x1 - wall, y1 - wall, z1 - wall), true);
  return m;
}

Mesh make_cup(double x0, double y0, double z0, double x1, double y1, double z1, double wall) {
  Mesh m = make_box(x0, y0, z0, x1, y1, z0 + wall);
  append_mesh(m, make_box(x0, y0, z0, x0 + wall, y1, z1));
  append_mesh(m, make_box(x1 - wall, y0, z0, x1, y1, z1));
  append_mesh(m, make_box(x0, y0, z0, x1, y0 + wall, z1));
  append_mesh(m, make_box(x0, y1 - wall, z0, x1, y1, z1));
  return m;
}

Mesh make_sphere(double radius, int rings, int segments) {
  Mesh mesh;
  mesh.F = pole_grid_faces(rings, segments);
  mesh.V.reserve(3 * (2 + size_t(rings - 1) * segments));
  mesh.V.insert(mesh.V.end(), {0, 0, radius});
  for (int r = 1; r < rings; ++r) {
    const double theta = kPi * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2 * kPi * s / segments;
      mesh.V.insert(mesh.V.end(), {radius * std::sin(theta) * std::cos(phi),
                                   radius * std::sin(theta) * std::sin(phi), radius * std::cos(theta)});
    }
  }
  mesh.V.insert(mesh.V.end(), {0, 0, -radius});
  return mesh;
}

Mesh make_torus(double R, double r, int major_segments, int minor_segments) {
  if (!(0 < r && r < R)) throw Error("make_torus: need 0 < r < R");
  Mesh mesh;
  mesh.F = torus_grid_faces(major_segments, minor_segments);
  mesh.V.reserve(3 * size_t(major_segments) * minor_segments);
  for (int i = 0; i < major_segments; ++i) {
    const double u = 2 * kPi * i / major_segments;
    for (int j = 0; j < minor_segments; ++j) {
      const double v = 2 * kPi * j / minor_segments;
      const double rho = R + r * std::cos(v);
      mesh.V.insert(mesh.V.end(), {rho * std::cos(u), rho * std::sin(u), r * std::sin(v)});
    }
  }
  return mesh;
}

double signed_volume(const Mesh& mesh) {
  double six_v = 0;
  const double* V = mesh.V.data();
#pragma omp parallel for reduction(+ : six_v)
  for (long long f = 0; f < (long long)mesh.faces(); ++f) {
    const double* a = V + 3 * size_t(mesh.F[3 * f]);
    const double* b = V + 3 * size_t(mesh.F[3 * f + 1]);
    const double* c = V + 3 * size_t(mesh.F[3 * f + 2]);
    six_v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
             a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return six_v / 6;
}

void orient_outward(Mesh& mesh) {
  if (signed_volume(mesh) >= 0) return;
  for (size_t f = 0; f < mesh.faces(); ++f) std::swap(mesh.F[3 * f + 1], mesh.F[3 * f + 2]);
}

EdgeCensus edge_census(const Mesh& mesh) {
  // Directed half-edge keyed by its undirected edge; the low bit says which way it runs.
  std::vector<uint64_t> half;
  half.reserve(mesh.F.size());
  for (size_t f = 0; f < mesh.faces(); ++f) {
    for (int j = 0; j < 3; ++j) {
      const uint64_t a = mesh.F[3 * f + j], b = mesh.F[3 * f + (j + 1) % 3];
      half.push_back(((std::min(a, b) << 32 | std::max(a, b)) << 1) | (a < b ? 1 : 0));
    }
  }
  std::sort(half.begin(), half.end());
  EdgeCensus census;
  for (size_t i = 0; i < half.size();) {
    size_t j = i;
    while (j < half.size() && (half[j] >> 1) == (half[i] >> 1)) ++j;
    ++census.edges;
    const bool good = j - i == 2 && (half[i] & 1) == 0 && (half[i + 1] & 1) == 1 &&
                      (half[i] >> 1 & 0xffffffffu) != (half[i] >> 33);
    if (!good) ++census.bad_edges;
    i = j;
  }
  return census;
}

}  // namespace slicereuse::test
