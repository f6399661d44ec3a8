#include "slicereuse/transfer_through_map.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "slicereuse/edge_links.h"
#include "slicereuse/error.h"
#include "slicereuse/fingerprint.h"
#include "slicereuse/straddling_faces.h"
#include "slicereuse/trace_contour.h"
#include "slicereuse/transfer_layers.h"

namespace slicereuse {
namespace {

// How far a seed may be walked towards the plane. The map puts the images of an encoded
// edge's two ends on either side of the plane (exactly so when it is in-plane), so the target's
// contour lies between them, usually in one of their faces or a few faces away.
constexpr int kMaxSeedSteps = 64;

// A face straddling zk found from face f by walking up (f below the plane) or down (f above it)
// across the edge opposite f's lowest (highest) corner; kNoSeed when none within the steps.
constexpr uint32_t kNoSeed = 0xffffffffu;
uint32_t level_face_near(const Mesh& target, const std::vector<uint32_t>& links, uint32_t f, double zk) {
  for (int step = 0; step < kMaxSeedSteps; ++step) {
    const uint32_t* c = &target.F[3 * size_t(f)];
    const double z[3] = {target.V[3 * size_t(c[0]) + 2], target.V[3 * size_t(c[1]) + 2],
                         target.V[3 * size_t(c[2]) + 2]};
    const uint32_t lo = uint32_t(std::min_element(z, z + 3) - z), hi = uint32_t(std::max_element(z, z + 3) - z);
    if (z[lo] < zk && z[hi] >= zk) return f;
    const uint32_t away = z[hi] < zk ? lo : hi;  // the corner farthest from the plane
    const uint32_t link = links[3 * size_t(f) + (away + 1) % 3];
    if (link == kUnlinked) return kNoSeed;
    f = link >> 2;
  }
  return kNoSeed;
}

// A seed for the loop(s) that source point p's images lead to: the faces of its edge ends'
// images, walked to the plane.
template <class Ends>
uint32_t seed_of(size_t p, const Ends& ends, const SurfaceMap& map, const Mesh& target,
                 const std::vector<uint32_t>& links, double zk) {
  uint32_t a, b;
  ends(p, a, b);
  const uint32_t seed = level_face_near(target, links, map.face[a], zk);
  return seed != kNoSeed ? seed : level_face_near(target, links, map.face[b], zk);
}

Slices exact_through_map(const Slices& enc, const SurfaceMap& map, const Mesh& target, bool with_encoding,
                         TransferStats& st, const Progress& progress) {
  std::vector<double> planes = target_planes(enc, target);
  const size_t L = planes.size(), Le = std::min(L, enc.layers());
  // The certificate: every traced loop closes, and the loops hold one point per face of the
  // target that straddles the plane, so no loop of the target's section was missed. The counts
  // also size each layer's slot in the output, so tracing writes in place.
  const std::vector<uint64_t> counts = straddling_face_counts(target, planes);
  std::vector<uint64_t> slot(Le + 1, 0);
  for (size_t k = 0; k < Le; ++k) slot[k + 1] = slot[k] + counts[k];
  Slices traced;
  traced.xyz.resize(3 * slot[Le]);
  if (with_encoding) {
    traced.face.resize(slot[Le]);
    traced.edge.resize(slot[Le]);
    traced.t.resize(slot[Le]);
  }
  const EdgeLinks links = edge_links(target);
  const EndsFromFaces ends{enc.edge.data(), enc.face.data(), map.source_faces.data()};
  std::vector<std::vector<uint64_t>> lengths(Le);
  std::vector<uint8_t> ok(Le, 0);
  std::vector<std::vector<uint32_t>> stamps(omp_get_max_threads());
  for_each_layer(Le, progress, [&](size_t k) {
    std::vector<uint32_t>& stamp = stamps[omp_get_thread_num()];
    if (stamp.empty()) stamp.assign(target.faces(), 0);
    const double zk = planes[k];
    const uint32_t s = uint32_t(k + 1);
    ContourSink sink{&traced.xyz[3 * slot[k]], nullptr, nullptr, nullptr, 0, counts[k], {}};
    if (with_encoding) {
      sink.face = &traced.face[slot[k]];
      sink.edge = &traced.edge[slot[k]];
      sink.t = &traced.t[slot[k]];
    }
    // One seed per source contour usually finds every loop; all points are tried only when the
    // section's topology differs from the source's.
    bool good = true;
    auto try_seed = [&](size_t p) {
      const uint32_t seed = seed_of(p, ends, map, target, links.links, zk);
      if (seed != kNoSeed && stamp[seed] != s) good = trace_contour(target, links.links, zk, seed, s, stamp.data(), sink);
    };
    for (size_t c = enc.layer_begin[k]; good && sink.cursor < sink.end && c < enc.layer_begin[k + 1]; ++c)
      try_seed(enc.contour_begin[c]);
    for (size_t p = layer_point_begin(enc, k); good && sink.cursor < sink.end && p < layer_point_end(enc, k); ++p)
      try_seed(p);
    ok[k] = good && sink.cursor == sink.end;
    lengths[k] = std::move(sink.lengths);
  });
  // Layer offsets over the slots. A layer that failed keeps its slot as one placeholder contour,
  // so the offsets of the others stay right; it is never picked (re-sliced instead).
  traced.layer_z.assign(planes.begin(), planes.begin() + Le);
  traced.layer_begin.assign(1, 0);
  traced.contour_begin.assign(1, 0);
  std::vector<size_t> done_layer(L, kNoLayer);
  for (size_t k = 0; k < Le; ++k) {
    if (ok[k]) {
      done_layer[k] = k;
      for (uint64_t n : lengths[k]) traced.contour_begin.push_back(traced.contour_begin.back() + n);
    } else if (counts[k] > 0) {
      traced.contour_begin.push_back(slot[k + 1]);
    }
    traced.layer_begin.push_back(traced.contour_begin.size() - 1);
  }
  traced.contour_open.assign(traced.contour_begin.size() - 1, 0);
  return splice_resliced(std::move(traced), done_layer, std::move(planes), target, with_encoding, st, progress);
}

// Layers follow the target's top as in exact mode, so the result has direct slicing's layers:
// the source's layers are carried up to it, and a taller target's extra layers, which no source
// point reaches, are re-sliced directly (and counted so).
Slices barycentric_through_map(const Slices& enc, const SurfaceMap& map, const Mesh& target, TransferStats& st,
                               const Progress& progress) {
  std::vector<double> planes = target_planes(enc, target);
  const size_t L = planes.size(), Le = std::min(L, enc.layers());
  Slices out = layout_of(enc);
  const EndsFromFaces ends{enc.edge.data(), enc.face.data(), map.source_faces.data()};
  std::vector<double> deviation(Le, 0);
  for_each_layer(Le, progress, [&](size_t k) {
    const double zk = enc.layer_z[k];
    double worst = 0;
    for (size_t p = layer_point_begin(enc, k); p < layer_point_end(enc, k); ++p) {
      uint32_t a, b;
      ends(p, a, b);
      double ga[3], gb[3];
      map_point(map, target, a, ga);
      map_point(map, target, b, gb);
      const double t = enc.t[p];
      out.xyz[3 * p] = (1 - t) * ga[0] + t * gb[0];
      out.xyz[3 * p + 1] = (1 - t) * ga[1] + t * gb[1];
      worst = std::max(worst, std::abs((1 - t) * ga[2] + t * gb[2] - zk));
      out.xyz[3 * p + 2] = zk;
    }
    deviation[k] = worst;
  });
  st.max_plane_deviation = deviation.empty() ? 0 : *std::max_element(deviation.begin(), deviation.end());
  std::vector<size_t> done_layer(L, kNoLayer);
  for (size_t k = 0; k < Le; ++k) done_layer[k] = k;
  return splice_resliced(std::move(out), done_layer, std::move(planes), target, false, st, progress);
}

}  // namespace

Slices transfer_through_map(const Slices& encoding, const SurfaceMap& map, const Mesh& target,
                            const TransferOptions& options, TransferStats* stats, const Progress& progress) {
  validate_mesh(target);
  if (!encoding.has_encoding())
    throw Error("transfer through a map needs an encoding (face and area coordinates per point)");
  validate_surface_map(map);
  if (encoding.fingerprint != map.source)
    throw Error("the encoding was made from a mesh with other faces than the map's source (encoding: " +
                describe_fingerprint(encoding.fingerprint) + "; map's source: " + describe_fingerprint(map.source) +
                ")");
  check_map_target(map, target);
  if (options.mode == TransferMode::Barycentric && options.encoding)
    throw Error("barycentric transfer through a map puts points inside the target's faces, not on its edges, so it "
                "gives no target encoding; use exact mode (0) to write the target's encoding");
  report_progress(progress, 0, "transferring");
  TransferStats st;
  Slices out = options.mode == TransferMode::Barycentric
                   ? barycentric_through_map(encoding, map, target, st, progress)
                   : exact_through_map(encoding, map, target, options.encoding, st, progress);
  out.z_start = encoding.z_start;
  out.thickness = encoding.thickness;
  out.fingerprint = map.target;
  report_progress(progress, 1, "transferring");
  if (stats) *stats = st;
  return out;
}

}  // namespace slicereuse
