#pragma once
// straddling_edge_counts: for every plane k, how many edges of the mesh have one end below
// layer_z[k] and the other at or above it (the slicer's rule). A manifold edge counts once, each
// face side of a boundary or non-manifold edge counts once (see edge_links).
// O(edges + planes) through a difference array over each edge's range of planes; this is the
// count transfer_contours certifies a transferred layer against.
#include <cstdint>
#include <vector>

#include "slicereuse/edge_links.h"
#include "slicereuse/mesh.h"

namespace slicereuse {

std::vector<uint64_t> straddling_edge_counts(const Mesh& mesh, const EdgeLinks& links,
                                             const std::vector<double>& layer_z);

}  // namespace slicereuse
