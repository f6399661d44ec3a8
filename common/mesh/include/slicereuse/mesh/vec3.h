#pragma once
// vec3: difference, dot and cross product, length and squared distance of 3-vectors, for
// anything indexed [0], [1], [2] (pointers into flat V arrays, double[3], Vec3); results as
// Vec3. Each is one expression in the order written here, so a call gives the bytes of that
// expression written out at the call site (the map's bytes depend on it).
#include <array>
#include <cmath>

namespace slicereuse {

using Vec3 = std::array<double, 3>;

template <class A, class B>
inline Vec3 sub(const A& a, const B& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

template <class A, class B>
inline double dot(const A& a, const B& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <class A, class B>
inline Vec3 cross(const A& a, const B& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

template <class A>
inline double norm(const A& a) {
  return std::sqrt(dot(a, a));
}

template <class A, class B>
inline double squared_distance(const A& a, const B& b) {
  const Vec3 d = sub(a, b);
  return dot(d, d);
}

}  // namespace slicereuse
