#pragma once
// Area coordinates of an encoded point, both ways (docs/formats.md, "Area coordinates and the
// decoding rule"). In: local edge j (0, 1, 2) and t in (0, 1]; out: (lambda1, lambda2, lambda3)
// relative to the face's corners. Back: the unique (j, t) those coordinates name.
// Used by the text encoding files and by contour layers in MeshLab, which carry the method's
// three coordinates per point, so that both decode by exactly the same rule.
#include <cstdint>

namespace slicereuse {

// Files from other programs (written in float, say) may not sum to 1 exactly.
constexpr double kAreaCoordinateSumTolerance = 1e-6;

// lambda_j = 1 - t, lambda_(j+1) = t, lambda_(j+2) = 0 (indices mod 3).
inline void encode_area_coordinates(unsigned j, double t, double lambda[3]) {
  lambda[j] = 1.0 - t;
  lambda[(j + 1) % 3] = t;
  lambda[(j + 2) % 3] = 0.0;
}

// j is the unique index with lambda_(j+2) == 0 and lambda_(j+1) > 0, and t = lambda_(j+1):
// the exact inverse of encode_area_coordinates. Returns nullptr on success, otherwise what is
// wrong in words (a negative or non-finite coordinate, no coordinate 0, all 0, one above 1, a
// sum other than 1 within kAreaCoordinateSumTolerance); then j and t are left unchanged.
const char* decode_area_coordinates(const double lambda[3], uint8_t& j, double& t);

}  // namespace slicereuse
