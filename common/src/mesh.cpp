#include "slicereuse/mesh.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "slicereuse/error.h"

namespace slicereuse {

ZRange z_range(const Mesh& mesh) {
  ZRange r{mesh.V[2], mesh.V[2]};
  for (size_t i = 2; i < mesh.V.size(); i += 3) {
    r.min = std::min(r.min, mesh.V[i]);
    r.max = std::max(r.max, mesh.V[i]);
  }
  return r;
}

void validate_mesh(const Mesh& mesh) {
  if (mesh.V.size() % 3 != 0) throw Error("mesh vertex array length is not a multiple of 3");
  if (mesh.F.size() % 3 != 0) throw Error("mesh face array length is not a multiple of 3");
  if (mesh.faces() == 0) throw Error("mesh has no faces");
  if (mesh.faces() >= (size_t(1) << 30))
    throw Error("mesh has " + std::to_string(mesh.faces()) + " faces, more than 2^30");
  const size_t nv = mesh.vertices();
  for (size_t i = 0; i < mesh.F.size(); ++i)
    if (mesh.F[i] >= nv)
      throw Error("face " + std::to_string(i / 3) + " refers to vertex " +
                  std::to_string(mesh.F[i]) + " but the mesh has " + std::to_string(nv) +
                  " vertices");
  for (size_t i = 0; i < mesh.V.size(); ++i)
    if (!std::isfinite(mesh.V[i]))
      throw Error("vertex " + std::to_string(i / 3) + " has a coordinate that is not finite");
}

}  // namespace slicereuse
