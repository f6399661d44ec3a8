// Base shapes of the mass-customization families (see family.h): swept profiles built as
// pole grids (genus 0) or torus grids (genus 1), sized to a target face count, then scaled
// so that z spans exactly [0, height].
#include <algorithm>
#include <cmath>

#include "family.h"
#include "shapes.h"
#include "slicereuse/util/error.h"

namespace slicereuse::test {

namespace {

constexpr double kPi = 3.14159265358979323846;

struct P2 { double a, b; };
struct P3 { double x, y, z; };
P3 operator+(P3 p, P3 q) { return {p.x + q.x, p.y + q.y, p.z + q.z}; }
P3 operator*(double s, P3 p) { return {s * p.x, s * p.y, s * p.z}; }
P3 cross(P3 p, P3 q) { return {p.y * q.z - p.z * q.y, p.z * q.x - p.x * q.z, p.x * q.y - p.y * q.x}; }
P3 normalized(P3 p) { return (1 / std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z)) * p; }

void push(std::vector<double>& V, P3 p) { V.insert(V.end(), {p.x, p.y, p.z}); }

double length(const std::vector<P2>& line) {
  double s = 0;
  for (size_t i = 1; i < line.size(); ++i) s += std::hypot(line[i].a - line[i - 1].a, line[i].b - line[i - 1].b);
  return s;
}

double chain_length(const std::vector<std::vector<P2>>& pieces) {
  double s = 0;
  for (const auto& p : pieces) s += length(p);
  return s;
}

// `count` points spaced evenly by arc length along piece `line`, from its start, without its end.
void sample_line(const std::vector<P2>& line, int count, std::vector<P2>& out) {
  const double total = length(line);
  size_t i = 1;
  double before = 0;  // arc length at line[i-1]
  for (int k = 0; k < count; ++k) {
    const double s = total * k / count;
    double seg = std::hypot(line[i].a - line[i - 1].a, line[i].b - line[i - 1].b);
    while (before + seg < s && i + 1 < line.size()) {
      before += seg;
      ++i;
      seg = std::hypot(line[i].a - line[i - 1].a, line[i].b - line[i - 1].b);
    }
    const double t = seg > 0 ? std::clamp((s - before) / seg, 0.0, 1.0) : 0.0;
    out.push_back({line[i - 1].a + t * (line[i].a - line[i - 1].a), line[i - 1].b + t * (line[i].b - line[i - 1].b)});
  }
}

// Resamples a chain of polylines (each piece starts where the previous one ends) into `intervals`
// intervals, spread over the pieces by length with at least one each, so that piece ends (the
// profile's corners) are kept exactly. Returns intervals points, plus the chain's end when open.
std::vector<P2> resample_chain(const std::vector<std::vector<P2>>& pieces, int intervals, bool closed) {
  const double total = chain_length(pieces);
  std::vector<int> n(pieces.size());
  int used = 0;
  for (size_t i = 0; i < pieces.size(); ++i) used += n[i] = std::max(1, int(intervals * length(pieces[i]) / total));
  for (size_t i = 0; used < intervals; i = (i + 1) % pieces.size(), ++used) ++n[i];
  std::vector<P2> out;
  for (size_t i = 0; i < pieces.size(); ++i) sample_line(pieces[i], n[i], out);
  if (!closed) out.push_back(pieces.back().back());
  return out;
}

template <class F>
std::vector<P2> dense_curve(double from, double to, F f, int n = 4000) {
  std::vector<P2> line(n + 1);
  for (int i = 0; i <= n; ++i) line[i] = f(from + (to - from) * i / n);
  return line;
}

// Arc length table of a parametric curve on [from, to]: maps evenly spaced arc lengths back to
// parameters so stations along a spine are evenly spaced.
template <class F>
struct ArcLength {
  std::vector<double> param, arc;
  ArcLength(double from, double to, F curve, int n = 8192) : param(n + 1), arc(n + 1) {
    P3 prev = curve(from);
    for (int i = 0; i <= n; ++i) {
      param[i] = from + (to - from) * i / n;
      const P3 p = curve(param[i]);
      arc[i] = i ? arc[i - 1] + std::sqrt((p.x - prev.x) * (p.x - prev.x) + (p.y - prev.y) * (p.y - prev.y) +
                                          (p.z - prev.z) * (p.z - prev.z))
                 : 0;
      prev = p;
    }
  }
  double total() const { return arc.back(); }
  double at(double s) const {
    const size_t i = std::clamp<size_t>(std::lower_bound(arc.begin(), arc.end(), s) - arc.begin(), 1, arc.size() - 1);
    const double t = (s - arc[i - 1]) / (arc[i] - arc[i - 1]);
    return param[i - 1] + t * (param[i] - param[i - 1]);
  }
};

// Segments around and stations along a grid with about `faces` faces and square-ish cells, for
// a surface `around` long one way and `along` the other.
void grid_size(size_t faces, double around, double along, int& segments, int& stations) {
  const double h = std::sqrt(2 * around * along / double(faces));
  segments = std::max(8, int(std::lround(around / h)));
  stations = std::max(4, int(std::lround(double(faces) / (2.0 * segments))));
}

// Dental-arch-like shell: an inverted-U wall profile (in normal n, height z) swept along a
// horseshoe in the plane z = 0, with tooth ridges and rounded closed ends.
Mesh make_arch(size_t faces) {
  const double Rx = 24, Ry = 20, half_angle = 1.75;
  const double W0 = 5, H0 = 14.5, wall = 1.8, taper = 0.3, cap = W0, teeth = 14;
  auto dome = [&](double W, double H, bool reverse) {
    std::vector<P2> line = dense_curve(0, kPi, [&](double phi) {
      const double c = std::cos(phi), z = H * std::cbrt(std::sin(phi) * std::sin(phi));
      return P2{W * std::copysign(std::cbrt(c * c), c) * (1 - taper * z / H0), z};
    });
    // Exact feet so the rims between the walls lie exactly on z = 0.
    line.front() = {W, 0};
    line.back() = {-W, 0};
    if (reverse) std::reverse(line.begin(), line.end());
    return line;
  };
  const double Wi = W0 - wall, Hi = H0 - wall;
  const std::vector<std::vector<P2>> profile = {
      dome(W0, H0, false), {{-W0, 0}, {-Wi, 0}}, dome(Wi, Hi, true), {{Wi, 0}, {W0, 0}}};

  auto spine = [&](double th) { return P3{Rx * std::sin(th), Ry * std::cos(th), 0}; };
  const ArcLength arc(-half_angle, half_angle, spine);
  const double L = arc.total(), cap_len = kPi / 2 * cap;
  int K, rings;
  grid_size(faces, chain_length(profile), L + 2 * cap_len, K, rings);
  const int cap_rings = std::max(2, int(std::lround(rings * cap_len / (L + 2 * cap_len))));
  const int body_rings = std::max(2, rings - 2 * (cap_rings - 1));
  const std::vector<P2> ring = resample_chain(profile, K, true);

  auto frame = [&](double th, P3& c, P3& T, P3& N) {
    c = spine(th);
    T = normalized({Rx * std::cos(th), -Ry * std::sin(th), 0});
    N = {-T.y, T.x, 0};
  };
  const P3 up{0, 0, 1};
  Mesh mesh;
  mesh.V.reserve(3 * (2 + size_t(K) * (body_rings + 2 * cap_rings)));
  // End caps: the profile shrinks about its mid-height centre as the end is rounded off.
  auto cap_ring = [&](double th, double dir, double alpha) {
    P3 c, T, N;
    frame(th, c, T, N);
    const double s = std::sin(alpha);
    const P3 o = c + (dir * cap * std::cos(alpha)) * T;
    for (const P2& p : ring) push(mesh.V, o + (p.a * s) * N + (H0 / 2 + (p.b - H0 / 2) * s) * up);
  };
  auto pole = [&](double th, double dir) {
    P3 c, T, N;
    frame(th, c, T, N);
    push(mesh.V, c + (dir * cap) * T + (H0 / 2) * up);
  };
  pole(-half_angle, -1);
  for (int k = 1; k < cap_rings; ++k) cap_ring(-half_angle, -1, kPi / 2 * k / cap_rings);
  for (int j = 0; j < body_rings; ++j) {
    const double s = L * j / (body_rings - 1);
    // Ridges at the teeth, narrower and lower between them; 1 at both ends to meet the caps.
    const double gap = (1 - std::cos(2 * kPi * teeth * s / L)) / 2;
    const double wf = 1 - 0.06 * gap, hf = 1 - 0.07 * gap;
    P3 c, T, N;
    frame(arc.at(s), c, T, N);
    for (const P2& p : ring) push(mesh.V, c + (p.a * wf) * N + (p.b * hf) * up);
  }
  for (int k = cap_rings - 1; k >= 1; --k) cap_ring(half_angle, 1, kPi / 2 * k / cap_rings);
  pole(half_angle, 1);
  mesh.F = pole_grid_faces(body_rings + 2 * (cap_rings - 1) + 1, K);
  return mesh;
}

// Ear-canal-like hollow cup: a bent, tapering elliptic tube; the profile runs (t along the
// spine, rho = relative section size) from the outer tip up the outer wall, over the rim and
// down the inner wall to the inner tip.
Mesh make_ear(size_t faces) {
  const double L = 22, Rb = 28, wiggle = 1.5, outer_tip = 3.5, inner = 0.72, inner_t0 = 3, inner_tip = 2.5;
  auto a_of = [&](double t) { return 4.2 - 1.2 * std::clamp(t / L, 0.0, 1.0); };
  auto b_of = [&](double t) { return 3.4 - 0.9 * std::clamp(t / L, 0.0, 1.0); };
  const double aref = 3.6;  // rho is scaled by this in the chain so its spacing is in mm
  const double mid = (1 + inner) / 2, hr = (1 - inner) / 2, rim = hr * a_of(L);
  const std::vector<std::vector<P2>> profile = {
      dense_curve(0, kPi / 2, [&](double al) { return P2{-outer_tip * std::cos(al), aref * std::sin(al)}; }),
      {{0, aref}, {L, aref}},
      dense_curve(0, kPi, [&](double g) { return P2{L + rim * std::sin(g), aref * (mid + hr * std::cos(g))}; }),
      {{L, aref * inner}, {inner_t0, aref * inner}},
      dense_curve(kPi / 2, 0, [&](double al) {
        return P2{inner_t0 - inner_tip * std::cos(al), aref * inner * std::sin(al)};
      })};
  auto spine = [&](double t) {
    return P3{Rb * (1 - std::cos(t / Rb)), wiggle * std::sin(kPi * t / L), Rb * std::sin(t / Rb)};
  };
  auto tangent = [&](double t) {
    return normalized({std::sin(t / Rb), wiggle * kPi / L * std::cos(kPi * t / L), std::cos(t / Rb)});
  };
  const double around = 2 * kPi * std::sqrt((a_of(L / 2) * a_of(L / 2) + b_of(L / 2) * b_of(L / 2)) / 2);
  int K, rings;
  grid_size(faces, around, chain_length(profile), K, rings);
  const std::vector<P2> stations = resample_chain(profile, rings, false);

  Mesh mesh;
  mesh.V.reserve(3 * (2 + size_t(K) * rings));
  for (size_t i = 0; i < stations.size(); ++i) {
    const double t = stations[i].a, rho = stations[i].b / aref;
    const double tc = std::clamp(t, 0.0, L);
    const P3 T = tangent(tc);
    const P3 c = spine(tc) + (t - tc) * T;  // straight extension beyond the spine's ends
    const P3 ey{0, 1, 0};
    const P3 N1 = normalized(ey + (-T.y) * T), N2 = cross(T, N1);
    const bool is_pole = i == 0 || i + 1 == stations.size();
    for (int j = 0; j < (is_pole ? 1 : K); ++j) {
      const double phi = 2 * kPi * j / K;
      push(mesh.V, c + (rho * a_of(tc) * std::cos(phi)) * N1 + (rho * b_of(tc) * std::sin(phi)) * N2);
    }
  }
  mesh.F = pole_grid_faces(int(stations.size()) - 1, K);
  return mesh;
}

// Mug-handle-like torus standing in the x-z plane: an elliptic tube along an elliptic loop.
Mesh make_handle(size_t faces) {
  const double Ax = 7.5, Az = 10.5, a0 = 2.2, b = 3.5;
  auto spine = [&](double th) { return P3{Ax * std::cos(th), 0, Az * std::sin(th)}; };
  const ArcLength arc(0, 2 * kPi, spine);
  int m, M;
  grid_size(faces, 2 * kPi * std::sqrt((a0 * a0 + b * b) / 2), arc.total(), m, M);
  M = std::max(3, M);
  Mesh mesh;
  mesh.V.reserve(3 * size_t(M) * m);
  const P3 ey{0, 1, 0};
  for (int i = 0; i < M; ++i) {
    const double th = arc.at(arc.total() * i / M);
    const P3 c = spine(th), T = normalized({-Ax * std::sin(th), 0, Az * std::cos(th)}), N = cross(T, ey);
    const double a = a0 * (1 + 0.15 * std::cos(th));  // thicker on the outer leg
    for (int j = 0; j < m; ++j) {
      const double phi = 2 * kPi * j / m;
      push(mesh.V, c + (a * std::cos(phi)) * N + (b * std::sin(phi)) * ey);
    }
  }
  mesh.F = torus_grid_faces(M, m);
  return mesh;
}

// Uniform scale and z shift to z in [0, height]; the extreme vertices land exactly on 0 and height.
void fit_height(Mesh& mesh, double height) {
  double lo = mesh.V[2], hi = mesh.V[2];
  for (size_t i = 2; i < mesh.V.size(); i += 3) lo = std::min(lo, mesh.V[i]), hi = std::max(hi, mesh.V[i]);
  const double s = height / (hi - lo);
  for (size_t i = 0; i < mesh.V.size(); i += 3) {
    mesh.V[i] *= s;
    mesh.V[i + 1] *= s;
    const double z = mesh.V[i + 2];
    mesh.V[i + 2] = z == hi ? height : std::min(height, (z - lo) * s);
  }
}

}  // namespace

