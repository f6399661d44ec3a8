#pragma once
// contour_step: the contour-walk rule, how the section of a mesh at plane z = zk crosses its
// faces. Direct slicing (slice_layers), contour tracing (trace_contour) and transfer through a
// map (transfer_through_map) all walk by these functions, and exact transfer equals direct
// slicing only because they do.
//
// Local edge j of a face joins corners j and (j+1)%3. A face straddles zk when a corner is below
// zk and another at or above it (a corner at zk counts as above). Then exactly one corner is
// alone on its side: the lone corner. The section crosses the face from its entry edge (corner j
// at or above, (j+1)%3 below) to its exit edge (corner j below, (j+1)%3 at or above); with
// outward normals this runs outer loops counter-clockwise seen from +z.
//   lone corner below zk:          entry edge (lone+2)%3, exit edge lone
//   lone corner at or above zk:    entry edge lone,       exit edge (lone+2)%3
// The walk leaves a face by its exit edge into the neighbour across it (edge_links.h), which it
// enters by that neighbour's local edge sg; next_exit_edge gives the neighbour's exit edge.
// Points are computed on an edge from its corner below to its corner at or above (edge_point),
// so an edge gives the same point bit for bit from both faces.
//
// section_edges applies the definition to a face met from scratch; the slicer, which knows each
// face's lone corner per range of planes, uses entry_edge_of_lone / exit_edge_of_lone; walks use
// next_exit_edge (tests/unit/test_contour_step.cpp checks they agree on every arrangement).
//
// Input: the mesh's flat arrays V (3 doubles per vertex) and F (3 corners per face), a face, an
// edge, zk. Output: edges as local edge numbers, points as EdgePoint. Inline: these run in the
// slicer's innermost loop, and in this form they compile as tightly as code written in place.
#include <cstddef>
#include <cstdint>

#include "slicereuse/slicing/edge_point.h"

namespace slicereuse {

constexpr uint32_t kNoEdge = 3;

inline uint32_t entry_edge_of_lone(uint32_t lone, bool lone_below) { return lone_below ? (lone + 2) % 3 : lone; }
inline uint32_t exit_edge_of_lone(uint32_t lone, bool lone_below) { return lone_below ? lone : (lone + 2) % 3; }

inline const double* corner_of(const double* V, const uint32_t* F, uint32_t f, uint32_t corner) {
  return V + 3 * size_t(F[3 * size_t(f) + corner]);
}

// The entry and exit edges of face f at zk; both kNoEdge when f does not straddle zk.
struct SectionEdges {
  uint32_t entry, exit;
};
inline SectionEdges section_edges(const double* V, const uint32_t* F, uint32_t f, double zk) {
  const bool below[3] = {corner_of(V, F, f, 0)[2] < zk, corner_of(V, F, f, 1)[2] < zk, corner_of(V, F, f, 2)[2] < zk};
  SectionEdges e{kNoEdge, kNoEdge};
  for (uint32_t j = 0; j < 3; ++j) {
    if (below[j] && !below[(j + 1) % 3]) e.exit = j;
    if (!below[j] && below[(j + 1) % 3]) e.entry = j;
  }
  return e;
}

// The exit edge of face g entered by its local edge sg: corner sg is at or above zk and corner
// (sg+1)%3 below, so the third corner decides which of them is the lone corner: (sg+1)%3 (below,
// exit edge (sg+1)%3) when the third is at or above zk, else sg (above, exit edge the third's).
inline uint32_t next_exit_edge(const double* V, const uint32_t* F, uint32_t g, uint32_t sg, double zk) {
  const uint32_t third = (sg + 2) % 3;
  return corner_of(V, F, g, third)[2] >= zk ? (sg + 1) % 3 : third;
}

// Where the section crosses face f's exit edge j (t from corner j), and its entry edge j (t from
// corner (j+1)%3, the corner below).
inline EdgePoint exit_point(const double* V, const uint32_t* F, uint32_t f, uint32_t j, double zk) {
  return edge_point(corner_of(V, F, f, j), corner_of(V, F, f, (j + 1) % 3), zk);
}
inline EdgePoint entry_point(const double* V, const uint32_t* F, uint32_t f, uint32_t j, double zk) {
  return edge_point(corner_of(V, F, f, (j + 1) % 3), corner_of(V, F, f, j), zk);
}

}  // namespace slicereuse
