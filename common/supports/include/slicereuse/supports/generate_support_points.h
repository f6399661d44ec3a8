#pragma once
// generate_support_points: the points a part needs so that every layer rests on the one below,
// found from its slicing, in the manner of PrusaSlicer's SLA SupportPointGenerator (our own
// code): each layer's region (layer_region.h) is compared with the layer below's:
//   islands:   a connected part of layer k that rests on layer k-1 with less than half its area
//              (k > 0; UVtools' island check asks a quarter of its pixels), or every part of
//              layer 0 when the part is raised off the plate;
//   overhangs: the part of layer k reaching farther than the larger of thickness /
//              tan(critical_angle_deg) and thickness x tan(75 degrees) beyond layer k-1's region:
//              the surface flatter than the critical angle and than 15 degrees;
//   slopes:    the surface between: reaching beyond thickness / tan(critical_angle_deg), short
//              of thickness x tan(75 degrees);
//   far:       the part of layer k farther than far_reach_mm from layer k-1's region, less its
//              parts narrower than 0.1 mm (a sliver that thin may light no pixel of its mask).
// Points are placed on those areas (greedy cover of a lattice of candidates, then the area's
// boundary for slivers thinner than the lattice; cover_layer.h), layer by layer from the bottom:
//   every point of an island or a far area lies within point_reach_mm() of a point of its own
//   layer, whose head's tip then lies under it in the layer below: with far_reach_mm and
//   head_reach_mm below 1 mm, no lit pixel of a mask is more than 1 mm from the layer below;
//   every point of an overhang lies within support_radius_mm() (and point_reach_mm()) of a point
//   of its own layer or, in space, within support_radius_mm() of a point of a layer below (the
//   surface between them is held by it), as PrusaSlicer's support force spreads over the
//   surface around a point, at any density;
//   slopes get points only while their part is short of its support force, as PrusaSlicer's
//   slopes do (support_force.h): a point holds held_area_mm2() of its layer's area, and a part
//   inherits what the parts it rests on hold; each then goes where the slopes are farthest from
//   the points held;
// every island has a point of its own, and points of a layer stand more than about half the
// radius apart (minimal_distance_mm yields to the cover). Each 2-D point becomes a point on
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
  // From the horizontal: a surface flatter than this overhangs and may need points (on the
  // slopes, as their support force asks; flatter than 15 degrees, covered). Not PrusaSlicer's
  // support_critical_angle, the angle of its support sticks: its points take a fixed 55 degrees.
  double critical_angle_deg = 45;
  // PrusaSlicer's support_points_density_relative / 100: at 1, one point holds 10 mm^2
  // (held_area_mm2), support_radius_mm() = sqrt(10 / (pi d)).
  double density_relative = 1.0;
  // PrusaSlicer's support_points_minimal_distance: how near a point added on a member may be
  // to a dropped one to count as that point moved (transfer_support_points.h).
  double minimal_distance_mm = 1.0;
  // The masks' rule (no lit pixel more than 1 mm from the layer below), see above: a layer's
  // far area and islands lie within head_reach_mm of the edge of a head's tip, which is lit in the
  // layer below, head_front_diameter_mm across (the tree's, SupportTreeOptions), so within
  // point_reach_mm() of its point.
  double far_reach_mm = 0.9;
  double head_reach_mm = 1.0;
  double head_front_diameter_mm = 0.5;
  // Raised off the plate (support_object_elevation > 0): layer 0 is an island to support.
  bool raised = true;
  size_t max_points = 1000000;
  // How much of a layer's area a point holds (its support force, support_force.h): 10 mm2 /
  // density_relative (PrusaSlicer 2.5's is 11.1: ours is a little denser).
  double held_area_mm2() const;
  // How far a point holds the overhanging surface around it: sqrt(held_area_mm2() / pi).
  double support_radius_mm() const;
  // How far a point holds its layer's far area and islands: head_reach_mm plus the head tip's
  // radius, less 0.05 mm for its pixels.
  double point_reach_mm() const;
  // How far a layer may reach beyond the one below without overhanging.
  double self_supporting_mm(double thickness) const;
};

SupportPoints generate_support_points(const Mesh& mesh, const Slices& slicing, const SupportPointOptions& options,
                                      const SupportPoints* existing = nullptr, const Progress& progress = {});

}  // namespace slicereuse
