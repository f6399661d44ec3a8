#pragma once
// layer_planes: the planes of a slicing, and which planes a z interval straddles.
//
// layer_planes(z_start, h, zmax) returns layer_z[k] = z_start + (k + 1/2)*h for every k >= 0
// with z_start + k*h < zmax (that is, ceil((zmax - z_start)/h) layers, decided by the same
// floating-point expression everywhere). Throws Error for h <= 0, non-finite input, no layer,
// or more than kMaxLayers layers (so a typo in units cannot exhaust memory).
// first_plane_above(layer_z, z) is the first k with layer_z[k] > z (layer_z.size() if none),
// for any increasing layer_z, O(1) when evenly spaced:
// a vertex at z is below plane k exactly when k >= first_plane_above(z).
#include <cstddef>
#include <vector>

namespace slicereuse {

// 10 million layers: 10 m of part at 1 um. More is a unit mistake, and would need gigabytes
// before the first contour point.
constexpr size_t kMaxLayers = 10'000'000;

// Plane k of a slicing from z_start, the one expression every plane comes from; k may be
// negative (a build plate's layers below a part's z_start: plate_job.h).
inline double layer_plane(double z_start, double thickness, double k) { return z_start + (k + 0.5) * thickness; }

std::vector<double> layer_planes(double z_start, double thickness, double zmax);

size_t first_plane_above(const std::vector<double>& layer_z, double z);

}  // namespace slicereuse
