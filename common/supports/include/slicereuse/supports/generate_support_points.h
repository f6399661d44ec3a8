#pragma once
// generate_support_points: the points a part needs so that every layer rests on the one below,
// found from its slicing, in the manner of PrusaSlicer's SLA SupportPointGenerator (our own
// code): each layer's region (layer_region.h) is compared with the layer below's:
//   islands:   a connected region of layer k (k > 0, or k = 0 when the part is raised off the
//              plate) that does not overlap layer k-1;
//   overhangs: the part of layer k farther than self_supporting_mm from layer k-1's region.
// Points are placed on those areas so that every point of an island or overhang lies within
// support_radius_mm() of a point of that layer (greedy cover of a lattice of candidates, then
// the area's boundary for slivers thinner than the lattice; cover_layer.h), no two points of a
// layer closer than minimal_distance_mm where that allows the cover (coverage wins), and every
// island has one. Each 2-D point becomes a point on
// the mesh: the downward-facing face above it between the two layers' planes (a vertical ray),
// with its area coordinates; failing that (a sliver's edge), the nearest contour point of layer
// k, on the face its encoding names.
//
// existing: points already there (a member's transferred points, on this mesh): an area they
// cover (their layer, layer[i], and support radius) gets none. The result is only the new points.
// Output: the new points, ordered by layer, fingerprint of mesh. Throws Error when the slicing
// has no points (xyz) or no encoding, or does not belong to mesh, or a count exceeds
// options.max_points ("... needs N support points, more than the limit of M").
#include <cstddef>
#include <limits>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/slicing/slices.h"
#include "slicereuse/supports/support_points.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

struct SupportPointOptions {
  // Farthest a layer may reach beyond the layer below without support.
  double self_supporting_mm = 0.5;
  // PrusaSlicer's support_points_density_relative / 100 and support_points_minimal_distance.
  double density_relative = 1.0;
  double minimal_distance_mm = 1.0;
  // Raised off the plate (support_object_elevation > 0): layer 0 is an island to support.
  bool raised = true;
  size_t max_points = 1000000;
  // A point covers its layer within this distance: minimal_distance_mm / sqrt(density_relative).
  double support_radius_mm() const;
};

SupportPoints generate_support_points(const Mesh& mesh, const Slices& slicing, const SupportPointOptions& options,
                                      const SupportPoints* existing = nullptr, const Progress& progress = {});

}  // namespace slicereuse
