#include "slicereuse/transfer/transfer_contours.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/slicing/edge_point.h"
#include "slicereuse/slicing/straddling_faces.h"
#include "slicereuse/util/error.h"
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

// Cuts layer k's encoded edges of the target by the layer's plane, into out at the encoding's
// offsets (and the target's encoding when out has room for it). Returns the certificate's first
// half: every edge still crosses from corner j below to corner j+1 at or above.
template <bool WithEncoding, class Ends>
bool transfer_layer(const Slices& enc, const Ends& ends, const Mesh& target, size_t k, Slices& out) {
  const double zk = enc.layer_z[k];
  const double* V = target.V.data();
  double* xyz = out.xyz.data();
  bool good = true;
  const size_t p0 = layer_point_begin(enc, k), p1 = layer_point_end(enc, k);
  for (size_t p = p0; p < p1; ++p) {
    uint32_t ia, ib;
    ends(p, ia, ib);
    const double* a = V + 3 * size_t(ia);
    const double* b = V + 3 * size_t(ib);
    good &= (a[2] < zk) & (b[2] >= zk);
    const EdgePoint e = edge_point(a, b, zk);
    xyz[3 * p] = e.x;
    xyz[3 * p + 1] = e.y;
    xyz[3 * p + 2] = zk;
    if (WithEncoding) out.t[p] = e.t;
  }
  if (WithEncoding) {
    std::memcpy(&out.face[p0], &enc.face[p0], (p1 - p0) * sizeof(uint32_t));
    std::memcpy(&out.edge[p0], &enc.edge[p0], p1 - p0);
  }
  return good;
}

template <class Ends>
Slices transfer_exact(const Slices& enc, const Ends& ends, const Mesh& target, bool with_encoding, TransferStats& st,
                      const Progress& progress) {
  std::vector<double> planes = target_planes(enc, target);
  const size_t L = planes.size(), Le = std::min(L, enc.layers());
  // The certificate's second half first, since it is cheap (O(faces + layers)): the target must
  // have exactly as many straddling edges as the layer has points (counted through its faces,
  // see straddling_faces.h), or the layer is re-sliced without being transferred at all.
  // A sample of the first half as well, as cheap (two points per contour): the first and the
  // middle point of every contour must still cross the plane the same way up. A member that
  // changed in z keeps its counts on most layers (its sections only move), so the counts alone
  // let it through to a full transfer that then fails almost everywhere; the sample catches it
  // before any point is transferred. Sampling only rejects layers the full check would reject.
  const std::vector<uint64_t> counts = straddling_face_counts(target, planes);
  const double* V = target.V.data();
  auto crosses = [&](size_t p, double zk) {
    uint32_t ia, ib;
    ends(p, ia, ib);
    return V[3 * size_t(ia) + 2] < zk && V[3 * size_t(ib) + 2] >= zk;
  };
  std::vector<uint8_t> ok(L, 0);
  size_t candidates = 0;
  for (size_t k = 0; k < Le; ++k) {
    ok[k] = counts[k] == layer_point_end(enc, k) - layer_point_begin(enc, k);
    for (size_t c = enc.layer_begin[k]; ok[k] && c < enc.layer_begin[k + 1]; ++c) {
      const size_t p0 = enc.contour_begin[c], p1 = enc.contour_begin[c + 1];
      ok[k] = !enc.contour_open[c] && crosses(p0, enc.layer_z[k]) && crosses((p0 + p1) / 2, enc.layer_z[k]);
    }
    candidates += ok[k];
  }
  // A member that changed in z can fail most layers; transferring the rest and splicing would
  // then cost more than slicing every layer (the result is the same by construction).
  if (2 * candidates < L) return slice_every_plane(target, std::move(planes), with_encoding, st, progress);
  Slices moved = layout_of(enc);
  if (with_encoding) {
    moved.face.resize(enc.points());
    moved.edge.resize(enc.points());
    moved.t.resize(enc.points());
  }
  for_each_layer(Le, progress, [&](size_t k) {
    if (ok[k])
      ok[k] = with_encoding ? transfer_layer<true>(enc, ends, target, k, moved)
                            : transfer_layer<false>(enc, ends, target, k, moved);
  });

  std::vector<size_t> done_layer(L, kNoLayer);
  for (size_t k = 0; k < Le; ++k)
    if (ok[k]) done_layer[k] = k;
  return splice_resliced(std::move(moved), done_layer, std::move(planes), target, with_encoding, st, progress);
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
  const Fingerprint fp = mesh_fingerprint(mesh);
  if (fp != encoding.fingerprint)
    throw Error("the target mesh's faces differ from those of the mesh the encoding was made from (encoding: " +
                describe_fingerprint(encoding.fingerprint) + "; target: " + describe_fingerprint(fp) +
                "); a target with other connectivity needs a cross-parameterization map (map file from Cross-Parameterize "
                "Meshes)");
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
  if (edge_ends.size() != 2 * encoding.points())
    throw Error("edge ends were computed for another encoding (" + std::to_string(edge_ends.size() / 2) +
                " points, the encoding has " + std::to_string(encoding.points()) + ")");
  return transfer(encoding, EndsFromPairs{edge_ends.data()}, target, options, stats, progress);
}

}  // namespace slicereuse
