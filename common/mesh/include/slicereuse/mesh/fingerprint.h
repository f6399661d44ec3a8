#pragma once
// mesh_fingerprint: the connectivity fingerprint of a mesh. Two meshes have the
// same fingerprint exactly when (up to hash collisions) their face index arrays are equal.
// describe_fingerprint gives it in words for messages: "<faces> faces, hash <16 hex digits>".
#include <cstdint>
#include <string>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

// Connectivity fingerprint: face count plus a 64-bit hash of the face index array.
struct Fingerprint {
  uint64_t faces = 0;
  uint64_t hash = 0;
  bool operator==(const Fingerprint& o) const { return faces == o.faces && hash == o.hash; }
  bool operator!=(const Fingerprint& o) const { return !(*this == o); }
};

Fingerprint mesh_fingerprint(const Mesh& mesh);

std::string describe_fingerprint(const Fingerprint& fp);

}  // namespace slicereuse
