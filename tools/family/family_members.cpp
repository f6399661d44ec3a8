// Family members (see family.h): the base's vertices moved by seeded smooth deformations that
// keep every plane z = const mapped bijectively onto itself (and, with a z change, every vertical
// column monotonically onto itself), so members stay free of self-intersections.
#include <algorithm>
#include <cmath>

#include "family.h"
#include "slicereuse/util/error.h"

namespace slicereuse::test {

namespace {

constexpr double kPi = 3.14159265358979323846;

// splitmix64: a tiny, portable generator, so members are the same on every platform.
struct Rng {
  uint64_t state;
  uint64_t next() {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * double(next() >> 11) * 0x1.0p-53; }
};

struct Bump {
  double cx, cy, cz, inv_two_sigma2, dx, dy;
};

struct ZBump {
  double cx, cy, inv_two_sigma2, dz;
};

}  // namespace

Mesh make_family_member(const Mesh& base, const FamilyOptions& o, int index) {
  Mesh mesh = base;
  mesh.V = deform_like_family_member(base, o, index, base.V);
  return mesh;
}

std::vector<double> deform_like_family_member(const Mesh& base, const FamilyOptions& o, int index,
                                              const std::vector<double>& points) {
  if (index < 0) throw Error("family: member index must be >= 0");
  if (base.V.empty()) throw Error("family: empty base mesh");
  std::vector<double> out = points;
  if (index == 0) return out;

  double lo[3], hi[3];
  for (int a = 0; a < 3; ++a) lo[a] = hi[a] = base.V[a];
  for (size_t i = 0; i < base.V.size(); i += 3)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], base.V[i + a]), hi[a] = std::max(hi[a], base.V[i + a]);
  const double cx = (lo[0] + hi[0]) / 2, cy = (lo[1] + hi[1]) / 2, z0 = lo[2], H = hi[2] - lo[2];
  const double D = std::sqrt((hi[0] - lo[0]) * (hi[1] - lo[1]));  // lateral size

  Rng rng{o.seed * 0xD1B54A32D192ED03ull + uint64_t(index)};
  rng.next();
  const double sx0 = rng.uniform(-0.04, 0.04), sx1 = rng.uniform(-0.04, 0.04);
  const double sy0 = rng.uniform(-0.04, 0.04), sy1 = rng.uniform(-0.04, 0.04);
  const double rot = rng.uniform(-0.03, 0.03), twist = rng.uniform(-0.1, 0.1);
  const double kx = rng.uniform(-0.05, 0.05), ky = rng.uniform(-0.05, 0.05);
  const double qx = rng.uniform(-0.06, 0.06), qy = rng.uniform(-0.06, 0.06);
  auto random_vertex = [&] { return &base.V[3 * (rng.next() % base.vertices())]; };
  // Lateral bumps: |grad| <= 0.61 * amplitude / sigma <= 0.09 each, six at most, so with the
  // affine part (singular values >= 0.9) every plane still maps one-to-one.
  std::vector<Bump> bumps(3 + rng.next() % 4);
  for (Bump& b : bumps) {
    const double* c = random_vertex();
    const double sigma = rng.uniform(0.12, 0.25) * D, amp = rng.uniform(0.05, 0.15) * sigma;
    const double dir = rng.uniform(0, 2 * kPi);
    b = {c[0], c[1], c[2], 1 / (2 * sigma * sigma), amp * std::cos(dir), amp * std::sin(dir)};
  }
  // Vertical change: z scaled by 1 + zscale plus bumps of height dz * 4u(1-u) (u = relative
  // height), vanishing at bottom and top; d z'/dz >= 0.97 - 3 * 0.12 > 0.
  // Band: bumps of height dz * sin^2(pi v) within u in [band_lo, band_lo + 0.2] (v relative to
  // the band), zero outside; d z'/dz >= 1 - 0.02 * pi / 0.2 > 0.68.
  double zscale = 0, band_lo = 0;
  std::vector<ZBump> zbumps;
  if (o.z_change == ZChange::Everywhere) {
    zscale = rng.uniform(-0.03, 0.03);
    zbumps.resize(1 + rng.next() % 3);
    for (ZBump& b : zbumps) {
      const double* c = random_vertex();
      const double sigma = rng.uniform(0.15, 0.3) * D;
      b = {c[0], c[1], 1 / (2 * sigma * sigma), rng.uniform(-0.03, 0.03) * H};
    }
  } else if (o.z_change == ZChange::Band) {
    band_lo = rng.uniform(0.2, 0.6);
    const double* c = random_vertex();
    const double sigma = rng.uniform(0.3, 0.5) * D;
    const double dz = rng.uniform(0.01, 0.02) * H;
    zbumps.push_back({c[0], c[1], 1 / (2 * sigma * sigma), rng.next() % 2 ? dz : -dz});
  }

  double* V = out.data();
#pragma omp parallel for schedule(static)
  for (long long i = 0; i < (long long)(points.size() / 3); ++i) {
    const double* p = &points[3 * i];
    const double u = (p[2] - z0) / H, m = u - 0.5;
    const double x0 = (p[0] - cx) * (1 + sx0 + sx1 * m), y0 = (p[1] - cy) * (1 + sy0 + sy1 * m);
    const double th = rot + twist * m, c = std::cos(th), s = std::sin(th);
    double x = cx + c * x0 - s * y0 + (kx * m + qx * m * m) * H;
    double y = cy + s * x0 + c * y0 + (ky * m + qy * m * m) * H;
    for (const Bump& b : bumps) {
      const double d2 = (p[0] - b.cx) * (p[0] - b.cx) + (p[1] - b.cy) * (p[1] - b.cy) + (p[2] - b.cz) * (p[2] - b.cz);
      const double g = std::exp(-d2 * b.inv_two_sigma2);
      x += g * b.dx;
      y += g * b.dy;
    }
    V[3 * i] = x;
    V[3 * i + 1] = y;
    if (o.z_change != ZChange::None) {
      // Profile of the bumps along the column: zero at the ends of the part (or band).
      const double v = (u - band_lo) / 0.2;
      const double profile = o.z_change == ZChange::Everywhere ? 4 * u * (1 - u)
                              : v > 0 && v < 1                 ? std::pow(std::sin(kPi * v), 2)
                                                               : 0;
      if (profile == 0 && zscale == 0) continue;  // z untouched, bit for bit
      double z = (p[2] - z0) * (1 + zscale);
      for (const ZBump& b : zbumps)
        z += b.dz * std::exp(-((x - b.cx) * (x - b.cx) + (y - b.cy) * (y - b.cy)) * b.inv_two_sigma2) * profile;
      V[3 * i + 2] = z0 + z;
    }
  }
  return out;
}

}  // namespace slicereuse::test
