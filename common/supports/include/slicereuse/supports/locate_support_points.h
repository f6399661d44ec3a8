#pragma once
// locate_support_points: support points from positions alone, each the nearest point of the
// mesh's surface to the given one (face and area coordinates; xyz and normal as
// place_support_points sets them). MeshLab's point layers carry only positions, which users may
// edit; the filters turn them back into support points with this. A uniform grid over the faces
// (SurfaceGrid) keeps each query to the faces near the point.
// Input: a valid mesh, 3 coordinates per point, one kind per point (SupportKind) or none (all
// Overhang), and how far a point may lie from the surface (user points: kUserPointReachMm).
// Output: fingerprint of mesh, layer 0 for every point (no slicing is at hand).
// Throws Error when xyz is not a multiple of 3, kinds has another count or a kind other than 0
// or 1, a coordinate is not finite, the mesh is not valid (validate_mesh), or a point lies
// farther than max_distance_mm from the surface ("support point 3 at (x, y, z) mm is 2.5 mm
// from the mesh's surface, farther than the 1 mm ...": another mesh's points, or moved off it);
// noun names the points in messages (drain holes are located the same way).
#include <cmath>
#include <cstdint>
#include <vector>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/supports/support_points.h"

namespace slicereuse {

// How far a user's point may lie from the surface it is moved onto (PrusaSlicer caps its
// manual points' distance to the mesh at 1 mm).
constexpr double kUserPointReachMm = 1;

SupportPoints locate_support_points(const Mesh& mesh, const std::vector<double>& xyz, std::vector<uint8_t> kinds = {},
                                    double max_distance_mm = INFINITY, const char* noun = "support point");

}  // namespace slicereuse
