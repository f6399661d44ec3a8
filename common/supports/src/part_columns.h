#pragma once
// PartColumns: a part's faces but its walls (unit normal z within kWallNormalZ of 0: seen
// edge-on from above, a ray's height on them is ill-conditioned and a point there is on a side,
// not under the part), or only its downward-facing ones (unit normal z < -kWallNormalZ), and
// only those reaching below z_below, when given (rays from points below that height meet no
// other), in a uniform x-y grid over their bounding boxes (about one face per cell), so that a
// vertical ray tests only the faces whose boxes cover its column. Built once per support tree
// or generation of support points; queries are const and thread safe.
// for_each_hit(x, y, hit) calls hit(face, l, z) for each face of the column, in face order,
// whose projection holds (x, y), edges included within kEdgeTolerance (area coordinates that
// far below 0: rounding, a contour a hair outside the face): l its area coordinates there
// (clamped to [0, 1], corner order, summing to 1), z the face's height there. highest_hit: the
// highest such z in (z_floor, z_from) (walls never count); NaN when there is none.
// lowest_hit_above: the lowest such z above z_from; NaN when there is none.
// inside: whether (x, y, z) lies inside the (closed, outward) part, all its faces kept: the
// lowest face above it faces up (walls aside, a vertical ray enters the part through a face
// facing down and leaves it through one facing up).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

// A face steeper than 89.99994 degrees is a wall (a mesh's rounding leans vertical ones).
constexpr double kWallNormalZ = 1e-6;
// Relative to the face: 1e-9 of a 10 mm face is 1e-8 mm, far below any feature.
constexpr double kEdgeTolerance = 1e-9;

class PartColumns {
 public:
  explicit PartColumns(const Mesh& part, bool downward_only = false, double z_below = INFINITY);
  double highest_hit(double x, double y, double z_from, double z_floor) const;
  double lowest_hit_above(double x, double y, double z_from) const;
  bool inside(double x, double y, double z) const;
  template <class Hit>
  void for_each_hit(double x, double y, Hit&& hit) const;

 private:
  const Mesh& part_;
  double x0_ = 0, y0_ = 0, cell_ = 1;
  int64_t nx_ = 1, ny_ = 1;
  std::vector<uint32_t> cell_begin_, cell_faces_;
  int64_t column(double v, double v0, int64_t n) const;
};

template <class Hit>
void PartColumns::for_each_hit(double x, double y, Hit&& hit) const {
  const double cx = std::floor((x - x0_) / cell_), cy = std::floor((y - y0_) / cell_);
  if (cx < 0 || cy < 0 || cx >= double(nx_) || cy >= double(ny_)) return;
  const size_t c = size_t(cy) * size_t(nx_) + size_t(cx);
  for (uint32_t i = cell_begin_[c]; i < cell_begin_[c + 1]; ++i) {
    const uint32_t* f = &part_.F[3 * size_t(cell_faces_[i])];
    const double* a = &part_.V[3 * size_t(f[0])];
    const double* b = &part_.V[3 * size_t(f[1])];
    const double* d = &part_.V[3 * size_t(f[2])];
    // Never 0: walls are not kept.
    const double area = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    const double la = ((b[0] - x) * (d[1] - y) - (b[1] - y) * (d[0] - x)) / area;
    const double lb = ((d[0] - x) * (a[1] - y) - (d[1] - y) * (a[0] - x)) / area;
    const double ld = 1 - la - lb;
    if (la < -kEdgeTolerance || lb < -kEdgeTolerance || ld < -kEdgeTolerance) continue;
    const double ca = std::max(la, 0.0), cb = std::max(lb, 0.0), cd = std::max(ld, 0.0), sum = ca + cb + cd;
    const double l[3] = {ca / sum, cb / sum, cd / sum};
    hit(cell_faces_[i], l, la * a[2] + lb * b[2] + ld * d[2]);
  }
}

}  // namespace slicereuse
