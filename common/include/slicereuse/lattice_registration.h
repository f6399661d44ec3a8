#pragma once
// register_on_lattice: non-rigid registration of a source surface onto a target surface, the
// core of cross_parameterize (iterative closest points with a smooth displacement field).
//
// Input: source vertex positions (3 per vertex, already roughly aligned, e.g. by a
// LandmarkWarp) with the source faces, a SurfaceGrid over the target, optional point
// constraints (source point -> target point, e.g. landmarks) and in_plane.
// Output: a DisplacementField d over space; source point p moves to p + d(p).
//
// The field lives on a regular lattice (about 20 cells along the longest side) and is
// interpolated trilinearly, so walls that lie close together move together and the linear
// system stays small (a few thousand unknowns, independent of the mesh size). In each ICP
// iteration every sampled source vertex is paired with the nearest target point that faces the
// same way (normals within 60 degrees): with in_plane, on the target's level set at the vertex's
// own height, so d has no z component; otherwise anywhere on the surface. Pairs farther than a
// shrinking trust distance are dropped. The field minimises point-to-plane plus a little
// point-to-point distance, weighted by vertex area, plus alpha times its bending energy
// (squared second differences on the lattice, so affine changes cost nothing), solved with
// Eigen's SimplicialLDLT; alpha decreases from level to level (stiff first, then detailed).
#include <array>
#include <cstdint>
#include <vector>

#include "slicereuse/mesh.h"
#include "slicereuse/progress.h"
#include "slicereuse/surface_grid.h"

namespace slicereuse {

class DisplacementField {
 public:
  DisplacementField() = default;
  DisplacementField(const double lo[3], double spacing, const int dims[3], int components);
  // out = p + d(p); points outside the lattice take the displacement of the nearest lattice point.
  void apply(const double p[3], double out[3]) const;

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
