#include "slicereuse/slicing/slice_layers.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "slicereuse/mesh/edge_links.h"
#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/slicing/contour_step.h"
#include "slicereuse/slicing/layer_planes.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/memory_budget.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse {
namespace {

// The planes a face straddles, [k0, k1), split at km: on [k0, km) its lowest corner `lo` is
// the lone corner below the plane, on [km, k1) its highest corner `hi` the lone corner at or
// above it, so the edges the contour enters and leaves by (contour_step.h) are fixed on each part.
struct FaceRange {
  uint32_t k0, km, k1;
  uint8_t lo, hi;
};

inline uint32_t exit_edge(const FaceRange& r, size_t k) {
  return k < r.km ? exit_edge_of_lone(r.lo, true) : exit_edge_of_lone(r.hi, false);
}
inline uint32_t entry_edge(const FaceRange& r, size_t k) {
  return k < r.km ? entry_edge_of_lone(r.lo, true) : entry_edge_of_lone(r.hi, false);
}

constexpr size_t kLayersPerBlock = 32;
// Output per point: xyz, face, edge, t.
constexpr size_t kBytesPerPoint = 3 * sizeof(double) + sizeof(uint32_t) + sizeof(uint8_t) + sizeof(double);

struct ActiveFace {
  uint32_t face, k1;
};

struct BlockContours {
  std::vector<uint32_t> per_layer;  // contours in each layer of the block
  std::vector<uint64_t> lengths;
  std::vector<uint8_t> open;
};

class LayerSlicer {
 public:
  LayerSlicer(const Mesh& mesh, const std::vector<uint32_t>& links, const std::vector<FaceRange>& ranges,
              const std::vector<double>& layer_z, Slices& out)
      : V_(mesh.V.data()), F_(mesh.F.data()), links_(links.data()), ranges_(ranges.data()),
        layer_z_(layer_z.data()), out_(out), encoding_(out.face.size() == out.xyz.size() / 3) {}

  // Appends layer k's contours (points from `cursor` to `end`) and their lengths to `block`.
  // stamp marks faces already chained in this layer; `stamp_value` is unique per layer.
  void slice(size_t k, const std::vector<ActiveFace>& active, bool has_unlinked, uint32_t* stamp,
             uint64_t cursor, uint64_t end, BlockContours& block) const {
    const uint32_t s = uint32_t(k + 1);
    uint32_t contours = 0;
    auto chain = [&](uint32_t f, bool open) {
      const uint64_t first = cursor;
      cursor = open ? walk<true>(f, k, s, stamp, cursor, end) : walk<false>(f, k, s, stamp, cursor, end);
      block.lengths.push_back(cursor - first);
      block.open.push_back(open);
      ++contours;
    };
    // Open polylines first, from their heads, so a closed walk never starts inside one.
    if (has_unlinked)
      for (const ActiveFace& a : active)
        if (links_[3 * a.face + entry_edge(ranges_[a.face], k)] == kUnlinked) chain(a.face, true);
    for (const ActiveFace& a : active)
      if (stamp[a.face] != s) chain(a.face, false);
    if (cursor != end) throw Error("internal error: layer " + std::to_string(k) + " point count mismatch");
    block.per_layer.push_back(contours);
  }

 private:
  template <bool Open>
  uint64_t walk(uint32_t f, size_t k, uint32_t s, uint32_t* stamp, uint64_t cursor, uint64_t end) const {
    const double zk = layer_z_[k];
    uint32_t je = exit_edge(ranges_[f], k);
    if (Open) {
      // The entry edge runs from corner js (at or above) down to corner js+1 (below).
      const uint32_t js = entry_edge(ranges_[f], k);
      const EdgePoint p = entry_point(V_, F_, f, js, zk);
      double t = 1 - p.t;
      uint32_t j = js;
      if (t == 0) {  // the point is corner js itself: name it as the end of the edge before
        j = (js + 2) % 3;
        t = 1;
      }
      emit(cursor++, end, p.x, p.y, zk, f, j, t);
    }
    const uint32_t first = f;
    for (;;) {
      stamp[f] = s;
      const EdgePoint p = exit_point(V_, F_, f, je, zk);
      emit(cursor++, end, p.x, p.y, zk, f, je, p.t);
      const uint32_t link = links_[3 * f + je];
      if (link == kUnlinked) break;
      const uint32_t g = link >> 2, sg = link & 3;
      if (!Open && g == first) break;
      je = next_exit_edge(V_, F_, g, sg, zk);
      f = g;
    }
    return cursor;
  }

  void emit(uint64_t i, uint64_t end, double x, double y, double z, uint32_t f, uint32_t j, double t) const {
    if (i >= end) throw Error("internal error: contour walk overran its layer");
    out_.xyz[3 * i] = x;
    out_.xyz[3 * i + 1] = y;
    out_.xyz[3 * i + 2] = z;
    if (!encoding_) return;
    out_.face[i] = f;
    out_.edge[i] = uint8_t(j);
    out_.t[i] = t;
  }

