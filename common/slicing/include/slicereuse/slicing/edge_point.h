#pragma once
// edge_point: where the plane z = zk cuts the edge from vertex a (below: za < zk) to vertex b
// (at or above: zb >= zk). Returns x, y and t in (0, 1] with p = (1-t)*a + t*b.
// Always evaluated from the lower vertex to the upper one, so the same edge gives bit-identical
// points whichever face it is reached from, in slicing and in transfer alike; the point's z is
// set to zk exactly by the callers.
namespace slicereuse {

struct EdgePoint {
  double x, y, t;
};

inline EdgePoint edge_point(const double* a, const double* b, double zk) {
  const double t = (zk - a[2]) / (b[2] - a[2]);
  return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), t};
}

}  // namespace slicereuse
