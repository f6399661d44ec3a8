#include "landmark_warp.h"

#include <Eigen/Dense>
#include <string>

#include "slicereuse/util/error.h"

namespace slicereuse {

LandmarkWarp::LandmarkWarp(const std::vector<std::array<double, 3>>& source,
                           const std::vector<std::array<double, 3>>& target, bool in_plane)
    : in_plane_(in_plane) {
  const size_t n = source.size();
  if (n != target.size())
    throw Error("landmarks: " + std::to_string(n) + " source and " + std::to_string(target.size()) +
                " target points, they must correspond one to one");
  if (n < 3) throw Error("landmarks: at least 3 corresponding pairs are needed, got " + std::to_string(n));
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

  Eigen::MatrixXd A(Eigen::Index(n), 1 + rank), b(Eigen::Index(n), 3);
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Index r = Eigen::Index(i);
    A(r, 0) = 1;
    for (int k = 0; k < rank; ++k) A(r, 1 + k) = X.row(r).dot(Eigen::Vector3d(axes_[k][0], axes_[k][1], axes_[k][2]));
    for (int a = 0; a < 3; ++a) b(r, a) = target[i][a];
  }
  const Eigen::MatrixXd x = A.colPivHouseholderQr().solve(b);
  if (!x.allFinite()) throw Error("landmarks: the landmark positions do not determine an alignment");
  poly_.resize(1 + rank);
  for (int k = 0; k <= rank; ++k)
    for (int a = 0; a < 3; ++a) poly_[k][a] = x(k, a);
}

void LandmarkWarp::apply(const double p[3], double out[3]) const {
  double r[3];
  for (int a = 0; a < 3; ++a) r[a] = poly_[0][a];
  for (size_t k = 0; k < axes_.size(); ++k) {
    const double u = (p[0] - origin_[0]) * axes_[k][0] + (p[1] - origin_[1]) * axes_[k][1] +
                     (p[2] - origin_[2]) * axes_[k][2];
    for (int a = 0; a < 3; ++a) r[a] += u * poly_[k + 1][a];
  }
  out[0] = r[0];
  out[1] = r[1];
  out[2] = in_plane_ ? p[2] : r[2];
}

}  // namespace slicereuse