const std::vector<std::string>& family_shapes() {
  static const std::vector<std::string> names = {"arch", "ear", "handle", "box", "sphere", "torus"};
  return names;
}

int family_shape_genus(const std::string& shape) {
  if (shape == "handle" || shape == "torus") return 1;
  for (const std::string& s : family_shapes())
    if (s == shape) return 0;
  throw Error("unknown family shape '" + shape + "' (arch, ear, handle, box, sphere, torus)");
}

Mesh make_family_base(const FamilyOptions& o) {
  family_shape_genus(o.shape);
  if (o.faces < 500) throw Error("family: at least 500 faces needed, got " + std::to_string(o.faces));
  if (!(o.height > 0) || !std::isfinite(o.height)) throw Error("family: height must be a positive number of mm");
  Mesh mesh;
  const double f = double(o.faces);
  if (o.shape == "arch") {
    mesh = make_arch(o.faces);
  } else if (o.shape == "ear") {
    mesh = make_ear(o.faces);
  } else if (o.shape == "handle") {
    mesh = make_handle(o.faces);
  } else if (o.shape == "box") {
    mesh = make_box(-10, -6, 0, 10, 6, 14.5, std::max(1, int(std::lround(std::sqrt(f / 12)))));
  } else if (o.shape == "sphere") {
    const int rings = std::max(3, int(std::lround(0.5 + std::sqrt(f / 4 + 0.25))));
    mesh = make_sphere(7, rings, 2 * rings);
  } else {
    const double R = 10, r = 3.5;
    const int minor = std::max(3, int(std::lround(std::sqrt(f / 2 * r / R))));
    mesh = make_torus(R, r, std::max(3, int(std::lround(f / (2.0 * minor)))), minor);
  }
  orient_outward(mesh);
  fit_height(mesh, o.height);
  return mesh;
}

}  // namespace slicereuse::test
