#pragma once
// Slices: the layered contours of one mesh and/or their encoding, as flat arrays.
//
// Layer k is the section of the mesh by the plane z = layer_z[k], the mid-plane of the slab
// [z_start + k*thickness, z_start + (k+1)*thickness]. Its contours are
// [layer_begin[k], layer_begin[k+1]); contour c's points are [contour_begin[c], contour_begin[c+1]).
// Closed contours are loops (the last point connects back to the first): outer boundaries run
// counter-clockwise and holes clockwise, seen from +z. Open contours (from holes or unevenly
// shared edges in the mesh, edge_links.h) are polylines, flagged in contour_open.
//
// Contour points (xyz) and their encoding (face, edge, t) are parallel arrays; either may be
// empty: a contour file carries only xyz, an encoding file only the encoding.
//
// Encoding of point p (the method's area coordinates, restricted to the edge p lies on):
//   face f = face[p], local edge j = edge[p] joins corners j and (j+1)%3 of f, and
//   p = (1-t)*v_j + t*v_{(j+1)%3} with 0 < t <= 1, i.e. lambda_j = 1-t, lambda_{j+1} = t,
//   lambda_{j+2} = 0. For every point of a closed contour, corner j is below the plane
//   (z < layer_z) and corner j+1 at or above it.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/util/buffer.h"

namespace slicereuse {

struct Slices {
  double z_start = 0;
  double thickness = 0;
  std::vector<double> layer_z;           // L
  std::vector<uint64_t> layer_begin;     // L+1
  std::vector<uint64_t> contour_begin;   // C+1
  std::vector<uint8_t> contour_open;     // C

  Buffer<double> xyz;                    // 3P, or empty

  Fingerprint fingerprint;               // of the mesh the encoding refers to
  Buffer<uint32_t> face;                 // P, or empty
  Buffer<uint8_t> edge;                  // P, or empty
  Buffer<double> t;                      // P, or empty

  size_t layers() const { return layer_z.size(); }
  size_t contours() const { return contour_open.size(); }
  size_t points() const { return contour_begin.empty() ? 0 : size_t(contour_begin.back()); }
  size_t open_contours() const;
  bool has_points() const { return xyz.size() == 3 * points(); }
  bool has_encoding() const { return face.size() == points() && edge.size() == points() && t.size() == points(); }
};

// Layers [a, b) of s into out (replaced; its buffers are reused, for a layer at a time): their
// layout (layer_z, offsets from 0, open flags), s's fingerprint, z_start that of layer a, s's
// thickness, and their points when with_points (else room for them: xyz sized, not filled);
// no encoding. Needs a <= b <= s.layers(), and s's points when with_points.
void layers_into(const Slices& s, size_t a, size_t b, Slices& out, bool with_points);

// Layers [a, b) of s with their points appended to out's (out's z_start and thickness kept; no
// encoding: out's is cleared). Needs a <= b <= s.layers() and s's points.
void append_layers(const Slices& s, size_t a, size_t b, Slices& out);

// Signed area of contour c's loop in the xy plane (shoelace, in double), seen from +z: positive
// for a counter-clockwise (outer) loop, negative for a clockwise one (a hole). Needs xyz.
double contour_area(const Slices& s, size_t c);

// Throws Error naming the first inconsistency: a thickness that is not positive, offset arrays
// not starting at 0, not increasing (every contour has at least one point) or not ending at the
// array sizes, array lengths that disagree, an open flag other than 0 or 1, an edge > 2, t
// outside (0, 1], a face id >= fingerprint.faces, or non-finite numbers.
// With check_points false, only the layout is checked (sizes and offsets, not the per-point
// values), in time independent of the point count: for a caller that checks each layer's points
// while it reads them anyway (export_masks).
void validate_slices(const Slices& s, bool check_points = true);

}  // namespace slicereuse
