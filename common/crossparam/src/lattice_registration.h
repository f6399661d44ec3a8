#pragma once
// register_on_lattice: non-rigid registration of a source surface onto a target surface, the
// core of cross_parameterize (iterative closest points with a smooth displacement field).
//
// Input: source vertex positions (3 per vertex, already roughly aligned, e.g. by a
// LandmarkWarp) with the source faces, a SurfaceGrid over the target, optional point
// constraints (source point -> target point, e.g. landmarks) and in_plane.
// Output: a DisplacementField d over space; source point p moves to p + d(p).
//
// The field is a polynomial part plus a lattice part. The polynomial part, fitted first with
// exact point-to-plane ICP, is (x, y, 1) times (1, z, z^2) per moved coordinate: it carries the
// smooth scale, shear, rotation, twist and bend between family members, which slide walls along
// themselves and which the lattice alone would recover only slowly. The lattice part lives on a
// regular lattice (about 2500 nodes over the bounding box) and is
// interpolated trilinearly, so walls that lie close together move together and the linear
// system stays small (a few thousand unknowns, independent of the mesh size). In each ICP
// iteration every sampled source vertex is paired with the nearest target point that faces the
// same way (normals within 60 degrees): with in_plane, on the target's level set at the vertex's
// own height, so d has no z component; otherwise anywhere on the surface. Pairs farther than a
// shrinking trust distance are dropped. The lattice part minimises the distance to each pair's
// linearized point-to-plane goal (plus a little point-to-point), weighted by vertex area, plus
// alpha times its bending energy (squared second differences, so affine changes cost nothing);
// its matrix is the same for every coordinate and iteration of a level, so Eigen's
// SimplicialLDLT factorizes it once per level; alpha decreases from level to level (stiff
// first, then detailed). Unpaired samples hold their place. Cost: 8 polynomial and 12 lattice
// iterations of nearest-point queries on at most 40000 sampled vertices.
#include <array>
#include <cstdint>
#include <vector>

#include "slicereuse/crossparam/surface_grid.h"
#include "slicereuse/mesh/mesh.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

class DisplacementField {
 public:
  DisplacementField() = default;
  DisplacementField(const double lo[3], double spacing, const int dims[3], int components);
  // out = p + d(p); points outside the lattice take the displacement of the nearest lattice point.
  void apply(const double p[3], double out[3]) const;

  // Polynomial part: d_c(p) += scale * sum_k poly[c][k] * basis_k(p), see polynomial_basis.
  static constexpr int kPolyTerms = 9;
  void set_polynomial_frame(const double centre[3], double scale, double z_scale);
  void polynomial_basis(const double p[3], double b[kPolyTerms]) const;
  double poly_scale() const { return poly_scale_; }
  double poly[3][kPolyTerms] = {};

  // Lattice nodes and the 8 nodes and weights of the cell holding p (trilinear).
  size_t nodes() const { return size_t(dims_[0]) * dims_[1] * dims_[2]; }
  void cell_weights(const double p[3], uint32_t node[8], double w[8]) const;
  int components() const { return components_; }
  const int* dims() const { return dims_; }
  std::vector<double>& values() { return d_; }  // components() per node

 private:
  double lo_[3] = {0, 0, 0}, h_ = 1;
  int dims_[3] = {1, 1, 1};
  int components_ = 0;
  std::vector<double> d_;
  double centre_[3] = {0, 0, 0}, poly_scale_ = 1, z_scale_ = 1;
};

struct RegistrationStats {
  double rms = 0;              // RMS distance of the accepted pairs in the last iteration (mm)
  double matched = 0;          // area fraction of sampled source vertices with an accepted pair
  int iterations = 0;
};

struct PointConstraint {
  std::array<double, 3> source, target;
};

DisplacementField register_on_lattice(const std::vector<double>& source_V, const std::vector<uint32_t>& source_F,
                                      const SurfaceGrid& target, const std::vector<PointConstraint>& constraints,
                                      bool in_plane, RegistrationStats* stats, const Progress& progress);

}  // namespace slicereuse
