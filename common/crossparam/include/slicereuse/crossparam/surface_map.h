#pragma once
// SurfaceMap: a map from a source mesh onto the surface of a target mesh of other connectivity
// (the method's cross-parameterization Gamma, sampled at the source's vertices), as flat arrays.
//
// Source vertex i maps to the target point
//   sum_j bary[3i+j] * target.V[target.F[3*face[i]+j]],  j = 0, 1, 2,
// on target face face[i], with every bary in [0, 1] and the three summing to 1 (up to rounding).
// A point inside a source face maps by interpolating its corners' images linearly.
// source_faces is the source mesh's F: transfer needs the vertices of each encoded edge, and the
// map carries them so that it works with only the encoding and the target at hand.
// The fingerprints (fingerprint.h) and vertex counts tie a map to the two meshes it was made for.
#include <cstdint>
#include <vector>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/mesh/fingerprint.h"

namespace slicereuse {

struct SurfaceMap {
  Fingerprint source;              // of source_faces
  Fingerprint target;              // of the target's F
  uint64_t source_vertices = 0;
  uint64_t target_vertices = 0;
  std::vector<uint32_t> source_faces;  // 3 * source.faces
  std::vector<uint32_t> face;          // source_vertices: target face of each image
  std::vector<double> bary;            // 3 * source_vertices

  size_t size() const { return face.size(); }
};

// Throws Error naming the first inconsistency: array lengths that disagree with the counts, a
// source face index >= source_vertices, source_faces not hashing to `source`, a target face id
// >= target.faces, or a barycentric coordinate that is not finite, outside [-1e-9, 1 + 1e-9], or
// whose three do not sum to 1 within 1e-9.
void validate_surface_map(const SurfaceMap& map);

// Throws Error when `target` is not the mesh the map was made for (fingerprint or vertex count).
void check_map_target(const SurfaceMap& map, const Mesh& target);

// The image of source vertex i on target, as xyz.
void map_point(const SurfaceMap& map, const Mesh& target, size_t i, double out[3]);

}  // namespace slicereuse
