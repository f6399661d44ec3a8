#pragma once
// slice_layers: slices a triangle mesh into layers of closed contours plus their encoding.
//
// Input: a mesh and the layer thickness h > 0; z_start defaults (NaN) to the lowest vertex z.
// There is one layer k for every k >= 0 with z_start + k*h < zmax, with its plane at
// layer_z[k] = z_start + (k + 1/2)*h.
// Output: Slices with xyz and the encoding filled (see slices.h), fingerprint of the mesh set.
//
// Robust by construction: a vertex with z >= plane counts as above it (symbolic perturbation),
// so every crossing lies strictly inside an edge with one end below and one at or above, and
// contours are chained through the shared edges of adjacent faces, never by comparing
// coordinates (closed shells touching along an edge are chained through it too: edge_links.h).
// Edges that are boundary, unevenly shared or inconsistently oriented end open polylines, which
// are kept and flagged. Each crossing point is computed from the edge's lower
// vertex towards its upper one, so the same edge gives bit-identical points in every face and
// in transfer_contours.
#include <limits>
#include <vector>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/slicing/slices.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

struct SliceOptions {
  double thickness = 0.1;
  double z_start = std::numeric_limits<double>::quiet_NaN();
  bool encoding = true;  // false: xyz only (37 -> 24 bytes written per point), e.g. for masks
};

// A z_start for hosts whose parameters cannot be NaN (a filter's default cannot depend on the
// mesh): kLowestVertexZStart, the filters' default, and any value at or below
// kLowestVertexZStartAtOrBelow mean the mesh's lowest vertex. z_start_option maps such a value to
// SliceOptions::z_start: NaN for those, else the value itself.
constexpr double kLowestVertexZStart = -1e30;
constexpr double kLowestVertexZStartAtOrBelow = -1e29;
inline double z_start_option(double z_start) {
  return z_start <= kLowestVertexZStartAtOrBelow ? std::numeric_limits<double>::quiet_NaN() : z_start;
}

Slices slice_layers(const Mesh& mesh, const SliceOptions& options, const Progress& progress = {});

// The planes slice_layers(mesh, options) slices at, and (when z_start is not null) the z_start it
// records: options.z_start, or the lowest vertex's z when that is NaN.
std::vector<double> slicing_planes(const Mesh& mesh, const SliceOptions& options, double* z_start = nullptr);

// The same for any increasing list of plane heights (layer_z = planes; z_start and thickness
// are left 0): transfer_contours re-slices just the layers it cannot certify.
Slices slice_planes(const Mesh& mesh, std::vector<double> planes, const Progress& progress = {},
                    bool with_encoding = true);

}  // namespace slicereuse
