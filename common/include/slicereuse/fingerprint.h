#pragma once
// mesh_fingerprint: the connectivity fingerprint of a mesh (see slices.h). Two meshes have the
// same fingerprint exactly when (up to hash collisions) their face index arrays are equal.
// describe_fingerprint gives it in words for messages: "<faces> faces, hash <16 hex digits>".
#include <string>

#include "slicereuse/mesh.h"
#include "slicereuse/slices.h"

namespace slicereuse {

Fingerprint mesh_fingerprint(const Mesh& mesh);

std::string describe_fingerprint(const Fingerprint& fp);

}  // namespace slicereuse
