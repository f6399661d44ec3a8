// The contour-walk rule (contour_step.h) against its definition on every arrangement of a face's
// corners around the plane: exit edge j has corner j below zk and corner j+1 at or above it,
// entry edge the reverse; the same edges from the lone corner and, entering by the entry edge,
// from next_exit_edge; and points on an edge, the same bits from both of its faces.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "slicereuse/slicing/contour_step.h"

using namespace slicereuse;

namespace {

constexpr double kZk = 1;
// A corner below the plane, at it (counts as above) or above it.
constexpr double kLevels[3] = {0, kZk, 2};

// The edges by their definition, by brute force over the local edges.
SectionEdges by_definition(const double z[3]) {
  SectionEdges e{kNoEdge, kNoEdge};
  for (uint32_t j = 0; j < 3; ++j) {
    const bool below = z[j] < kZk, next_below = z[(j + 1) % 3] < kZk;
    if (below && !next_below) e.exit = j;
    if (!below && next_below) e.entry = j;
  }
  return e;
}

}  // namespace

TEST(ContourStep, SectionEdgesFollowTheDefinitionForEveryArrangement) {
  const uint32_t F[3] = {0, 1, 2};
  int straddling = 0;
  for (double z0 : kLevels)
    for (double z1 : kLevels)
      for (double z2 : kLevels) {
        const double z[3] = {z0, z1, z2};
        const double V[9] = {0, 0, z0, 1, 0, z1, 0, 1, z2};
        const SectionEdges want = by_definition(z), got = section_edges(V, F, 0, kZk);
        EXPECT_EQ(got.entry, want.entry) << z0 << " " << z1 << " " << z2;
        EXPECT_EQ(got.exit, want.exit) << z0 << " " << z1 << " " << z2;
        EXPECT_EQ(got.entry == kNoEdge, got.exit == kNoEdge);
        if (got.exit == kNoEdge) continue;
        ++straddling;
        // The lone corner's form (the slicer's), from the corner alone on its side.
        const int n_below = (z0 < kZk) + (z1 < kZk) + (z2 < kZk);
        const bool lone_below = n_below == 1;
        uint32_t lone = 0;
        while ((z[lone] < kZk) != lone_below) ++lone;
        EXPECT_EQ(entry_edge_of_lone(lone, lone_below), got.entry);
        EXPECT_EQ(exit_edge_of_lone(lone, lone_below), got.exit);
        // Entered by its entry edge, the face is left by its exit edge.
        EXPECT_EQ(next_exit_edge(V, F, 0, got.entry, kZk), got.exit) << z0 << " " << z1 << " " << z2;
      }
  EXPECT_EQ(straddling, 27 - 8 - 1);  // all but all-below (1) and all-at-or-above (2^3)
}

TEST(ContourStep, AnEdgeGivesTheSamePointFromBothFaces) {
  // Faces 0 (0, 1, 2) and 1 (1, 0, 3) share the edge 0-1, which crosses the plane.
  const double V[12] = {0.1, 0.3, 0.2, 0.7, 0.9, 1.9, 0.3, -0.4, 1.7, 0.6, 1.2, 0.4};
  const uint32_t F[6] = {0, 1, 2, 1, 0, 3};
  const double zk = 0.7;
  const SectionEdges a = section_edges(V, F, 0, zk), b = section_edges(V, F, 1, zk);
  ASSERT_EQ(a.exit, 0u);   // corner 0 (vertex 0) below, corner 1 (vertex 1) above
  ASSERT_EQ(b.entry, 0u);  // corner 0 (vertex 1) above, corner 1 (vertex 0) below
  const EdgePoint p = exit_point(V, F, 0, a.exit, zk), q = entry_point(V, F, 1, b.entry, zk);
  EXPECT_EQ(p.x, q.x);
  EXPECT_EQ(p.y, q.y);
  EXPECT_EQ(p.t, q.t);
  EXPECT_GT(p.t, 0);
  EXPECT_LE(p.t, 1);
}
