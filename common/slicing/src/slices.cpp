#include "slicereuse/slicing/slices.h"

#include <charconv>
#include <cmath>
#include <string>

#include "slicereuse/util/error.h"

namespace slicereuse {
namespace {

std::string num(uint64_t v) { return std::to_string(v); }

std::string real(double v) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

// Offsets must start at 0 and never decrease (strict: always increase).
template <class Offsets>
void check_offsets(const Offsets& b, size_t expected_size, bool strict, const char* name,
                   const char* item) {
  if (b.size() != expected_size)
    throw Error(std::string(name) + " has " + num(b.size()) + " entries, expected " +
                num(expected_size));
  if (b[0] != 0) throw Error(std::string(name) + "[0] is " + num(b[0]) + ", expected 0");
  for (size_t i = 0; i + 1 < b.size(); ++i) {
    if (b[i + 1] < b[i] || (strict && b[i + 1] == b[i]))
      throw Error(std::string(name) + " is not increasing at " + item + " " + num(i) + " (" +
                  num(b[i]) + " then " + num(b[i + 1]) + ")" +
                  (strict && b[i + 1] == b[i] ? ": it has no points" : ""));
  }
}

// Arrays of tens of millions of numbers are checked on all cores, and only when something is
// wrong searched again in order for the first culprit (the message names it). Small ones (a
// layer made where its mask is drawn is checked on that thread) on the calling thread: an
// OpenMP region there would cost a team of threads and their barrier, per layer.
constexpr long long kParallelFrom = 1 << 16;

template <class Array>
void check_finite(const Array& a, const char* name) {
  const long long n = static_cast<long long>(a.size());
  bool bad = false;
#pragma omp parallel for reduction(|| : bad) schedule(static) if (n >= kParallelFrom)
  for (long long i = 0; i < n; ++i) bad |= !std::isfinite(a[size_t(i)]);
  if (!bad) return;
  for (size_t i = 0; i < a.size(); ++i)
    if (!std::isfinite(a[i])) throw Error(std::string(name) + "[" + num(i) + "] is not finite");
}

}  // namespace

void layers_into(const Slices& s, size_t a, size_t b, Slices& out, bool with_points) {
  const size_t c0 = s.layer_begin[a], c1 = s.layer_begin[b];
  const size_t p0 = s.contour_begin[c0], points = s.contour_begin[c1] - p0;
  out.z_start = s.z_start + double(a) * s.thickness;
  out.thickness = s.thickness;
  out.fingerprint = s.fingerprint;
  out.layer_z.assign(s.layer_z.begin() + long(a), s.layer_z.begin() + long(b));
  out.layer_begin.resize(b - a + 1);
  for (size_t k = a; k <= b; ++k) out.layer_begin[k - a] = s.layer_begin[k] - c0;
  out.contour_begin.resize(c1 - c0 + 1);
  for (size_t c = c0; c <= c1; ++c) out.contour_begin[c - c0] = s.contour_begin[c] - p0;
  out.contour_open.assign(s.contour_open.begin() + long(c0), s.contour_open.begin() + long(c1));
  if (with_points)
    out.xyz.assign(s.xyz.begin() + long(3 * p0), s.xyz.begin() + long(3 * (p0 + points)));
  else
    out.xyz.resize(3 * points);
  out.face.clear();
  out.edge.clear();
  out.t.clear();
}

void append_layers(const Slices& s, size_t a, size_t b, Slices& out) {
  const size_t c0 = s.layer_begin[a], c1 = s.layer_begin[b];
  const size_t p0 = s.contour_begin[c0], p1 = s.contour_begin[c1];
  if (out.layer_begin.empty()) out.layer_begin.push_back(0);
  if (out.contour_begin.empty()) out.contour_begin.push_back(0);
  const uint64_t contours = out.contours(), points = out.points();
  out.layer_z.insert(out.layer_z.end(), s.layer_z.begin() + long(a), s.layer_z.begin() + long(b));
  for (size_t k = a + 1; k <= b; ++k) out.layer_begin.push_back(s.layer_begin[k] - c0 + contours);
  for (size_t c = c0 + 1; c <= c1; ++c) out.contour_begin.push_back(s.contour_begin[c] - p0 + points);
  out.contour_open.insert(out.contour_open.end(), s.contour_open.begin() + long(c0), s.contour_open.begin() + long(c1));
  out.xyz.insert(out.xyz.end(), s.xyz.begin() + long(3 * p0), s.xyz.begin() + long(3 * p1));
  out.face.clear();
  out.edge.clear();
  out.t.clear();
}

size_t Slices::open_contours() const {
  size_t n = 0;
  for (uint8_t o : contour_open) n += o != 0;
  return n;
}

double contour_area(const Slices& s, size_t c) {
  const uint64_t b = s.contour_begin[c], n = s.contour_begin[c + 1] - b;
  double area = 0;
  for (uint64_t i = 0; i < n; ++i) {
    const double* p = &s.xyz[3 * (b + i)];
    const double* q = &s.xyz[3 * (b + (i + 1 == n ? 0 : i + 1))];
    area += 0.5 * (p[0] * q[1] - q[0] * p[1]);
  }
  return area;
}

void validate_slices(const Slices& s, bool check_points) {
  if (!std::isfinite(s.z_start)) throw Error("z_start is not finite");
  if (!std::isfinite(s.thickness) || s.thickness <= 0)
    throw Error("layer thickness " + real(s.thickness) + " is not a positive number");
  check_finite(s.layer_z, "layer_z");
  const size_t L = s.layers(), C = s.contours();
  check_offsets(s.layer_begin, L + 1, false, "layer_begin", "layer");
  if (s.layer_begin.back() != C)
    throw Error("layer_begin ends at " + num(s.layer_begin.back()) + ", expected the " + num(C) +
                " contours");
  // An empty contour means nothing and could not be told apart from a blank line in text.
  check_offsets(s.contour_begin, C + 1, true, "contour_begin", "contour");
  for (size_t c = 0; c < C; ++c)
    if (s.contour_open[c] > 1)
      throw Error("contour_open[" + num(c) + "] is " + num(s.contour_open[c]) + ", expected 0 or 1");

  const size_t P = s.points();
  if (!s.xyz.empty()) {
    if (s.xyz.size() != 3 * P)
      throw Error("xyz has " + num(s.xyz.size()) + " numbers, expected 3 per point (" +
                  num(3 * P) + ")");
    if (check_points) check_finite(s.xyz, "xyz");
  }
  if (s.face.empty() && s.edge.empty() && s.t.empty()) return;
  if (s.face.size() != P || s.edge.size() != P || s.t.size() != P)
    throw Error("encoding arrays face/edge/t have " + num(s.face.size()) + "/" +
                num(s.edge.size()) + "/" + num(s.t.size()) + " entries, expected " + num(P));
  if (!check_points) return;
  bool bad = false;
#pragma omp parallel for reduction(|| : bad) schedule(static) if (P >= size_t(kParallelFrom))
  for (long long p = 0; p < static_cast<long long>(P); ++p)
    bad |= s.face[size_t(p)] >= s.fingerprint.faces || s.edge[size_t(p)] > 2 ||
           !(s.t[size_t(p)] > 0 && s.t[size_t(p)] <= 1);
  if (!bad) return;
  for (size_t p = 0; p < P; ++p) {
    if (s.face[p] >= s.fingerprint.faces)
      throw Error("face[" + num(p) + "] = " + num(s.face[p]) + " is not below the mesh's " +
                  num(s.fingerprint.faces) + " faces");
    if (s.edge[p] > 2) throw Error("edge[" + num(p) + "] = " + num(s.edge[p]) + " is not 0, 1 or 2");
    if (!(s.t[p] > 0 && s.t[p] <= 1))
      throw Error("t[" + num(p) + "] = " + real(s.t[p]) + " is outside (0, 1]");
  }
}

}  // namespace slicereuse
