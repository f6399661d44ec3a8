#include "slicereuse/transfer/transfer_through_map.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "slicereuse/mesh/edge_links.h"
#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/slicing/contour_step.h"
#include "slicereuse/slicing/straddling_faces.h"
#include "slicereuse/slicing/trace_contour.h"
#include "slicereuse/util/error.h"
#include "transfer_layers.h"

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

// Carried points are placed on the target's section (barycentric_through_map): the walk along
// the section from a seed goes on while the section comes nearer to the point, and this many
// faces past the nearest one.
constexpr int kStepsPastNearest = 3;

// The point of the target's section at zk nearest (in xy) to a carried point q, over the
// section's segments offered: each straddling face's segment from its entry to its exit
// crossing, both computed as the slicer computes them (contour_step.h).
struct NearestOnSection {
  double d2 = HUGE_VAL, x = 0, y = 0;
  void offer(const Mesh& target, uint32_t f, const SectionEdges& e, double zk, const double* q) {
    const EdgePoint a = entry_point(target.V.data(), target.F.data(), f, e.entry, zk);
    const EdgePoint b = exit_point(target.V.data(), target.F.data(), f, e.exit, zk);
    const double ux = b.x - a.x, uy = b.y - a.y, len2 = ux * ux + uy * uy;
    const double s = len2 > 0 ? std::clamp(((q[0] - a.x) * ux + (q[1] - a.y) * uy) / len2, 0.0, 1.0) : 0.0;
    const double px = a.x + s * ux, py = a.y + s * uy;
    const double d2_here = (q[0] - px) * (q[0] - px) + (q[1] - py) * (q[1] - py);
    if (d2_here < d2) d2 = d2_here, x = px, y = py;
  }
};

// Walks the section's loop through `seed` forward (through exit edges) and backward (through
// entry edges), each way until kStepsPastNearest faces past the nearest segment so far, offering
// each face's segment to `nearest` and appending the faces walked to `walked`.
void nearest_along_loop(const Mesh& target, const std::vector<uint32_t>& links, double zk, uint32_t seed,
                        const double* q, NearestOnSection& nearest, std::vector<uint32_t>& walked) {
  for (const bool forward : {true, false}) {
    uint32_t f = seed;
    for (int past = 0; past < kStepsPastNearest; ++past) {
      const SectionEdges e = section_edges(target.V.data(), target.F.data(), f, zk);
      if (e.exit == kNoEdge) break;
      const double before = nearest.d2;
      nearest.offer(target, f, e, zk, q);
      if (nearest.d2 < before) past = 0;
      walked.push_back(f);
      const uint32_t link = links[3 * size_t(f) + (forward ? e.exit : e.entry)];
      if (link == kUnlinked || (link >> 2) == seed) break;
      f = link >> 2;
    }
  }
}

// Barycentric transfer's contours without those none of whose points was placed on the
// target's section: the target has no surface at that height there (a dome's top that is lower
// on the target), so such a contour would print material that the target does not have. Counts
// them in stats.dropped_contours and the other contours' unplaced points in
// stats.unplaced_points. Only the first `carried` layers were carried (a shorter target's planes
// end below the source's top); the others' contours are kept as they are, unused and uncounted.
// s has xyz only.
Slices without_unplaced_contours(Slices s, size_t carried, const std::vector<uint8_t>& placed, TransferStats& st) {
  std::vector<uint8_t> keep(s.contours(), 1);
  for (size_t c = 0; c < s.layer_begin[carried]; ++c) {
    const auto first = placed.begin() + s.contour_begin[c], last = placed.begin() + s.contour_begin[c + 1];
    keep[c] = std::find(first, last, 1) != last;
    if (keep[c]) st.unplaced_points += size_t(std::count(first, last, 0));
    else ++st.dropped_contours;
  }
  if (st.dropped_contours == 0) return s;
  Slices out;
  out.z_start = s.z_start;
  out.thickness = s.thickness;
  out.layer_z = s.layer_z;
  out.layer_begin.assign(1, 0);
  out.contour_begin.assign(1, 0);
  out.xyz.reserve(s.xyz.size());
  for (size_t k = 0; k < s.layers(); ++k) {
    for (size_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c) {
      if (!keep[c]) continue;
      out.xyz.insert(out.xyz.end(), s.xyz.begin() + 3 * s.contour_begin[c], s.xyz.begin() + 3 * s.contour_begin[c + 1]);
      out.contour_begin.push_back(out.xyz.size() / 3);
      out.contour_open.push_back(s.contour_open[c]);
    }
    out.layer_begin.push_back(out.contour_open.size());
  }
  return out;
}

