#pragma once
// points_on: support points (support_points.h) at the centroids of the given faces of part, of
// the overhang kind, placed on it (place_support_points): the trees' tests' hand-made points.
#include <cstdint>
#include <vector>

#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/mesh/mesh.h"
#include "slicereuse/supports/support_points.h"

namespace slicereuse::test {

inline SupportPoints points_on(const Mesh& part, const std::vector<uint32_t>& faces) {
  SupportPoints p;
  p.fingerprint = mesh_fingerprint(part);
  for (uint32_t f : faces) {
    p.face.push_back(f);
    p.bary.insert(p.bary.end(), {1.0 / 3, 1.0 / 3, 1 - 2.0 / 3});
    p.kind.push_back(uint8_t(SupportKind::Overhang));
    p.layer.push_back(0);
  }
  place_support_points(p, part);
  return p;
}

}  // namespace slicereuse::test
