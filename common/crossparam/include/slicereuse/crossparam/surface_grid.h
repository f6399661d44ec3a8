#pragma once
// SurfaceGrid: a uniform 3D grid over a mesh's faces for nearest-point queries on the surface,
// either on one level set (the section by a plane z = const) or anywhere in 3D.
//
// Input: a valid mesh (it must outlive the grid) and a cell size (0: chosen from the mesh's
// mean edge length). Output of a query: the nearest surface point as face + barycentric
// coordinates (bary[j] belongs to corner j of the face), its xyz and its distance, among the
// faces whose unit normal n_f satisfies dot(n_f, normal) >= min_dot (pass normal = nullptr to
// accept every face), within max_distance; face = kNoFace when there is none.
//
// nearest_on_level looks only at faces that straddle z (lowest corner <= z <= highest corner)
// and measures distance in xy: the point returned lies on the face's segment in the plane z, so
// its interpolated z equals z up to rounding. Why a grid: a level query then visits only the
// one slab of cells that holds z, and rings of cells around (x, y) in it.
// Queries are const and thread safe.
#include <cstdint>
#include <vector>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

constexpr uint32_t kNoFace = 0xffffffffu;

struct SurfacePoint {
  uint32_t face = kNoFace;
  double bary[3] = {0, 0, 0};
  double xyz[3] = {0, 0, 0};
  double distance = 0;
};

class SurfaceGrid {
 public:
  SurfaceGrid(const Mesh& mesh, double cell_size = 0);

  SurfacePoint nearest_on_level(const double p[3], double z, const double* normal, double min_dot,
                                double max_distance) const;
  SurfacePoint nearest_on_surface(const double p[3], const double* normal, double min_dot,
                                  double max_distance) const;

  double cell_size() const { return h_; }
  double mean_edge() const { return mean_edge_; }
  const std::vector<double>& face_normals() const { return normal_; }  // 3 per face, unit

 private:
  size_t cell_of(const double p[3], int c[3]) const;
  double unvisited_bound(const double p[3], const int c[3], int r, int axes) const;
  const Mesh& mesh_;
  double lo_[3] = {0, 0, 0}, h_ = 1, mean_edge_ = 0;
  int n_[3] = {1, 1, 1};
  std::vector<uint32_t> begin_, faces_;  // CSR: faces overlapping each cell
  std::vector<double> zlo_, zhi_, normal_;
};

}  // namespace slicereuse
