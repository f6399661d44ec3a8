#pragma once
// LandmarkWarp: the affine map of space that carries the source landmarks closest (least
// squares) onto their target landmarks, the initial alignment of cross_parameterize.
//
// Input: n >= 3 landmark pairs (source[i] -> target[i]) that are not collinear, and in_plane:
// then only x and y are moved, as affine functions of (x, y, z), and z is kept, so every point
// stays in its own plane z = const. The affine part acts along the source landmarks' principal
// directions: all three when they span space, the two of their plane when they are coplanar
// (e.g. exactly 3 landmarks). Why affine and not an interpolating (thin-plate) warp: the
// registration that follows corrects the rest, and an interpolating warp bends the surface
// between landmarks along itself, a sliding that the registration can hardly see to undo.
// Output: the warp, applied by apply(). Throws Error for too few, collinear or coincident
// landmarks, naming the problem.
#include <array>
#include <vector>

namespace slicereuse {

class LandmarkWarp {
 public:
  LandmarkWarp(const std::vector<std::array<double, 3>>& source, const std::vector<std::array<double, 3>>& target,
               bool in_plane);
  void apply(const double p[3], double out[3]) const;

 private:
  bool in_plane_;
  double origin_[3] = {0, 0, 0};
  std::vector<std::array<double, 3>> axes_;  // principal directions (2 or 3)
  std::vector<std::array<double, 3>> poly_;  // constant, then one row per axis
};

}  // namespace slicereuse
