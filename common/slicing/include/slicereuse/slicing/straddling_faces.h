#pragma once
// straddling_face_counts: for every plane k, how many faces of the mesh have a corner below
// layer_z[k] and a corner at or above it (the slicer's rule). O(faces + planes) through a
// difference array over each face's range of planes.
//
// This is the count transfer_contours certifies a transferred layer against (and the points per
// layer that layer_chunks budgets). Each straddling
// face has exactly two crossing edges, so the target's crossing edges, counted once per face
// side, number twice its straddling faces. A closed layer of the source has one point per
// edge, on manifold edges only (two face sides each); when every one of those edges still
// crosses in the target, the target has no other crossing edge exactly when its straddling
// faces number the layer's points. No adjacency is needed.
#include <cstdint>
#include <vector>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

std::vector<uint64_t> straddling_face_counts(const Mesh& mesh, const std::vector<double>& layer_z);

}  // namespace slicereuse
