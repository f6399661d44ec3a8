#pragma once
// transfer_layers: the layer bookkeeping every transfer shares (transfer_contours for a target
// with the source's faces, transfer_through_map for a target with other faces).
//
// target_planes(encoding, target): the planes direct slicing of the target uses, the source's
// (every member sits on the same build plate) up to the target's own top, so a taller member
// gets its extra layers and a shorter one no empty ones.
// splice_resliced(done, done_layer, planes, target, ...): the transfer's result on `planes`:
// plane k is layer done_layer[k] of `done` (a certified transferred layer), or, where
// done_layer[k] is kNoLayer, re-sliced directly on the target (slice_planes) and spliced in.
// When more than half the planes must be re-sliced, slicing every plane at once costs less than
// splicing, and gives the same result by construction. Fills the stats' layer counts.
// slice_every_plane: that direct slicing of every plane (all counted as re-sliced).
// for_each_layer(L, progress, body): body(k) for k in [0, L), in parallel blocks of layers.
// layer_point_begin/end(s, k): the range of layer k's points in s.
// layout_of(encoding): Slices with the encoding's layers and contours and room for their xyz;
// layout_of(encoding, a, b): the same for its layers [a, b), counted from 0 (layers_into, slices.h,
// after a check that they fit in memory).
// EndsFromFaces: the two vertex ids of encoded point p's edge (corner j, then corner j+1 of its
// face), looked up in the faces F of any mesh with the encoding's fingerprint.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/slicing/slices.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

constexpr size_t kNoLayer = SIZE_MAX;

std::vector<double> target_planes(const Slices& encoding, const Mesh& target);

Slices splice_resliced(Slices done, const std::vector<size_t>& done_layer, std::vector<double> planes,
                       const Mesh& target, bool with_encoding, TransferStats& stats, const Progress& progress);

Slices slice_every_plane(const Mesh& target, std::vector<double> planes, bool with_encoding, TransferStats& stats,
                         const Progress& progress);

void for_each_layer(size_t layers, const Progress& progress, const std::function<void(size_t)>& body);

inline size_t layer_point_begin(const Slices& s, size_t k) { return s.contour_begin[s.layer_begin[k]]; }
inline size_t layer_point_end(const Slices& s, size_t k) { return s.contour_begin[s.layer_begin[k + 1]]; }

Slices layout_of(const Slices& encoding);
Slices layout_of(const Slices& encoding, size_t a, size_t b);

// One transfer between its progress reports: make(stats) computes the layers; the output gets
// the encoding's z_start and thickness and the fingerprint of the mesh it lies on (the target's),
// and *stats (when not null) the figures.
template <class Make>
Slices reported_transfer(const Slices& encoding, const Fingerprint& lies_on, TransferStats* stats,
                         const Progress& progress, Make&& make) {
  report_progress(progress, 0, "transferring");
  TransferStats st;
  Slices out = make(st);
  out.z_start = encoding.z_start;
  out.thickness = encoding.thickness;
  out.fingerprint = lies_on;
  report_progress(progress, 1, "transferring");
  if (stats) *stats = st;
  return out;
}

struct EndsFromFaces {
  const uint8_t* edge;
  const uint32_t* face;
  const uint32_t* F;
  void operator()(size_t p, uint32_t& a, uint32_t& b) const {
    static constexpr uint32_t kNextCorner[3] = {1, 2, 0};
    const uint32_t* corners = F + 3 * size_t(face[p]);
    a = corners[edge[p]];
    b = corners[kNextCorner[edge[p]]];
  }
};

}  // namespace slicereuse
