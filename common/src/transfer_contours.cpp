#include "slicereuse/transfer_contours.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "slicereuse/edge_links.h"
#include "slicereuse/edge_point.h"
#include "slicereuse/error.h"
#include "slicereuse/fingerprint.h"
#include "slicereuse/layer_planes.h"
#include "slicereuse/parallel_blocks.h"
#include "slicereuse/slice_layers.h"
#include "slicereuse/straddling_edges.h"

namespace slicereuse {
namespace {

constexpr size_t kLayersPerBlock = 64;

std::string describe(const Fingerprint& fp) {
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fp.hash));
  return std::to_string(fp.faces) + " faces, hash " + hash;
}

size_t first_point(const Slices& s, size_t k) { return s.contour_begin[s.layer_begin[k]]; }
size_t end_point(const Slices& s, size_t k) { return s.contour_begin[s.layer_begin[k + 1]]; }

void for_each_layer(size_t L, const Progress& progress, const std::function<void(size_t)>& body) {
  parallel_blocks(
      (L + kLayersPerBlock - 1) / kLayersPerBlock,
      [&](size_t b) {
        for (size_t k = b * kLayersPerBlock; k < std::min(L, (b + 1) * kLayersPerBlock); ++k) body(k);
      },
      progress, "transferring");
}

// Slices with enc's layers and contours, and room for their points.
Slices same_layout(const Slices& enc) {
  Slices out;
  out.layer_z = enc.layer_z;
  out.layer_begin = enc.layer_begin;
  out.contour_begin = enc.contour_begin;
  out.contour_open = enc.contour_open;
  out.xyz.resize(3 * enc.points());
  return out;
}

// The planes direct slicing of the target uses: the source's (every member sits on the same
// build plate) up to the target's own top, so a taller member gets its extra layers and a
// shorter one no empty ones.
std::vector<double> target_planes(const Slices& enc, const Mesh& target) {
  if (!(enc.thickness > 0)) return enc.layer_z;
  double zmax = target.V[2];
  for (size_t i = 2; i < target.V.size(); i += 3) zmax = std::max(zmax, target.V[i]);
  std::vector<double> planes = layer_planes(enc.z_start, enc.thickness, zmax);
  std::copy_n(enc.layer_z.begin(), std::min(planes.size(), enc.layers()), planes.begin());
  return planes;
}

// Cuts layer k's encoded edges of the target by the layer's plane, into out at the encoding's
// offsets. Returns the certificate's first half: every edge still crosses from corner j below
// to corner j+1 at or above.
bool transfer_layer(const Slices& enc, const Mesh& target, size_t k, Slices& out) {
  const double zk = enc.layer_z[k];
  const double* V = target.V.data();
  const uint32_t* F = target.F.data();
  bool good = true;
  const size_t p0 = first_point(enc, k), p1 = end_point(enc, k);
  for (size_t p = p0; p < p1; ++p) {
    const size_t f = enc.face[p], j = enc.edge[p];
    const double* a = V + 3 * size_t(F[3 * f + j]);
    const double* b = V + 3 * size_t(F[3 * f + (j + 1) % 3]);
    good &= (a[2] < zk) & (b[2] >= zk);
    const EdgePoint e = edge_point(a, b, zk);
    out.xyz[3 * p] = e.x;
    out.xyz[3 * p + 1] = e.y;
    out.xyz[3 * p + 2] = zk;
    out.t[p] = e.t;
  }
  std::memcpy(&out.face[p0], &enc.face[p0], (p1 - p0) * sizeof(uint32_t));
  std::memcpy(&out.edge[p0], &enc.edge[p0], p1 - p0);
  return good;
}

// Layer k of the result is layer pick[k].layer of *pick[k].from.
struct Pick {
  const Slices* from;
  size_t layer;
};

Slices assemble(const std::vector<Pick>& pick, std::vector<double> planes, const Progress& progress) {
  const size_t L = pick.size();
  Slices out;
  out.layer_z = std::move(planes);
  out.layer_begin.assign(1, 0);
  out.contour_begin.assign(1, 0);
  std::vector<size_t> point_begin(L + 1, 0);
  for (size_t k = 0; k < L; ++k) {
    const Slices& s = *pick[k].from;
    const size_t sk = pick[k].layer;
    for (size_t c = s.layer_begin[sk]; c < s.layer_begin[sk + 1]; ++c) {
      out.contour_open.push_back(s.contour_open[c]);
      out.contour_begin.push_back(out.contour_begin.back() + s.contour_begin[c + 1] - s.contour_begin[c]);
    }
    out.layer_begin.push_back(out.contour_open.size());
    point_begin[k + 1] = out.contour_begin.back();
  }
  const size_t P = point_begin[L];
  out.xyz.resize(3 * P);
  out.face.resize(P);
  out.edge.resize(P);
  out.t.resize(P);
  for_each_layer(L, progress, [&](size_t k) {
    const Slices& s = *pick[k].from;
    const size_t p0 = first_point(s, pick[k].layer), n = end_point(s, pick[k].layer) - p0, q = point_begin[k];
    std::memcpy(&out.xyz[3 * q], &s.xyz[3 * p0], 3 * n * sizeof(double));
    std::memcpy(&out.face[q], &s.face[p0], n * sizeof(uint32_t));
    std::memcpy(&out.edge[q], &s.edge[p0], n);
    std::memcpy(&out.t[q], &s.t[p0], n * sizeof(double));
  });
  return out;
}

