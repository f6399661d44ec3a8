#include "slicereuse/plates/plate_job.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>

#include "slicereuse/slicing/layer_chunks.h"
#include "slicereuse/slicing/layer_planes.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/parallel_blocks.h"
#include "slicereuse/util/seconds_since.h"

namespace slicereuse {
namespace {

// Reusing, a range holds at most this many bytes of points, whatever the budget: a range costs
// what its points do (ExactTransfer), and a plate then fills at most this much fresh memory,
// which the kernel zeroes first (on the development VM at 0.5 to 10 GB/s from run to run: a
// member of the arch at 1 um, 1.8 GB of points, spent 0.1 to 2 s there). Plates of the SL1S at
// 0.05 mm (100 to 180 MB) are one range; smaller ranges (64 MB) made them slower.
constexpr uint64_t kReusedRangeBytes = uint64_t(256) << 20;

// The plate's layers [a, b) as parts (export_masks.h), one per member that has any of them: each
// member's own layers there (own[m]: how many it has), by transfer (transfers[m], when reusing:
// layers above the encoding's are sliced directly within it) or sliced directly. The masks draw
// each member's layers where they are, without a merged copy.
std::vector<SlicePart> plate_range(const std::vector<Mesh>& placed, const std::vector<ExactTransfer>& transfers,
                                   const std::vector<double>& planes, const std::vector<size_t>& own, size_t a,
                                   size_t b, PlateJobStats& st, const Progress& progress) {
  const size_t n = placed.size();
  std::vector<SlicePart> parts;
  for (size_t m = 0; m < n; ++m) {
    const Progress mp = sub_progress(progress, double(m) / double(n), double(m + 1) / double(n));
    const size_t e = std::min(b, own[m]);
    if (a >= e) continue;
    if (transfers.empty()) {
      parts.push_back({slice_planes(placed[m], {planes.begin() + long(a), planes.begin() + long(e)}, mp, false), 0});
      st.resliced_layers += e - a;
    } else {
      TransferStats ts;
      parts.push_back({transfers[m].layers(a, e, &ts, mp), 0});
      st.transferred_layers += ts.transferred_layers;
      st.resliced_layers += ts.resliced_layers;
    }
    Slices& made = parts.back().slices;
    made.z_start = st.z_start + double(a) * st.thickness;
    made.thickness = st.thickness;
    st.points += made.points();
  }
  return parts;
}

constexpr size_t kPointBytes = 3 * sizeof(double);
constexpr size_t kNotDirect = SIZE_MAX;

// A member's layers sliced directly on a plate made where drawn (MadeWhereDrawn): the planes,
// their slices once made, and for each of the member's layers its layer there (or kNotDirect).
struct DirectLayers {
  std::vector<size_t> at;
  std::vector<double> planes;
  Slices slices;

  void add(size_t k, double z) {
    at[k] = planes.size();
    planes.push_back(z);
  }
};

// The member's layers that its transfer t cannot make: those the cheap certificate refuses
// (above the source's top, or failing the counts or sample), and, when there are any (the member
// changed in z, and then some layers that pass the sample fail the whole certificate: 4 to 18 of
// 290 for members of the arch family), those the whole certificate refuses too, found now, so
// that all are sliced in one pass. (Slicing one plane costs as much as slicing them all, about
// 0.05 s for the 545k-face arch: its faces are sorted first.)
DirectLayers layers_to_slice(const ExactTransfer& t) {
  bool changed = false;
  for (size_t k = 0; k < t.layers(); ++k) changed |= !t.transferable(k);
  DirectLayers d;
  d.at.assign(t.layers(), kNotDirect);
  for (size_t k = 0; k < t.layers(); ++k)
    if (!t.transferable(k) || (changed && !t.certified(k))) d.add(k, t.plane(k));
  return d;
}

// A reused plate made a layer at a time where its masks are drawn (LayerMaker, export_masks.h):
// each member's layer k is transferred on the thread that draws it (ExactTransfer::layer_into),
// into that thread's parts, so its points are drawn while in cache and the plate holds no range
// of them. A plate then fills no fresh memory, which the first plate of a job paid for: a plate
// of 3 SL1S members spent 0.12 s of its 0.34 s filling its range. The layers a member cannot
// transfer (layers_to_slice) are sliced beforehand, one pass per member, and copied out layer by
// layer. A member whose every layer passed the cheap certificate may still fail the whole one on
// some (a vertex moved across an edge the sample does not read): on the first such layer, the
// member's layers are all checked and those failing sliced, once, in one pass.
class MadeWhereDrawn {
 public:
  MadeWhereDrawn(const std::vector<Mesh>& placed, const std::vector<ExactTransfer>& transfers,
                 std::vector<DirectLayers> direct, double z_start, double thickness, const Progress& progress)
      : placed_(placed),
        transfers_(transfers),
        z_start_(z_start),
        thickness_(thickness),
        direct_(std::move(direct)),
        late_(placed.size()),
        late_once_(new std::once_flag[placed.size()]) {
    const auto t = std::chrono::steady_clock::now();
    size_t layers = 0, done = 0;
    for (const DirectLayers& d : direct_) layers += d.planes.size();
    for (size_t m = 0; m < direct_.size(); ++m) {
      const size_t n = direct_[m].planes.size();
      if (n == 0) continue;
      const Progress mp = sub_progress(progress, double(done) / double(layers), double(done + n) / double(layers));
      direct_[m].slices = slice_planes(placed_[m], direct_[m].planes, mp, false);
      done += n;
    }
    direct_seconds_ = seconds_since(t);
  }

