#include "slicereuse/mesh/fingerprint.h"

#include <xxhash.h>

#include <cstdio>

namespace slicereuse {

Fingerprint mesh_fingerprint(const Mesh& mesh) {
  static_assert(sizeof(uint32_t) == 4, "face indices are hashed as 32-bit little-endian words");
  Fingerprint fp;
  fp.faces = mesh.faces();
  fp.hash = XXH3_64bits(mesh.F.data(), mesh.F.size() * sizeof(uint32_t));
  return fp;
}

std::string describe_fingerprint(const Fingerprint& fp) {
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fp.hash));
  return std::to_string(fp.faces) + " faces, hash " + hash;
}

}  // namespace slicereuse