  const double* V_;
  const uint32_t* F_;
  const uint32_t* links_;
  const FaceRange* ranges_;
  const double* layer_z_;
  Slices& out_;
  const bool encoding_;  // the output has room for the encoding
};

FaceRange face_range(const Mesh& mesh, size_t f, const std::vector<double>& layer_z) {
  const double z[3] = {mesh.V[3 * size_t(mesh.F[3 * f]) + 2], mesh.V[3 * size_t(mesh.F[3 * f + 1]) + 2],
                       mesh.V[3 * size_t(mesh.F[3 * f + 2]) + 2]};
  uint8_t lo = 0, hi = 0;
  for (uint8_t c = 1; c < 3; ++c) {
    if (z[c] < z[lo]) lo = c;
    if (z[c] >= z[hi]) hi = c;
  }
  // lo is the first lowest corner and hi the last highest, so they differ even on a flat face
  // (whose ranges then come out empty).
  const uint8_t mid = uint8_t(3 - lo - hi);
  return {uint32_t(first_plane_above(layer_z, z[lo])), uint32_t(first_plane_above(layer_z, z[mid])),
          uint32_t(first_plane_above(layer_z, z[hi])), lo, hi};
}

// Phase 1: the planes every face straddles.
std::vector<FaceRange> face_ranges(const Mesh& mesh, const std::vector<double>& layer_z) {
  const size_t nf = mesh.faces();
  std::vector<FaceRange> ranges(nf);
#pragma omp parallel for schedule(static)
  for (long long f = 0; f < static_cast<long long>(nf); ++f) ranges[f] = face_range(mesh, size_t(f), layer_z);
  return ranges;
}

// Phase 2, in one pass over the faces: the exact point count of every layer before any
// chaining, so each layer writes straight into its slot of the flat output (one point per
// straddling face, plus the first point of every open polyline: a face whose entry edge has no
// neighbour), and how many faces start straddling at each layer.
struct LayerCounts {
  std::vector<uint64_t> point_begin;   // L+1: layer k's points are [point_begin[k], point_begin[k+1])
  std::vector<uint32_t> bucket_begin;  // L+2: after phase 3, bucket k is [bucket_begin[k], bucket_begin[k+1])
};

LayerCounts count_layers(const std::vector<FaceRange>& ranges, const EdgeLinks& links, size_t L) {
  LayerCounts c{std::vector<uint64_t>(L + 1, 0), std::vector<uint32_t>(L + 2, 0)};
  std::vector<int64_t> diff(L + 1, 0);
  for (size_t f = 0; f < ranges.size(); ++f) {
    const FaceRange& r = ranges[f];
    if (r.k0 < r.km) {
      const int64_t n = 1 + (links.links[3 * f + entry_edge(r, r.k0)] == kUnlinked);
      diff[r.k0] += n;
      diff[r.km] -= n;
    }
    if (r.km < r.k1) {
      const int64_t n = 1 + (links.links[3 * f + entry_edge(r, r.km)] == kUnlinked);
      diff[r.km] += n;
      diff[r.k1] -= n;
    }
    if (r.k0 < r.k1) ++c.bucket_begin[r.k0 + 1];
  }
  for (size_t k = 0, running = 0; k < L; ++k) {
    running += diff[k];
    c.point_begin[k + 1] = c.point_begin[k] + running;
  }
  return c;
}

// Phase 3: faces bucketed by the first layer they straddle (the sweep adds bucket k at layer k);
// turns bucket_begin from counts into offsets.
std::vector<uint32_t> bucket_faces(const std::vector<FaceRange>& ranges, std::vector<uint32_t>& bucket_begin) {
  const size_t L = bucket_begin.size() - 2;
  for (size_t k = 0; k <= L; ++k) bucket_begin[k + 1] += bucket_begin[k];
  std::vector<uint32_t> bucket(bucket_begin[L]);
  std::vector<uint32_t> cursor(bucket_begin.begin(), bucket_begin.end() - 1);
  for (size_t f = 0; f < ranges.size(); ++f)
    if (ranges[f].k0 < ranges[f].k1) bucket[cursor[ranges[f].k0]++] = uint32_t(f);
  return bucket;
}

// Phase 4: the active faces at the start of each block of layers, so blocks can run
// independently.
std::vector<std::vector<ActiveFace>> active_at_block_starts(const std::vector<FaceRange>& ranges,
                                                            const std::vector<uint32_t>& bucket,
                                                            const std::vector<uint32_t>& bucket_begin, size_t nb) {
  std::vector<std::vector<ActiveFace>> block_start(nb);
  std::vector<ActiveFace> active;
  for (size_t b = 0; b < nb; ++b) {
    const size_t b0 = b * kLayersPerBlock;
    if (b > 0)
      for (uint32_t i = bucket_begin[b0 - kLayersPerBlock]; i < bucket_begin[b0]; ++i)
        active.push_back({bucket[i], ranges[bucket[i]].k1});
    active.erase(std::remove_if(active.begin(), active.end(), [&](const ActiveFace& a) { return a.k1 <= b0; }),
                 active.end());
    block_start[b] = active;
  }
  return block_start;
}

// Phase 5: every block of layers swept and chained, in parallel, straight into out's points
// (sized by phase 2); returns each block's contour list.
std::vector<BlockContours> sweep_blocks(const Mesh& mesh, const EdgeLinks& links, const std::vector<FaceRange>& ranges,
                                        const LayerCounts& counts, const std::vector<uint32_t>& bucket,
                                        std::vector<std::vector<ActiveFace>> block_start, Slices& out,
                                        const Progress& progress) {
  const size_t L = out.layers(), nb = block_start.size();
  const bool has_unlinked = links.unlinked > 0;
  const LayerSlicer slicer(mesh, links.links, ranges, out.layer_z, out);
  std::vector<BlockContours> blocks(nb);
  std::vector<std::vector<uint32_t>> stamps(omp_get_max_threads());
  parallel_blocks(
      nb,
      [&](size_t b) {
        std::vector<uint32_t>& stamp = stamps[omp_get_thread_num()];
        if (stamp.empty()) stamp.assign(mesh.faces(), 0);
        std::vector<ActiveFace> active = std::move(block_start[b]);
        const size_t b0 = b * kLayersPerBlock, b1 = std::min(L, b0 + kLayersPerBlock);
        for (size_t k = b0; k < b1; ++k) {
          for (uint32_t i = counts.bucket_begin[k]; i < counts.bucket_begin[k + 1]; ++i)
            active.push_back({bucket[i], ranges[bucket[i]].k1});
          active.erase(std::remove_if(active.begin(), active.end(), [&](const ActiveFace& a) { return a.k1 <= k; }),
                       active.end());
          slicer.slice(k, active, has_unlinked, stamp.data(), counts.point_begin[k], counts.point_begin[k + 1],
                       blocks[b]);
        }
      },
      progress, "slicing");
  return blocks;
}

// Phase 6: the blocks' contour lists stitched into the flat arrays, in layer order.
void stitch_blocks(const std::vector<BlockContours>& blocks, size_t L, Slices& out) {
  size_t C = 0;
  for (const BlockContours& b : blocks) C += b.lengths.size();
  out.layer_begin.resize(L + 1);
  out.contour_begin.resize(C + 1);
  out.contour_open.resize(C);
  out.layer_begin[0] = 0;
  out.contour_begin[0] = 0;
  size_t k = 0, c = 0;
  for (const BlockContours& b : blocks) {
    for (uint32_t n : b.per_layer) {
      out.layer_begin[k + 1] = out.layer_begin[k] + n;
      ++k;
    }
    for (size_t i = 0; i < b.lengths.size(); ++i, ++c) {
      out.contour_begin[c + 1] = out.contour_begin[c] + b.lengths[i];
      out.contour_open[c] = b.open[i];
    }
  }
}

}  // namespace

