#include "slicereuse/crossparam/surface_map.h"

#include <cmath>
#include <string>

#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/util/error.h"

namespace slicereuse {

namespace {
constexpr double kBaryTolerance = 1e-9;
std::string num(uint64_t v) { return std::to_string(v); }
}  // namespace

void validate_surface_map(const SurfaceMap& map) {
  const uint64_t n = map.source_vertices;
  if (map.face.size() != n)
    throw Error("the map has " + num(map.face.size()) + " target faces for " + num(n) + " source vertices");
  if (map.bary.size() != 3 * n)
    throw Error("the map has " + num(map.bary.size()) + " barycentric coordinates, expected 3 x " + num(n));
  if (map.source_faces.size() != 3 * map.source.faces)
    throw Error("the map carries " + num(map.source_faces.size()) + " source face indices, the source fingerprint says " +
                num(map.source.faces) + " faces (x 3)");
  for (size_t k = 0; k < map.source_faces.size(); ++k)
    if (map.source_faces[k] >= n)
      throw Error("source face " + num(k / 3) + " refers to vertex " + num(map.source_faces[k]) + " but the source has " +
                  num(n) + " vertices");
  Mesh faces_only;
  faces_only.F = map.source_faces;
  if (mesh_fingerprint(faces_only) != map.source)
    throw Error("the map's source faces do not match its source fingerprint");
  for (uint64_t i = 0; i < n; ++i) {
    if (map.face[i] >= map.target.faces)
      throw Error("source vertex " + num(i) + " maps to target face " + num(map.face[i]) + " but the target has " +
                  num(map.target.faces) + " faces");
    const double* b = &map.bary[3 * i];
    for (int j = 0; j < 3; ++j)
      if (!std::isfinite(b[j]) || b[j] < -kBaryTolerance || b[j] > 1 + kBaryTolerance)
        throw Error("source vertex " + num(i) + " has a barycentric coordinate outside [0, 1]");
    if (std::abs(b[0] + b[1] + b[2] - 1) > kBaryTolerance)
      throw Error("the barycentric coordinates of source vertex " + num(i) + " do not sum to 1");
  }
}

void check_map_target(const SurfaceMap& map, const Mesh& target) {
  const Fingerprint fp = mesh_fingerprint(target);
  if (fp != map.target)
    throw Error("the map was made for a target with " + num(map.target.faces) +
                " faces and other connectivity; this target (" + num(fp.faces) +
                " faces) is not the map's target");
  if (target.vertices() != map.target_vertices)
    throw Error("the map was made for a target with " + num(map.target_vertices) + " vertices, this one has " +
                num(target.vertices()));
}

void map_point(const SurfaceMap& map, const Mesh& target, size_t i, double out[3]) {
  const uint32_t* f = &target.F[3 * size_t(map.face[i])];
  const double* b = &map.bary[3 * i];
  for (int a = 0; a < 3; ++a)
    out[a] = b[0] * target.V[3 * size_t(f[0]) + a] + b[1] * target.V[3 * size_t(f[1]) + a] +
             b[2] * target.V[3 * size_t(f[2]) + a];
}

}  // namespace slicereuse
