#pragma once
// DownwardFaces: a uniform x-y grid over the bounding boxes of a mesh's downward-facing faces
// (unit normal z < 0), for vertical rays from below: where a support point under (x, y) meets
// the part. Built once per generation; queries are const and thread safe.
//
// hit(x, y, span, inner): the lowest face whose projection holds (x, y) and whose height there
// lies in inner (lo, hi], else the lowest in span [lo, hi] (ties: the lower face id); false when
// none. bary are its area coordinates at (x, y), clamped to [0, 1] and summing to 1.
#include <cstdint>
#include <vector>

#include "slicereuse/mesh/mesh.h"
#include "support_areas.h"

namespace slicereuse {

class DownwardFaces {
 public:
  explicit DownwardFaces(const Mesh& mesh);
  bool hit(double x, double y, const LayerSpan& span, const LayerSpan& inner, uint32_t& face, double bary[3]) const;

 private:
  const Mesh& mesh_;
  double x0_ = 0, y0_ = 0, cell_ = 1;
  int nx_ = 0, ny_ = 0;
  std::vector<uint32_t> begin_, faces_;  // CSR: faces whose box meets each cell
};

}  // namespace slicereuse