  // Layer k's parts, one per member that has it.
  void make(size_t k, std::vector<SlicePart>& parts) {
    const auto t = std::chrono::steady_clock::now();
    size_t used = 0, points = 0, transferred = 0;
    for (size_t m = 0; m < placed_.size(); ++m) {
      if (k >= transfers_[m].layers()) continue;
      if (parts.size() == used) parts.emplace_back();
      Slices& out = parts[used++].slices;
      const DirectLayers* d = &direct_[m];
      if (d->at[k] == kNotDirect) {
        if (transfers_[m].layer_into(k, out)) {
          ++transferred;
          points += out.points();
          continue;
        }
        std::call_once(late_once_[m], [&] { late_[m] = late_layers(m); });
        d = &late_[m];
        if (d->at[k] == kNotDirect)
          throw Error(format("internal error: layer %zu of plate member %zu failed its certificate once, not twice", k,
                             m + 1));
      }
      layers_into(d->slices, d->at[k], d->at[k] + 1, out, true);
      // Sliced directly, the part's z_start and thickness are not the plate's.
      out.z_start = z_start_ + double(k) * thickness_;
      out.thickness = thickness_;
      points += out.points();
    }
    parts.resize(used);
    points_ += points;
    transferred_ += transferred;
    resliced_ += used - transferred;
    nanoseconds_ += uint64_t(1e9 * seconds_since(t));
  }

  void stats(PlateJobStats& st) const {
    st.points = points_;
    st.transferred_layers = transferred_;
    st.resliced_layers = resliced_;
    st.slicing_seconds = direct_seconds_ + 1e-9 * double(nanoseconds_);
  }

 private:
  // Member m's layers that pass the cheap certificate but not the whole one, sliced (on the
  // drawing thread that found the first: its OpenMP team is its own, a rare cost).
  DirectLayers late_layers(size_t m) const {
    DirectLayers d;
    const ExactTransfer& t = transfers_[m];
    d.at.assign(t.layers(), kNotDirect);
    for (size_t k = 0; k < t.layers(); ++k)
      if (direct_[m].at[k] == kNotDirect && !t.certified(k)) d.add(k, t.plane(k));
    d.slices = slice_planes(placed_[m], d.planes, {}, false);
    return d;
  }

