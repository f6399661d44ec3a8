#pragma once
// transfer_through_map: a target's contours from a source's encoding and a SurfaceMap, for a
// target whose connectivity differs from the source's (transfer_contours covers equal faces).
//
// Barycentric mode (the method as written): each encoded point p = (1-t) v_a + t v_b on source
// edge (a, b) is carried through the map, (1-t) Gamma(a) + t Gamma(b), and placed on its layer's
// plane z_k (in-plane constraint); max_plane_deviation reports how far the carried point was
// from z_k before it was placed.
// Exact mode: the carried points tell which target faces each layer crosses; the target's own
// contour at z_k is traced from those seeds through the target's adjacency (no search for
// starting faces), and the layer is certified as transfer_contours does (every traced loop
// closes and the target has exactly as many straddling faces on the plane as traced points);
// layers that fail are re-sliced directly. The result equals direct slicing of the target.
//
// Throws Error when the encoding is not of the map's source, or target is not the map's target.
#include "slicereuse/mesh.h"
#include "slicereuse/progress.h"
#include "slicereuse/slices.h"
#include "slicereuse/surface_map.h"
#include "slicereuse/transfer_contours.h"

namespace slicereuse {

Slices transfer_through_map(const Slices& encoding, const SurfaceMap& map, const Mesh& target,
                            const TransferOptions& options, TransferStats* stats = nullptr,
                            const Progress& progress = {});

}  // namespace slicereuse
