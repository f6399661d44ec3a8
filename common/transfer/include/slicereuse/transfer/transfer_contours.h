#pragma once
// transfer_contours: computes a target mesh's contours from a source's encoding and the
// target's vertices (the target must have the source's faces, checked by fingerprint).
//
// Exact mode: every encoded point lies on a mesh edge; the same edge of the target is cut by
// the same plane layer_z[k] (every member sits on the same build plate). A layer is certified
// when every one of its edges still straddles its plane the same way up and the target has
// exactly as many straddling edges on that plane as the layer has points; otherwise that layer
// alone is re-sliced directly on the target. Layers run up to the target's own top, as direct
// slicing with the source's z_start and thickness would give: a taller target's extra layers are
// sliced directly (and counted as re-sliced), a shorter target's surplus layers are dropped.
// The result therefore equals direct slicing of the target layer by layer (up to the order of
// contours and the start point of each loop), bit for bit.
// Barycentric mode: the method's Eq. 2, p = sum lambda_i * v_i on the target face, on the
// source's layers as they are; points may leave the plane when the target differs in z
// (max_plane_deviation reports by how much).
//
// Output: Slices with xyz and, when `encoding` is true, the target's own encoding, so the target
// can be a source later. Without it, transfer writes 24 instead of 37 bytes per point; it is
// memory-bound, so that is what it costs.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/slicing/slices.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

enum class TransferMode { Exact = 0, Barycentric = 1 };

// Explicit, so a bare TransferMode argument does not silently mean "with the encoding".
struct TransferOptions {
  TransferMode mode;
  bool encoding;  // also compute the target's encoding (face, edge, t per point)
  explicit TransferOptions(TransferMode m = TransferMode::Exact, bool with_encoding = true)
      : mode(m), encoding(with_encoding) {}
};

struct TransferStats {
  size_t transferred_layers = 0;
  size_t resliced_layers = 0;
  double max_plane_deviation = 0;  // barycentric mode: max |z - layer_z|
  // Barycentric transfer through a map (transfer_through_map.h): carried points left where the
  // map carried them, because no section of the target was found near their images, and
  // contours dropped because none of their points was (the target has no surface there).
  size_t unplaced_points = 0;
  size_t dropped_contours = 0;
};

// family_difference: "" when mesh has the faces of the mesh the encoding was made from (the same
// fingerprint), else how they differ, in words ("faces differ from those of ..."), for a job that
// slices such a member directly instead. mesh must be valid (validate_mesh).
std::string family_difference(const Slices& encoding, const Mesh& mesh);

// Throws Error when target's fingerprint differs from encoding.fingerprint.
Slices transfer_contours(const Slices& encoding, const Mesh& target, const TransferOptions& options,
                         TransferStats* stats = nullptr, const Progress& progress = {});

// encoded_edge_ends: for every encoded point, the ids of its edge's two vertices (corner j,
// then corner j+1 of its face), 2 per point, from the encoding and the faces of any member of
// the family. Transfer is bound by looking each face up; a pipeline that transfers one encoding
// to many members computes these once and passes them to every transfer below.
// Throws Error when mesh's fingerprint differs from encoding.fingerprint.
Buffer<uint32_t> encoded_edge_ends(const Slices& encoding, const Mesh& mesh);

// The same transfer, reading edge_ends (from encoded_edge_ends) instead of the faces.
Slices transfer_contours(const Slices& encoding, const Buffer<uint32_t>& edge_ends, const Mesh& target,
                         const TransferOptions& options, TransferStats* stats = nullptr,
                         const Progress& progress = {});

// VertexOrder: a family's vertices numbered in the order the encoding's points first use them
// (layer after layer), and the points' edge ends (encoded_edge_ends) in those numbers. A layer's
// few thousand vertices lie all over a mesh's own vertex array; a transfer that reads a copy
// in this order (ExactTransfer with an order) reads them nearly in sequence. Made once for any
// number of members, from the edge ends alone, in one pass over them.
struct VertexOrder {
  Buffer<uint32_t> ends;         // 2 per point
  std::vector<uint32_t> vertex;  // number -> the mesh's vertex id
};

VertexOrder vertex_order(const Buffer<uint32_t>& edge_ends);

// ExactTransfer: the exact transfer (without the target's encoding) a range of layers at a time,
// for a job that holds only some of a member's layers in memory at once (a build plate,
// plate_job.h). What costs O(faces), the family check and the certificate's counts on every
// plane of the target, is done once, when it is made; layers(a, b) then costs what its points
// do, and equals layers [a, b) of transfer_contours(encoding, [edge_ends,] target, exact without
// encoding), re-sliced layers included, with z_start that of layer a.
class ExactTransfer {
 public:
  // Throws what transfer_contours throws for these. Keeps references to all of them.
  ExactTransfer(const Slices& encoding, const Mesh& target);
  // With an order (vertex_order of edge_ends), the transfer keeps a copy of the target's vertices
  // in that order, which layer_into and certified read; throws Error for an order of other edge
  // ends or another mesh.
  ExactTransfer(const Slices& encoding, const Buffer<uint32_t>& edge_ends, const Mesh& target,
                const VertexOrder* order = nullptr);

  // The target's planes: the encoding's, up to the target's own top (a taller target's extra
  // layers are sliced directly): how many, and plane k's z.
  size_t layers() const { return planes_.size(); }
  double plane(size_t k) const { return planes_[k]; }
  // The target's points on each of its layers (its faces that straddle the plane; one point
  // each on a closed layer), which the certificate checks.
  const std::vector<uint64_t>& layer_points() const { return counts_; }
  // Throws Error unless a <= b <= layers().
  Slices layers(size_t a, size_t b, TransferStats* stats = nullptr, const Progress& progress = {}) const;

  // A layer at a time, for a job that makes each layer where it is used (a plate's masks,
  // plate_job.h), on any thread, without threads of its own:
  // transferable(k): whether layer k passes the certificate's counts and its sample (layers()
  // re-slices the others, and so must the caller);
  // certified(k): whether it passes the whole certificate as well: every edge still crosses the
  // plane the same way up (a pass over the layer's points, without computing them);
  // layer_into(k, out): layer k by transfer into out (replaced; its buffers are reused), with
  // z_start that of layer k, and certified(k), found while transferring. When it returns false,
  // out is not the layer: the layer must be sliced directly.
  // certified and layer_into throw Error unless transferable(k).
  bool transferable(size_t k) const { return k < transferable_.size() && transferable_[k]; }
  bool certified(size_t k) const;
  bool layer_into(size_t k, Slices& out) const;

 private:
  void check_transferable(size_t k) const;
  const uint32_t* transfer_ends() const;  // null: looked up in the faces
  const double* transfer_vertices() const;

  const Slices& encoding_;
  const Buffer<uint32_t>* edge_ends_;
  const Mesh& target_;
  std::vector<double> planes_;
  std::vector<uint64_t> counts_;
  std::vector<uint8_t> transferable_;
  const VertexOrder* order_ = nullptr;
  Buffer<double> ordered_vertices_;  // with an order: the target's vertices in it, 3 per vertex
};

}  // namespace slicereuse
