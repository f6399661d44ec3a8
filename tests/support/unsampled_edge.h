#pragma once
// move_vertex_across_unsampled_edge: a member whose layer k passes the exact transfer's cheap
// certificate (the counts of straddling faces and the sample of two points per contour,
// transfer_contours.h) but not the whole one, for testing the path where only transferring the
// layer finds it changed.
//
// Input: the source's encoding (slices with an encoding and thickness) and a member of its
// family. Output: true, with *layer = k, after moving one vertex of member just below plane k:
// the upper end of the edge of a point of layer k that is neither the first nor the middle point
// of its contour, lying below plane k + 1, with as many neighbours at or above plane k as below
// it (so plane k keeps its count of straddling faces, as many as straddling edges on a closed
// mesh, and layer k its sampled points; the other planes see b where they did);
// false, member untouched, when no such vertex exists.
#include <cstddef>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/slicing/slices.h"

namespace slicereuse::test {

bool move_vertex_across_unsampled_edge(const Slices& source, Mesh& member, size_t* layer);

}  // namespace slicereuse::test
