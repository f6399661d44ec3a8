#pragma once
// edge_links: face adjacency through manifold edges, as one flat array.
//
// Input: a mesh. Output: for every face f and local edge j (corners j -> (j+1)%3),
// links[3f+j] = (g << 2) | i when the directed edge u->v of f is used by no other face and
// its reverse v->u by exactly one face g, as g's local edge i; otherwise kUnlinked (a boundary
// edge, a non-manifold edge, or an edge whose two faces disagree in orientation).
// Linked pairs are symmetric. The slicer chains contours through links only, so a contour can
// be followed without comparing coordinates, and every unlinked edge ends an open polyline.
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
