#pragma once
// segment_distance2: the squared distance from point p to the segment ab, in the plane, in the
// units of the coordinates given (Clipper units as doubles, or mm). Doubles: the products of
// Clipper coordinates of up to 1e9 units would overflow 64-bit integers.
namespace slicereuse {

inline double segment_distance2(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay;
  const double qx = px - ax, qy = py - ay;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? (qx * dx + qy * dy) / len2 : 0;
  t = t < 0 ? 0 : (t > 1 ? 1 : t);
  const double ex = qx - t * dx, ey = qy - t * dy;
  return ex * ex + ey * ey;
}

}  // namespace slicereuse
