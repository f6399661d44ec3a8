#include "slicereuse/landmark_warp.h"

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "slicereuse/error.h"

namespace slicereuse {

LandmarkWarp::LandmarkWarp(const std::vector<std::array<double, 3>>& source,
                           const std::vector<std::array<double, 3>>& target, bool in_plane)
    : in_plane_(in_plane), centres_(source) {
  const size_t n = source.size();
  if (n != target.size())
    throw Error("landmarks: " + std::to_string(n) + " source and " + std::to_string(target.size()) +
                " target points, they must correspond one to one");
  if (n < 3) throw Error("landmarks: at least 3 corresponding pairs are needed, got " + std::to_string(n));
  // The affine part acts along the landmarks' principal directions: all three when they span
  // space, the two of their plane when they are coplanar (e.g. exactly 3 landmarks).
  Eigen::MatrixXd X(n, 3);
  for (size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) origin_[a] += source[i][a] / double(n);
  for (size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) X(Eigen::Index(i), a) = source[i][a] - origin_[a];
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(X, Eigen::ComputeFullV);
  const Eigen::Vector3d sv = svd.singularValues();
  if (!(sv(0) > 0)) throw Error("landmarks: the source landmarks all coincide");
  int rank = 0;
  for (int a = 0; a < 3; ++a) rank += sv(a) > 1e-6 * sv(0);
  if (rank < 2) throw Error("landmarks: the source landmarks lie on one line; at least 3 must span a plane");
  for (int a = 0; a < rank; ++a) axes_.push_back({svd.matrixV()(0, a), svd.matrixV()(1, a), svd.matrixV()(2, a)});

  const Eigen::Index m = Eigen::Index(n) + 1 + rank;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(m, m);
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(m, 3);
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Index r = Eigen::Index(i);
    for (size_t j = 0; j < n; ++j) {
      double d2 = 0;
      for (int a = 0; a < 3; ++a) d2 += (source[i][a] - source[j][a]) * (source[i][a] - source[j][a]);
      if (i != j && d2 == 0) throw Error("landmarks: two source landmarks are at the same point");
      A(r, Eigen::Index(j)) = std::sqrt(d2);
    }
    A(r, Eigen::Index(n)) = A(Eigen::Index(n), r) = 1;
    for (int k = 0; k < rank; ++k) {
      const double u = X(r, 0) * axes_[k][0] + X(r, 1) * axes_[k][1] + X(r, 2) * axes_[k][2];
      A(r, Eigen::Index(n) + 1 + k) = A(Eigen::Index(n) + 1 + k, r) = u;
    }
    for (int a = 0; a < 3; ++a) b(r, a) = target[i][a];
  }
  const Eigen::MatrixXd x = A.fullPivLu().solve(b);
  if (!x.allFinite() || !(A * x).isApprox(b, 1e-6))
    throw Error("landmarks: the landmark positions do not determine a warp (degenerate configuration)");
  weights_.resize(n);
  for (size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) weights_[i][a] = x(Eigen::Index(i), a);
  poly_.resize(1 + rank);
  for (int k = 0; k <= rank; ++k)
    for (int a = 0; a < 3; ++a) poly_[k][a] = x(Eigen::Index(n) + k, a);
}

void LandmarkWarp::apply(const double p[3], double out[3]) const {
  double r[3];
  for (int a = 0; a < 3; ++a) r[a] = poly_[0][a];
  for (size_t k = 0; k < axes_.size(); ++k) {
    const double u = (p[0] - origin_[0]) * axes_[k][0] + (p[1] - origin_[1]) * axes_[k][1] +
                     (p[2] - origin_[2]) * axes_[k][2];
    for (int a = 0; a < 3; ++a) r[a] += u * poly_[k + 1][a];
  }
  for (size_t i = 0; i < centres_.size(); ++i) {
    const double d = std::sqrt((p[0] - centres_[i][0]) * (p[0] - centres_[i][0]) +
                               (p[1] - centres_[i][1]) * (p[1] - centres_[i][1]) +
                               (p[2] - centres_[i][2]) * (p[2] - centres_[i][2]));
    for (int a = 0; a < 3; ++a) r[a] += d * weights_[i][a];
  }
  out[0] = r[0];
  out[1] = r[1];
  out[2] = in_plane_ ? p[2] : r[2];
}

}  // namespace slicereuse
