#pragma once
// edge_links: face adjacency through manifold edges, as one flat array.
//
// Input: a mesh. Output: for every face f and local edge j (corners j -> (j+1)%3),
// links[3f+j] = (g << 2) | i when the directed edge u->v of f has a reverse v->u in face g, as
// g's local edge i: the only one when the edge is manifold; when it is shared by more faces (closed
// shells touching along it, as an STL file's shared corners make them) but as many use u->v as
// v->u, the r-th half-edge u->v (in half-edge order) is linked to the r-th v->u. Otherwise
// kUnlinked (a boundary edge, or an edge whose faces disagree in orientation).
// Linked pairs are symmetric. The slicer chains contours through links only, so a contour can
// be followed without comparing coordinates, and every unlinked edge ends an open polyline.
// Pairing the half-edges of a shared edge any way gives closed loops of the same oriented
// segments, so the same winding numbers: the nonzero rule fills the union of the shells.
#include <cstdint>
#include <vector>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

constexpr uint32_t kUnlinked = 0xffffffffu;

struct EdgeLinks {
  std::vector<uint32_t> links;  // 3 * faces
  size_t unlinked = 0;          // number of unlinked face edges
};

EdgeLinks edge_links(const Mesh& mesh);

}  // namespace slicereuse
