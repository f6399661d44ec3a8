#pragma once
// layer_chunks: splits a slicing's layers into consecutive ranges whose contour points fit a
// memory budget, so that a job whose whole stack would not fit in memory (Make Print Job at a
// fine layer on a large part) is sliced and exported a range at a time.
//
// Input: a mesh, the increasing plane heights (layer_planes.h), the budget in bytes for one
// range's contour points, and the bytes each point takes.
// Output: the range starts followed by the layer count, {0, k1, ..., L}: one range {0, L} when
// everything fits. A layer's point count is the number of faces its plane crosses (one contour
// point per crossed face: exact for closed contours, one short per open polyline), counted in
// O(faces + layers) before anything is sliced. A layer larger than the budget is a range of its
// own. A budget of 0 means unknown: one range.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

std::vector<size_t> layer_chunks(const Mesh& mesh, const std::vector<double>& planes, uint64_t budget_bytes,
                                 size_t bytes_per_point);

// The same for several meshes sliced on the same planes, a layer's points being all of theirs
// (a build plate of members, plate_job.h).
std::vector<size_t> layer_chunks(const std::vector<const Mesh*>& meshes, const std::vector<double>& planes,
                                 uint64_t budget_bytes, size_t bytes_per_point);

// The same from each layer's point count, known already (layer_points.size() layers).
std::vector<size_t> layer_chunks(const std::vector<uint64_t>& layer_points, uint64_t budget_bytes,
                                 size_t bytes_per_point);

}  // namespace slicereuse
