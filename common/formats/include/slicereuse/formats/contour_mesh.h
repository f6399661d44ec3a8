#pragma once
// ContourMesh: slices as an edge mesh with per-vertex attributes, the form in which a MeshLab
// layer carries a contour or encoding file (io_encoding). Plain arrays, no MeshLab types: the
// plugin copies them into its mesh and custom attributes and back.
//
// contour_mesh_from_slices: in: validated Slices with xyz (and optionally an encoding).
// Out: one vertex per contour point, in point order; per vertex its layer index and its
// contour index (global, 0-based); edges join consecutive points of a contour, plus the edge
// from its last point back to the first when it is closed (a one-point closed contour gets the
// edge (v, v)). With an encoding, per vertex also the face id and the three area coordinates
// (docs/formats.md). Per mesh: thickness, z_start, every layer's z (empty layers have no
// vertex) and the fingerprint.
//
// slices_from_contour_mesh: the exact inverse: same layers, contours, order, open flags,
// points and encoding. Vertices may come with gaps in the contour numbering (contours deleted
// in MeshLab): contours are renumbered in order. Throws Error naming the vertex, edge or
// contour when the mesh is not such a contour mesh: contour indices decreasing or not sorted
// by layer, a layer index outside the layers, an edge that is not a segment of one contour, a
// contour whose edges are not a polyline or loop through its points, area coordinates that do
// not name a point on a face edge.
#include <cstdint>
#include <vector>

#include "slicereuse/slicing/slices.h"
#include "slicereuse/util/buffer.h"

namespace slicereuse {

struct ContourMesh {
  double thickness = 0;
  double z_start = 0;
  std::vector<double> layer_z;  // L
  Fingerprint fingerprint;      // of the encoded mesh (0, 0 without an encoding)

  Buffer<double> position;      // 3V: x, y, z
  Buffer<uint32_t> layer;       // V
  Buffer<uint32_t> contour;     // V
  Buffer<uint32_t> face;        // V, or empty without an encoding
  Buffer<double> area;          // 3V (lambda1..3 per vertex), or empty
  Buffer<uint32_t> edges;       // 2E: vertex index pairs

  size_t vertices() const { return layer.size(); }
  bool has_encoding() const { return !face.empty(); }
};

ContourMesh contour_mesh_from_slices(const Slices& s);
Slices slices_from_contour_mesh(const ContourMesh& m);

// XXH3_64bits over every field and array of m (sizes included): equal for equal meshes, so a
// host can tell whether a contour layer still holds what it was filled with.
uint64_t contour_mesh_hash(const ContourMesh& m);

}  // namespace slicereuse
