#pragma once
// pillar_path: whether a support's way down is blocked by the part, by vertical rays.
//
// PartColumns indexes the part's faces in a uniform x-y grid over their bounding boxes (built
// once per support tree, about one face per cell), so that a vertical ray tests only the faces
// whose boxes cover its column.
// find_way_down looks below a support point at (x, y, z): the axis ray from just under the
// point (the point's own face is not a hit), and rays at kRimRays points on the circle of
// rim_radius around the axis from z_head_bottom (the head, narrower than the pillar, lies
// within that circle too; below the point a sloping surface of its own may lie within the rim
// above the head's bottom: the head zone covers that). A hit is a crossing of any face strictly
// between z_floor and the ray's start.
#include <cstdint>
#include <vector>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

class PartColumns {
 public:
  explicit PartColumns(const Mesh& part);
  // The highest z in (z_floor, z_from) where the vertical line through (x, y) meets a face of
  // the part (faces seen edge-on from above never do); NaN when there is none.
  double highest_hit(double x, double y, double z_from, double z_floor) const;

 private:
  const Mesh& part_;
  double x0_ = 0, y0_ = 0, cell_ = 1;
  int64_t nx_ = 1, ny_ = 1;
  std::vector<uint32_t> cell_begin_, cell_faces_;
  int64_t column(double v, double v0, int64_t n) const;
};

// Rays on the rim, besides the axis: 8, so that a surface between two of them rises at most
// rim_radius * (1 - cos(pi/8)) < 0.05 mm (a pixel) into the circle before one sees it.
constexpr int kRimRays = 8;

struct WayDown {
  // NaN when the way down to z_floor is clear; else the highest hit of any ray.
  double blocked_z;
  // The axis ray's highest hit (NaN when it has none); when above z_head_bottom, the head
  // itself reaches the part below.
  double axis_z;
};

WayDown find_way_down(const PartColumns& part, double x, double y, double z, double z_head_bottom, double z_floor,
                      double rim_radius);

}  // namespace slicereuse
