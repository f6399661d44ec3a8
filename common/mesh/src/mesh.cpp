#include "slicereuse/mesh/mesh.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

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
  size_t non_finite = 0, first = 0;
  for (size_t v = 0; v < nv; ++v)
    if (!std::isfinite(mesh.V[3 * v]) || !std::isfinite(mesh.V[3 * v + 1]) || !std::isfinite(mesh.V[3 * v + 2]))
      if (non_finite++ == 0) first = v;
  // Refused rather than sliced around: the faces they touch would leave holes in the print.
  if (non_finite != 0)
    throw Error(format("the mesh has %zu vertices with NaN or infinite coordinates (first: vertex %zu); "
                       "repair or remove them first",
                       non_finite, first));
}

}  // namespace slicereuse
