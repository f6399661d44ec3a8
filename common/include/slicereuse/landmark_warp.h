#pragma once
// LandmarkWarp: a smooth warp of space that carries each source landmark exactly onto its
// target landmark: an affine part plus a 3D thin-plate residual (radial basis |p - s_i|), the
// initial alignment of cross_parameterize.
//
// Input: n >= 3 landmark pairs (source[i] -> target[i]) that are not collinear, and in_plane:
// then only x and y are warped, as functions of (x, y, z), and z is kept, so the warp moves
// every point within its own plane z = const (the landmarks' z differences are ignored).
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
  std::vector<std::array<double, 3>> centres_;
  std::vector<std::array<double, 3>> weights_;  // radial weights per landmark and coordinate
  double origin_[3] = {0, 0, 0};
  std::vector<std::array<double, 3>> axes_;     // polynomial directions (2 or 3)
  std::vector<std::array<double, 3>> poly_;     // constant, then one row per axis
};

}  // namespace slicereuse