  const std::vector<Mesh>& placed_;
  const std::vector<ExactTransfer>& transfers_;
  const double z_start_, thickness_;
  std::vector<DirectLayers> direct_, late_;
  std::unique_ptr<std::once_flag[]> late_once_;
  double direct_seconds_ = 0;
  std::atomic<size_t> points_{0}, transferred_{0}, resliced_{0};
  std::atomic<uint64_t> nanoseconds_{0};
};

// The plate's z_start and thickness for o (see plate_job.h), lowest being its members' lowest
// vertex (used only slicing directly from z_start NaN).
void plate_frame(size_t members, const PlateJobOptions& o, double lowest, double* z_start, double* thickness) {
  if (members == 0) throw Error("a plate needs at least one member");
  if (o.encoding) {
    if (!(o.encoding->thickness > 0))
      throw Error("the encoding has no layer thickness (it was not made by slicing at a thickness), so the plate's "
                  "layers are unknown");
    *z_start = o.encoding->z_start;
    *thickness = o.encoding->thickness;
  } else {
    *z_start = std::isnan(o.slicing.z_start) ? lowest : o.slicing.z_start;
    *thickness = o.slicing.thickness;
  }
}

}  // namespace

std::vector<double> plate_planes(const std::vector<Mesh>& placed, const PlateJobOptions& o, double* z_start,
                                 double* thickness) {
  double lowest = INFINITY, top = -INFINITY;
  for (const Mesh& m : placed) {
    validate_mesh(m);
    const ZRange z = z_range(m);
    lowest = std::min(lowest, z.min);
    top = std::max(top, z.max);
  }
  plate_frame(placed.size(), o, lowest, z_start, thickness);
  return layer_planes(*z_start, *thickness, top);
}

PlateJobStats export_plate(const std::vector<Mesh>& placed, const PlateJobOptions& o, const PrinterProfile& profile,
                           const std::string& output_path, const Progress& progress) {
  PlateJobStats st;
  const size_t n = placed.size();
  std::vector<double> planes;  // slicing directly
  std::vector<ExactTransfer> transfers;
  std::vector<DirectLayers> direct;
  // Each member's own layer count: its direct slicing from the plate's z_start stops at its top
  // (a transfer's layers are those).
  std::vector<size_t> own(n, 0);
  if (o.encoding) {
    // Reusing, each member's transfer is prepared once for the plate (which checks the member),
    // and the layers it cannot transfer found, members on all cores in one parallel region:
    // OpenMP's threads spin for milliseconds after each, against the masks' threads.
    plate_frame(n, o, NAN, &st.z_start, &st.thickness);
    std::vector<std::unique_ptr<ExactTransfer>> made(n);
    direct.resize(n);
    parallel_blocks(
        n,
        [&](size_t m) {
          made[m] = o.edge_ends
                        ? std::make_unique<ExactTransfer>(*o.encoding, *o.edge_ends, placed[m], o.vertex_order)
                        : std::make_unique<ExactTransfer>(*o.encoding, placed[m]);
          direct[m] = layers_to_slice(*made[m]);
        },
        {}, "preparing the transfers");
    for (size_t m = 0; m < n; ++m) {
      transfers.push_back(std::move(*made[m]));
      own[m] = transfers[m].layers();
    }
  } else {
    planes = plate_planes(placed, o, &st.z_start, &st.thickness);
    for (size_t m = 0; m < n; ++m) {
      const double top = z_range(placed[m]).max;
      if (st.z_start < top) own[m] = layer_planes(st.z_start, st.thickness, top).size();
    }
  }
  const size_t L = o.encoding ? *std::max_element(own.begin(), own.end()) : planes.size();
  // A range holds every member's points (reusing, each layer's are the certificate's counts,
  // made already).
  const uint64_t reused_budget =
      o.range_budget_bytes == 0 ? kReusedRangeBytes : std::min(o.range_budget_bytes, kReusedRangeBytes);
  st.layers = L;
  if (!transfers.empty()) {
    // Made where drawn when the layers to slice directly fit in the budget (else in ranges).
    uint64_t direct_points = 0;
    for (size_t m = 0; m < n; ++m)
      for (size_t k = 0; k < own[m]; ++k)
        if (direct[m].at[k] != kNotDirect) direct_points += transfers[m].layer_points()[k];
    if (direct_points * kPointBytes <= reused_budget) {
      const double share = direct_points > 0 ? 0.1 : 0;  // of the progress, for the direct slicing
      MadeWhereDrawn made(placed, transfers, std::move(direct), st.z_start, st.thickness,
                          sub_progress(progress, 0, share));
      st.ranges = 0;
      st.masks = export_masks(LayerMaker{L, st.thickness, [&](size_t k, std::vector<SlicePart>& parts) {
                                           made.make(k, parts);
                                         }},
                              profile, output_path, sub_progress(progress, share, 1));
      made.stats(st);
      return st;
    }
  }
  std::vector<size_t> first;
  if (transfers.empty()) {
    std::vector<const Mesh*> meshes;
    for (const Mesh& m : placed) meshes.push_back(&m);
    first = layer_chunks(meshes, planes, o.range_budget_bytes, kPointBytes);
  } else {
    std::vector<uint64_t> points(L, 0);
    for (const ExactTransfer& t : transfers)
      for (size_t k = 0; k < t.layers(); ++k) points[k] += t.layer_points()[k];
    first = layer_chunks(points, reused_budget, kPointBytes);
  }
  st.ranges = first.size() - 1;

  SliceChunks chunks{first, st.thickness, [&](size_t i, const Progress& range_progress) {
                       const auto t = std::chrono::steady_clock::now();
                       std::vector<SlicePart> s =
                           plate_range(placed, transfers, planes, own, first[i], first[i + 1], st, range_progress);
                       st.slicing_seconds += seconds_since(t);
                       return s;
                     }};
  st.masks = export_masks(chunks, profile, output_path, progress);
  return st;
}

}  // namespace slicereuse
