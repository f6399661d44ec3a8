#pragma once
// SupportPoints: where a part touches its supports, in the encoding's own language: for each
// point the mesh face it lies on and its area coordinates on that face, so that a member of the
// family (the same faces, other vertices) has the same point on its own surface; plus, for the
// mesh the points were made on, the position and the face's unit outward normal.
//
//   point i lies on face f = face[i] at sum_j bary[3i+j] * V[F[3f+j]], j = 0, 1, 2,
//   every bary in [0, 1], the three summing to 1; xyz[3i..] is that position on the mesh the
//   points belong to, normal[3i..] that face's unit outward normal.
// kind[i] says why the point is there: an island (a region of a layer resting on nothing) or an
// overhang (a part of a layer reaching farther than the self-supporting distance beyond the layer
// below). layer[i] is the index of the layer it supports, on the slicing it was found on.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

enum class SupportKind : uint8_t { Island = 0, Overhang = 1 };

struct SupportPoints {
  Fingerprint fingerprint;       // of the mesh the face ids refer to
  std::vector<uint32_t> face;    // P
  std::vector<double> bary;      // 3P
  std::vector<double> xyz;       // 3P
  std::vector<double> normal;    // 3P
  std::vector<uint8_t> kind;     // P, SupportKind
  std::vector<uint32_t> layer;   // P

  size_t size() const { return face.size(); }
  // Appends point i of other (same fingerprint).
  void push_back_from(const SupportPoints& other, size_t i);
};

// Whether point i's surface faces up, its normal within 30 degrees of +z (PrusaSlicer's normal
// cutoff): nothing above the part's surface there needs it, and a head under it would cross the
// part. Such points are neither made nor kept, and the support tree drops them.
bool faces_up(const SupportPoints& points, size_t i);
// The same for a unit normal's z.
bool normal_faces_up(double normal_z);

// Sets xyz and normal of every point from its face and area coordinates on mesh, which must
// have the points' fingerprint (not checked here).
void place_support_points(SupportPoints& points, const Mesh& mesh);

// Throws Error naming the first inconsistency: array lengths that disagree, a face id >=
// fingerprint.faces, an area coordinate outside [-1e-9, 1 + 1e-9] or three not summing to 1
// within 1e-6, a kind other than 0 or 1, or a number that is not finite. With a mesh, also
// when the mesh is not the one the points were made on: "the support points are for a mesh of
// <faces, hash>, this one has <faces, hash>".
void validate_support_points(const SupportPoints& points, const Mesh* mesh = nullptr);

}  // namespace slicereuse