Slices transfer_exact(const Slices& enc, const Mesh& target, TransferStats& st, const Progress& progress) {
  std::vector<double> planes = target_planes(enc, target);
  const size_t L = planes.size(), Le = std::min(L, enc.layers());
  // The certificate's second half first, since it is cheap (O(edges + layers)): the target must
  // have exactly as many straddling edges as the layer has points, or the layer is re-sliced
  // without being transferred at all.
  const std::vector<uint64_t> counts = straddling_edge_counts(target, edge_links(target), planes);
  std::vector<uint8_t> ok(L, 0);
  for (size_t k = 0; k < Le; ++k) {
    ok[k] = counts[k] == end_point(enc, k) - first_point(enc, k);
    for (size_t c = enc.layer_begin[k]; c < enc.layer_begin[k + 1]; ++c) ok[k] &= !enc.contour_open[c];
  }
  Slices moved = same_layout(enc);
  moved.face.resize(enc.points());
  moved.edge.resize(enc.points());
  moved.t.resize(enc.points());
  for_each_layer(Le, progress, [&](size_t k) {
    if (ok[k]) ok[k] = transfer_layer(enc, target, k, moved);
  });

  std::vector<size_t> redo;
  std::vector<double> redo_planes;
  for (size_t k = 0; k < L; ++k)
    if (!ok[k]) {
      redo.push_back(k);
      redo_planes.push_back(planes[k]);
    }
  if (redo.empty() && L == enc.layers()) {
    st.transferred_layers = L;
    return moved;
  }
  // A member that changed in z can fail most layers; splicing would then cost a full copy on
  // top of slicing, so slice every layer instead (the result is the same by construction).
  if (2 * redo.size() > L) {
    st.resliced_layers = L;
    return slice_planes(target, std::move(planes), progress);
  }
  st.resliced_layers = redo.size();
  st.transferred_layers = L - redo.size();
  Slices fresh = slice_planes(target, std::move(redo_planes), progress);
  std::vector<Pick> pick(L);
  for (size_t k = 0, r = 0; k < L; ++k) pick[k] = r < redo.size() && redo[r] == k ? Pick{&fresh, r++} : Pick{&moved, k};
  return assemble(pick, std::move(planes), progress);
}

Slices transfer_barycentric(const Slices& enc, const Mesh& target, TransferStats& st, const Progress& progress) {
  Slices out = same_layout(enc);
  const double* V = target.V.data();
  const uint32_t* F = target.F.data();
  std::vector<double> deviation(enc.layers(), 0);
  for_each_layer(enc.layers(), progress, [&](size_t k) {
    double worst = 0;
    for (size_t p = first_point(enc, k); p < end_point(enc, k); ++p) {
      const size_t f = enc.face[p], j = enc.edge[p];
      const double* a = V + 3 * size_t(F[3 * f + j]);
      const double* b = V + 3 * size_t(F[3 * f + (j + 1) % 3]);
      const double t = enc.t[p];
      for (int d = 0; d < 3; ++d) out.xyz[3 * p + d] = (1 - t) * a[d] + t * b[d];
      worst = std::max(worst, std::abs(out.xyz[3 * p + 2] - enc.layer_z[k]));
    }
    deviation[k] = worst;
  });
  out.face = enc.face;
  out.edge = enc.edge;
  out.t = enc.t;
  st.transferred_layers = enc.layers();
  st.max_plane_deviation = deviation.empty() ? 0 : *std::max_element(deviation.begin(), deviation.end());
  return out;
}

}  // namespace

Slices transfer_contours(const Slices& encoding, const Mesh& target, TransferMode mode, TransferStats* stats,
                         const Progress& progress) {
  validate_mesh(target);
  if (!encoding.has_encoding()) throw Error("transfer needs an encoding (face and area coordinates per point)");
  const Fingerprint fp = mesh_fingerprint(target);
  if (fp != encoding.fingerprint)
    throw Error("the target mesh's faces differ from those of the mesh the encoding was made from (encoding: " +
                describe(encoding.fingerprint) + "; target: " + describe(fp) +
                "); a cross-parameterization map is needed for a target with other connectivity");
  report_progress(progress, 0, "transferring");
  TransferStats st;
  Slices out = mode == TransferMode::Barycentric ? transfer_barycentric(encoding, target, st, progress)
                                                  : transfer_exact(encoding, target, st, progress);
  out.z_start = encoding.z_start;
  out.thickness = encoding.thickness;
  out.fingerprint = fp;
  report_progress(progress, 1, "transferring");
  if (stats) *stats = st;
  return out;
}

}  // namespace slicereuse
