#pragma once
// locate_support_points: support points from positions alone, each the nearest point of the
// mesh's surface to the given one (face and area coordinates; xyz and normal as
// place_support_points sets them). MeshLab's point layers carry only positions, which users may
// edit; the filters turn them back into support points with this. A uniform grid over the faces
// (SurfaceGrid) keeps each query to the faces near the point.
// Input: a valid mesh, 3 coordinates per point, and one kind per point (SupportKind) or none
// (all Overhang). Output: fingerprint of mesh, layer 0 for every point (no slicing is at hand).
// Throws Error when xyz is not a multiple of 3, kinds has another count or a kind other than 0
// or 1, a coordinate is not finite, or the mesh is not valid (validate_mesh).
#include <cstdint>
#include <vector>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/supports/support_points.h"

namespace slicereuse {

SupportPoints locate_support_points(const Mesh& mesh, const std::vector<double>& xyz, std::vector<uint8_t> kinds = {});

}  // namespace slicereuse
