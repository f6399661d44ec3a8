#pragma once
// transfer_through_map: a target's contours from a source's encoding and a SurfaceMap, for a
// target whose connectivity differs from the source's (transfer_contours covers equal faces).
//
// Barycentric mode (the method as written): each encoded point p = (1-t) v_a + t v_b on source
// edge (a, b) is carried through the map, q = (1-t) Gamma(a) + t Gamma(b), and placed on its
// layer's plane z_k (in-plane constraint) on the target's surface: at the point of the target's
// section at z_k nearest to q in xy (on a segment between two of the slicer's crossings), just
// as the map takes each source vertex to the nearest point of the target's level set at its
// height. Why not q itself: the map is sampled at vertices, so q lies on a chord between two
// target surface points, off the surface, and where the surface is nearly horizontal (domes'
// tops, tooth ridges) the chord's small sag is a large shift in the plane. The nearest section
// point is sought along the loop(s) that the faces of Gamma(a) and Gamma(b) lead to (walked to
// the plane, as exact mode's seeds); a point with no section point nearer to q than
// |Gamma(a) - Gamma(b)| (no straddling face near its images, or only another loop) keeps q and is
// counted in stats.unplaced_points; a contour none of whose points has such a section point is
// dropped (the target has no surface at its height there, e.g. a dome's top that is lower on
// the target) and counted in stats.dropped_contours. One output point per source point of the
// other contours, in the source's contours and order. max_plane_deviation reports how far q was
// from z_k before it was placed. Layers run up to the target's own top (the same planes as direct slicing of the target on the
// source's plate); a taller target's layers above the source's have no points to carry and are
// re-sliced directly. The points lie inside the target's faces, not on its edges, so this mode
// has no target encoding: it refuses options.encoding = true.
// Exact mode: the carried points tell which target faces each layer crosses (the faces of the
// images of an encoded edge's two ends, walked at most a few faces to the plane); the target's
// own contour at z_k is traced from those seeds through the target's adjacency (trace_contour.h,
// no search for starting faces), and the layer is certified: every traced loop closes and the
// loops hold exactly as many points as the target has faces straddling the plane
// (straddling_faces.h), so no loop was missed. Layers that fail are re-sliced directly; layers
// run up to the target's own top as in transfer_contours (transfer_layers.h). The result equals
// direct slicing of the target, bit for bit up to the order of loops and their start points, and
// with options.encoding it carries the target's own encoding (face, edge, t of the target).
//
// Throws Error when the encoding is not of the map's source, target is not the map's target,
// the map is inconsistent (validate_surface_map), or barycentric mode is asked for an encoding.
#include "slicereuse/crossparam/surface_map.h"
#include "slicereuse/mesh/mesh.h"
#include "slicereuse/slicing/slices.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

Slices transfer_through_map(const Slices& encoding, const SurfaceMap& map, const Mesh& target,
                            const TransferOptions& options, TransferStats* stats = nullptr,
                            const Progress& progress = {});

}  // namespace slicereuse