// Layers follow the target's top as in exact mode, so the result has direct slicing's layers:
// the source's layers are carried up to it, and a taller target's extra layers, which no source
// point reaches, are re-sliced directly (and counted so).
Slices barycentric_through_map(const Slices& enc, const SurfaceMap& map, const Mesh& target, TransferStats& st,
                               const Progress& progress) {
  std::vector<double> planes = target_planes(enc, target);
  const size_t L = planes.size(), Le = std::min(L, enc.layers());
  Slices out = layout_of(enc);
  const EdgeLinks links = edge_links(target);
  const EndsFromFaces ends{enc.edge.data(), enc.face.data(), map.source_faces.data()};
  std::vector<double> deviation(Le, 0);
  std::vector<uint8_t> placed(enc.points(), 0);
  for_each_layer(Le, progress, [&](size_t k) {
    const double zk = enc.layer_z[k];
    double worst = 0;
    std::vector<uint32_t> walked;
    // A vertex's seed face on this plane; consecutive points share an edge end (the faces the
    // contour crosses), so the last two are remembered.
    uint32_t known_vertex[2] = {kNoSeed, kNoSeed}, known_seed[2] = {kNoSeed, kNoSeed}, next = 0;
    auto seed_of_vertex = [&](uint32_t v) {
      for (int j = 0; j < 2; ++j)
        if (known_vertex[j] == v) return known_seed[j];
      known_vertex[next] = v;
      known_seed[next] = level_face_near(target, links.links, map.face[v], zk);
      const uint32_t seed = known_seed[next];
      next ^= 1;
      return seed;
    };
    for (size_t p = layer_point_begin(enc, k); p < layer_point_end(enc, k); ++p) {
      uint32_t a, b;
      ends(p, a, b);
      double ga[3], gb[3];
      map_point(map, target, a, ga);
      map_point(map, target, b, gb);
      const double t = enc.t[p];
      const double q[2] = {(1 - t) * ga[0] + t * gb[0], (1 - t) * ga[1] + t * gb[1]};
      worst = std::max(worst, std::abs((1 - t) * ga[2] + t * gb[2] - zk));
      // q lies on the chord between two target surface points, off the target's surface; where
      // the surface is nearly horizontal (domes' tops, ridges) the chord's small sag below it is
      // a large shift in the plane. By the in-plane constraint p's image is the point of the
      // target's surface at z_k, i.e. of its section, nearest to q, as each vertex's image is the
      // point of the target's level set nearest to the vertex's registered position. It is sought
      // along the loop(s) that the faces of the two images lead to, walked to the plane.
      NearestOnSection nearest;
      walked.clear();
      const uint32_t seed_a = seed_of_vertex(a), seed_b = seed_of_vertex(b);
      if (seed_a != kNoSeed) nearest_along_loop(target, links.links, zk, seed_a, q, nearest, walked);
      // Both images usually lead to the same stretch of the loop: walked once.
      if (seed_b != kNoSeed && std::find(walked.begin(), walked.end(), seed_b) == walked.end())
        nearest_along_loop(target, links.links, zk, seed_b, q, nearest, walked);
      // p's image lies between its edge's images: a section point farther from q than they are
      // apart is on another loop (the walk to the plane crossed a cap), and q stays (counted).
      const double span2 = (ga[0] - gb[0]) * (ga[0] - gb[0]) + (ga[1] - gb[1]) * (ga[1] - gb[1]) +
                           (ga[2] - gb[2]) * (ga[2] - gb[2]);
      placed[p] = nearest.d2 <= span2;
      out.xyz[3 * p] = placed[p] ? nearest.x : q[0];
      out.xyz[3 * p + 1] = placed[p] ? nearest.y : q[1];
      out.xyz[3 * p + 2] = zk;
    }
    deviation[k] = worst;
  });
  st.max_plane_deviation = deviation.empty() ? 0 : *std::max_element(deviation.begin(), deviation.end());
  out = without_unplaced_contours(std::move(out), Le, placed, st);
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
  return reported_transfer(encoding, map.target, stats, progress, [&](TransferStats& st) {
    return options.mode == TransferMode::Barycentric ? barycentric_through_map(encoding, map, target, st, progress)
                                                     : exact_through_map(encoding, map, target, options.encoding,
                                                                         st, progress);
  });
}

}  // namespace slicereuse
