#pragma once
// support_points_for_areas: generate_support_points once the layers' areas are known
// (support_areas.h), so that transfer, which certifies on the same areas, computes them once.
// Each layer's points in the plane (cover_layer.h), then each on the mesh: the face a vertical
// ray from below meets first within the layer's span (PartColumns of its downward faces,
// preferring heights between the planes of layers k-1 and k), else the contour point of layer
// k nearest in x-y on a face that does not face up (faces_up, support_points.h), on the face
// and edge its encoding names. The cover runs up the layers (an overhang may be held by points
// below it), the rays on all cores, merged in layer order.
// existing: points on this mesh that count as taken on their layer (layer[i]).
// Output: the new points; Error past options.max_points.
#include <vector>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/slicing/slices.h"
#include "slicereuse/supports/generate_support_points.h"
#include "slicereuse/supports/support_points.h"
#include "slicereuse/util/progress.h"
#include "support_areas.h"

namespace slicereuse {

SupportPoints support_points_for_areas(const Mesh& mesh, const Slices& slicing, const std::vector<LayerAreas>& areas,
                                       const SupportPointOptions& options, const SupportPoints* existing,
                                       const Progress& progress);

}  // namespace slicereuse
