#pragma once
// mesh_defects: what in a mesh from a scanner or design tool will show in its slicing, counted
// so that a filter can say why a part gives open contours or none at all.
//
// Input: a mesh whose indices are in range (validate_mesh's index checks; coordinates may be
// anything). Output: counts (and the first offender of each kind, for the message):
//   non_finite_vertices    vertices with a NaN or infinite coordinate
//   repeated_vertex_faces  faces naming one vertex twice (a, a, b)
//   zero_area_faces        other faces whose corners are collinear (exactly: zero cross product)
//   duplicate_faces        faces with the same three vertices as an earlier face, in any order
//   boundary_edges         edges of exactly one face: the rims of holes
//   non_manifold_edges     edges of three or more faces
// The slicer keeps working on all of them: open polylines end at boundary edges and at
// non-manifold edges not used as often one way as the other (edge_links.h; a duplicate face
// doubles its edges one way), and are flagged and counted.
// describe_mesh_defects gives one line naming each kind found, "" for a clean mesh.
#include <cstdint>
#include <string>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

struct MeshDefects {
  static constexpr uint64_t kNone = ~uint64_t(0);
  uint64_t non_finite_vertices = 0, first_non_finite_vertex = kNone;
  uint64_t repeated_vertex_faces = 0, first_repeated_vertex_face = kNone;
  uint64_t zero_area_faces = 0, first_zero_area_face = kNone;
  uint64_t duplicate_faces = 0, first_duplicate_face = kNone;
  uint64_t boundary_edges = 0;
  uint64_t non_manifold_edges = 0;

  bool clean() const {
    return non_finite_vertices + repeated_vertex_faces + zero_area_faces + duplicate_faces + boundary_edges +
               non_manifold_edges == 0;
  }
};

MeshDefects find_mesh_defects(const Mesh& mesh);

std::string describe_mesh_defects(const MeshDefects& d);

}  // namespace slicereuse
