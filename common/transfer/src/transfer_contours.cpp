#include "slicereuse/transfer/transfer_contours.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/slicing/edge_point.h"
#include "slicereuse/slicing/straddling_faces.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "transfer_layers.h"

namespace slicereuse {
namespace {

// The two vertex ids of encoded point p's edge, read from encoded_edge_ends (EndsFromFaces,
// transfer_layers.h, looks them up in the faces).
struct EndsFromPairs {
  const uint32_t* ends;
  void operator()(size_t p, uint32_t& a, uint32_t& b) const {
    a = ends[2 * p];
    b = ends[2 * p + 1];
  }
};

constexpr size_t kPrefetchPoints = 16;

// Cuts layer k's encoded edges of the target by the layer's plane, into out at the encoding's
// offsets less p0 (out's first point is the encoding's point p0), and the target's encoding when
// out has room for it. Returns the certificate's first half: every edge still crosses from corner
// j below to corner j+1 at or above.
template <bool WithEncoding, class Ends>
bool transfer_layer(const Slices& enc, const Ends& ends, const double* V, size_t k, size_t p0, Slices& out) {
  const double zk = enc.layer_z[k];
  double* xyz = out.xyz.data();
  bool good = true;
  const size_t p1 = layer_point_begin(enc, k), p2 = layer_point_end(enc, k);
  for (size_t p = p1; p < p2; ++p) {
    // The vertices a few points ahead are fetched now: in the mesh's own order they lie anywhere
    // in its arrays (see VertexOrder), and a layer made where it is drawn (plate_job.h) finds
    // them out of cache, since the masks ran on this core in between.
    if (p + kPrefetchPoints < p2) {
      uint32_t fa, fb;
      ends(p + kPrefetchPoints, fa, fb);
      __builtin_prefetch(V + 3 * size_t(fa));
      __builtin_prefetch(V + 3 * size_t(fb));
    }
    uint32_t ia, ib;
    ends(p, ia, ib);
    const double* a = V + 3 * size_t(ia);
    const double* b = V + 3 * size_t(ib);
    good &= (a[2] < zk) & (b[2] >= zk);
    const EdgePoint e = edge_point(a, b, zk);
    const size_t q = p - p0;
    xyz[3 * q] = e.x;
    xyz[3 * q + 1] = e.y;
    xyz[3 * q + 2] = zk;
    if (WithEncoding) out.t[q] = e.t;
  }
  if (WithEncoding) {
    std::memcpy(&out.face[p1 - p0], &enc.face[p1], (p2 - p1) * sizeof(uint32_t));
    std::memcpy(&out.edge[p1 - p0], &enc.edge[p1], p2 - p1);
  }
  return good;
}

// The certificate for point p: its edge still crosses plane zk from corner j below to corner
// j+1 at or above (V: the vertices ends numbers).
template <class Ends>
bool crosses(const Ends& ends, const double* V, size_t p, double zk) {
  uint32_t ia, ib;
  ends(p, ia, ib);
  return (V[3 * size_t(ia) + 2] < zk) & (V[3 * size_t(ib) + 2] >= zk);
}

// The certificate's second half, and a sample of its first, for layers [a, b) of the target's
// planes (counts[k]: the target's straddling faces on plane k): 1 where layer k may be
// transferred, 0 where it must be re-sliced (a layer above the encoding's top has nothing to
// transfer). The counts are cheap (made once, in O(faces + layers)): the target must have
// exactly as many straddling edges as the layer has points (counted through its faces, see
// straddling_faces.h). The sample is as cheap (two points per contour): the first and the middle
// point of every contour must still cross the plane the same way up. A member that changed in z
// keeps its counts on most layers (its sections only move), so the counts alone let it through
// to a full transfer that then fails almost everywhere; the sample catches it before any point
// is transferred. Sampling only rejects layers the full check would reject.
template <class Ends>
std::vector<uint8_t> candidate_layers(const Slices& enc, const Ends& ends, const Mesh& target,
                                      const std::vector<uint64_t>& counts, size_t a, size_t b) {
  const double* V = target.V.data();
  std::vector<uint8_t> ok(b - a, 0);
  for (size_t k = a; k < std::min(b, enc.layers()); ++k) {
    bool good = counts[k] == layer_point_end(enc, k) - layer_point_begin(enc, k);
    for (size_t c = enc.layer_begin[k]; good && c < enc.layer_begin[k + 1]; ++c) {
      const size_t p0 = enc.contour_begin[c], p1 = enc.contour_begin[c + 1];
      good = !enc.contour_open[c] && crosses(ends, V, p0, enc.layer_z[k]) &&
             crosses(ends, V, (p0 + p1) / 2, enc.layer_z[k]);
    }
    ok[k - a] = good;
  }
  return ok;
}

// Layers [a, b) of the target's planes (target_planes) by exact transfer, counts[k] being the
// target's straddling faces on plane k.
template <class Ends>
Slices transfer_exact_layers(const Slices& enc, const Ends& ends, const Mesh& target, const std::vector<double>& planes,
                             const std::vector<uint64_t>& counts, size_t a, size_t b, bool with_encoding,
                             TransferStats& st, const Progress& progress) {
  // The range's encoded layers are [ta, te): ta is a when there are any, the encoding's top
  // when a lies at or above it.
  const size_t n = b - a, ta = std::min(a, enc.layers()), te = std::min(b, enc.layers());
  std::vector<uint8_t> ok = candidate_layers(enc, ends, target, counts, a, b);
  const size_t candidates = size_t(std::count(ok.begin(), ok.end(), uint8_t(1)));
  std::vector<double> range(planes.begin() + long(a), planes.begin() + long(b));
  // A member that changed in z can fail most layers; transferring the rest and splicing would
  // then cost more than slicing every layer (the result is the same by construction).
  if (2 * candidates < n) return slice_every_plane(target, std::move(range), with_encoding, st, progress);
  Slices moved = layout_of(enc, ta, te);
  if (with_encoding) {
    moved.face.resize(moved.points());
    moved.edge.resize(moved.points());
    moved.t.resize(moved.points());
  }
  const size_t p0 = layer_point_begin(enc, ta);
  // The transfer reports the first half of the progress, re-slicing what it could not transfer
  // the second (each from 0 to 1 on its own).
  for_each_layer(te - ta, sub_progress(progress, 0, 0.5), [&](size_t i) {
    if (ok[i])
      ok[i] = with_encoding ? transfer_layer<true>(enc, ends, target.V.data(), a + i, p0, moved)
                            : transfer_layer<false>(enc, ends, target.V.data(), a + i, p0, moved);
  });

  std::vector<size_t> done_layer(n, kNoLayer);
  for (size_t i = 0; i < te - ta; ++i)
    if (ok[i]) done_layer[i] = i;
  return splice_resliced(std::move(moved), done_layer, std::move(range), target, with_encoding, st,
                         sub_progress(progress, 0.5, 1));
}

template <class Ends>
Slices transfer_exact(const Slices& enc, const Ends& ends, const Mesh& target, bool with_encoding, TransferStats& st,
                      const Progress& progress) {
  const std::vector<double> planes = target_planes(enc, target);
  return transfer_exact_layers(enc, ends, target, planes, straddling_face_counts(target, planes), 0, planes.size(),
                               with_encoding, st, progress);
}

template <class Ends>
Slices transfer_barycentric(const Slices& enc, const Ends& ends, const Mesh& target, bool with_encoding,
                            TransferStats& st, const Progress& progress) {
  Slices out = layout_of(enc);
  const double* V = target.V.data();
  std::vector<double> deviation(enc.layers(), 0);
  for_each_layer(enc.layers(), progress, [&](size_t k) {
    double worst = 0;
    for (size_t p = layer_point_begin(enc, k); p < layer_point_end(enc, k); ++p) {
      uint32_t ia, ib;
      ends(p, ia, ib);
      const double* a = V + 3 * size_t(ia);
      const double* b = V + 3 * size_t(ib);
      const double t = enc.t[p];
      for (int d = 0; d < 3; ++d) out.xyz[3 * p + d] = (1 - t) * a[d] + t * b[d];
      worst = std::max(worst, std::abs(out.xyz[3 * p + 2] - enc.layer_z[k]));
    }
    deviation[k] = worst;
  });
  if (with_encoding) {  // the method's reuse keeps the area coordinates as they are
    out.face = enc.face;
    out.edge = enc.edge;
    out.t = enc.t;
  }
  st.transferred_layers = enc.layers();
  st.max_plane_deviation = deviation.empty() ? 0 : *std::max_element(deviation.begin(), deviation.end());
  return out;
}

void check_family(const Slices& encoding, const Mesh& mesh) {
  validate_mesh(mesh);
  if (!encoding.has_encoding()) throw Error("transfer needs an encoding (face and area coordinates per point)");
  const std::string difference = family_difference(encoding, mesh);
  if (!difference.empty())
    throw Error("the target mesh's " + difference +
                "; a target with other connectivity needs a cross-parameterization map (map file from Cross-Parameterize "
                "Meshes)");
}

void check_edge_ends(const Slices& encoding, const Buffer<uint32_t>& edge_ends) {
  if (edge_ends.size() != 2 * encoding.points())
    throw Error("edge ends were computed for another encoding (" + std::to_string(edge_ends.size() / 2) +
                " points, the encoding has " + std::to_string(encoding.points()) + ")");
}

template <class Ends>
Slices transfer(const Slices& encoding, const Ends& ends, const Mesh& target, const TransferOptions& options,
                TransferStats* stats, const Progress& progress) {
  return reported_transfer(encoding, encoding.fingerprint, stats, progress, [&](TransferStats& st) {
    return options.mode == TransferMode::Barycentric
               ? transfer_barycentric(encoding, ends, target, options.encoding, st, progress)
               : transfer_exact(encoding, ends, target, options.encoding, st, progress);
  });
}

}  // namespace

std::string family_difference(const Slices& encoding, const Mesh& mesh) {
  const Fingerprint fp = mesh_fingerprint(mesh);
  if (fp == encoding.fingerprint) return "";
  return "faces differ from those of the mesh the encoding was made from (encoding: " +
         describe_fingerprint(encoding.fingerprint) + "; target: " + describe_fingerprint(fp) + ")";
}

Slices transfer_contours(const Slices& encoding, const Mesh& target, const TransferOptions& options,
                         TransferStats* stats, const Progress& progress) {
  check_family(encoding, target);
  return transfer(encoding, EndsFromFaces{encoding.edge.data(), encoding.face.data(), target.F.data()}, target,
                  options, stats, progress);
}

Buffer<uint32_t> encoded_edge_ends(const Slices& encoding, const Mesh& mesh) {
  check_family(encoding, mesh);
  const EndsFromFaces from_faces{encoding.edge.data(), encoding.face.data(), mesh.F.data()};
  Buffer<uint32_t> ends(2 * encoding.points());
  const long long P = static_cast<long long>(encoding.points());
#pragma omp parallel for schedule(static)
  for (long long p = 0; p < P; ++p) from_faces(size_t(p), ends[2 * p], ends[2 * p + 1]);
  return ends;
}

Slices transfer_contours(const Slices& encoding, const Buffer<uint32_t>& edge_ends, const Mesh& target,
                         const TransferOptions& options, TransferStats* stats, const Progress& progress) {
  check_family(encoding, target);
  check_edge_ends(encoding, edge_ends);
  return transfer(encoding, EndsFromPairs{edge_ends.data()}, target, options, stats, progress);
}

ExactTransfer::ExactTransfer(const Slices& encoding, const Mesh& target)
    : encoding_(encoding), edge_ends_(nullptr), target_(target) {
  check_family(encoding, target);
  planes_ = target_planes(encoding, target);
  counts_ = straddling_face_counts(target, planes_);
  transferable_ = candidate_layers(
      encoding, EndsFromFaces{encoding.edge.data(), encoding.face.data(), target.F.data()}, target, counts_, 0,
      planes_.size());
}

ExactTransfer::ExactTransfer(const Slices& encoding, const Buffer<uint32_t>& edge_ends, const Mesh& target,
                             const VertexOrder* order)
    : ExactTransfer(encoding, target) {
  check_edge_ends(encoding, edge_ends);
  edge_ends_ = &edge_ends;
  if (!order) return;
  if (order->ends.size() != edge_ends.size())
    throw Error("a vertex order was made for another encoding (" + std::to_string(order->ends.size() / 2) +
                " points, the encoding has " + std::to_string(encoding.points()) + ")");
  order_ = order;
  ordered_vertices_.resize(3 * order->vertex.size());
  const double* V = target.V.data();
  for (size_t i = 0; i < order->vertex.size(); ++i) {
    if (order->vertex[i] >= target.vertices())
      throw Error("a vertex order names vertex " + std::to_string(order->vertex[i]) + ", but the target has " +
                  std::to_string(target.vertices()));
    std::memcpy(&ordered_vertices_[3 * i], V + 3 * size_t(order->vertex[i]), 3 * sizeof(double));
  }
}

const uint32_t* ExactTransfer::transfer_ends() const {
  return order_ ? order_->ends.data() : edge_ends_ ? edge_ends_->data() : nullptr;
}

const double* ExactTransfer::transfer_vertices() const {
  return order_ ? ordered_vertices_.data() : target_.V.data();
}

Slices ExactTransfer::layers(size_t a, size_t b, TransferStats* stats, const Progress& progress) const {
  if (a > b || b > planes_.size())
    throw Error(format("transfer of layers %zu to %zu asked for, but the target has %zu", a, b, planes_.size()));
  Slices out = reported_transfer(encoding_, encoding_.fingerprint, stats, progress, [&](TransferStats& st) {
    return edge_ends_ ? transfer_exact_layers(encoding_, EndsFromPairs{edge_ends_->data()}, target_, planes_, counts_,
                                              a, b, false, st, progress)
                      : transfer_exact_layers(encoding_,
                                              EndsFromFaces{encoding_.edge.data(), encoding_.face.data(),
                                                            target_.F.data()},
                                              target_, planes_, counts_, a, b, false, st, progress);
  });
  if (encoding_.thickness > 0) out.z_start = encoding_.z_start + double(a) * encoding_.thickness;
  return out;
}

void ExactTransfer::check_transferable(size_t k) const {
  if (!transferable(k))
    throw Error(format("layer %zu cannot be transferred alone (the target has %zu layers; only those its certificate's "
                       "counts let through can)",
                       k, planes_.size()));
}

bool ExactTransfer::certified(size_t k) const {
  check_transferable(k);
  const double* V = transfer_vertices();
  const double zk = encoding_.layer_z[k];
  const auto all_cross = [&](const auto& ends) {
    bool good = true;
    for (size_t p = layer_point_begin(encoding_, k); p < layer_point_end(encoding_, k); ++p)
      good &= crosses(ends, V, p, zk);
    return good;
  };
  if (const uint32_t* ends = transfer_ends()) return all_cross(EndsFromPairs{ends});
  return all_cross(EndsFromFaces{encoding_.edge.data(), encoding_.face.data(), target_.F.data()});
}

bool ExactTransfer::layer_into(size_t k, Slices& out) const {
  check_transferable(k);
  layers_into(encoding_, k, k + 1, out, false);
  const size_t p0 = layer_point_begin(encoding_, k);
  if (const uint32_t* ends = transfer_ends())
    return transfer_layer<false>(encoding_, EndsFromPairs{ends}, transfer_vertices(), k, p0, out);
  return transfer_layer<false>(encoding_,
                               EndsFromFaces{encoding_.edge.data(), encoding_.face.data(), target_.F.data()},
                               target_.V.data(), k, p0, out);
}

VertexOrder vertex_order(const Buffer<uint32_t>& edge_ends) {
  VertexOrder o;
  o.ends.resize(edge_ends.size());
  uint32_t top = 0;
  for (uint32_t v : edge_ends) top = std::max(top, v);
  std::vector<uint32_t> renamed(edge_ends.empty() ? 0 : size_t(top) + 1, UINT32_MAX);
  for (size_t i = 0; i < edge_ends.size(); ++i) {
    uint32_t& r = renamed[edge_ends[i]];
    if (r == UINT32_MAX) {
      r = uint32_t(o.vertex.size());
      o.vertex.push_back(edge_ends[i]);
    }
    o.ends[i] = r;
  }
  return o;
}

}  // namespace slicereuse