std::vector<double> slicing_planes(const Mesh& mesh, const SliceOptions& options, double* z_start) {
  validate_mesh(mesh);
  const ZRange z = z_range(mesh);
  const double start = std::isnan(options.z_start) ? z.min : options.z_start;
  if (z_start) *z_start = start;
  return layer_planes(start, options.thickness, z.max);
}

Slices slice_layers(const Mesh& mesh, const SliceOptions& options, const Progress& progress) {
  double z_start = 0;
  std::vector<double> planes = slicing_planes(mesh, options, &z_start);
  Slices out = slice_planes(mesh, std::move(planes), progress, options.encoding);
  out.z_start = z_start;
  out.thickness = options.thickness;
  return out;
}

Slices slice_planes(const Mesh& mesh, std::vector<double> planes, const Progress& progress, bool with_encoding) {
  validate_mesh(mesh);
  if (!std::is_sorted(planes.begin(), planes.end())) throw Error("slice planes must be in increasing order");
  report_progress(progress, 0, "preparing");
  Slices out;
  out.layer_z = std::move(planes);
  out.fingerprint = mesh_fingerprint(mesh);
  const size_t L = out.layers();

  const EdgeLinks links = edge_links(mesh);
  const std::vector<FaceRange> ranges = face_ranges(mesh, out.layer_z);
  LayerCounts counts = count_layers(ranges, links, L);
  const size_t P = counts.point_begin[L];
  check_memory_for(P * (with_encoding ? kBytesPerPoint : 3 * sizeof(double)), format("slicing %zu layers into %zu contour points", L, P),
                   "use a thicker layer, or fewer layers (z_start)");
  out.xyz.resize(3 * P);
  if (with_encoding) {
    out.face.resize(P);
    out.edge.resize(P);
    out.t.resize(P);
  }
  const std::vector<uint32_t> bucket = bucket_faces(ranges, counts.bucket_begin);
  const size_t nb = (L + kLayersPerBlock - 1) / kLayersPerBlock;
  std::vector<std::vector<ActiveFace>> block_start = active_at_block_starts(ranges, bucket, counts.bucket_begin, nb);

  const std::vector<BlockContours> blocks =
      sweep_blocks(mesh, links, ranges, counts, bucket, std::move(block_start), out, progress);
  stitch_blocks(blocks, L, out);
  report_progress(progress, 1, "slicing");
  return out;
}

}  // namespace slicereuse
