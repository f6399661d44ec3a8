#include "slicereuse/fingerprint.h"

#include <xxhash.h>

namespace slicereuse {

Fingerprint mesh_fingerprint(const Mesh& mesh) {
  static_assert(sizeof(uint32_t) == 4, "face indices are hashed as 32-bit little-endian words");
  Fingerprint fp;
  fp.faces = mesh.faces();
  fp.hash = XXH3_64bits(mesh.F.data(), mesh.F.size() * sizeof(uint32_t));
  return fp;
}

}  // namespace slicereuse
