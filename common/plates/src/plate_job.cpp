#include "slicereuse/plates/plate_job.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "slicereuse/slicing/layer_chunks.h"
#include "slicereuse/slicing/layer_planes.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "slicereuse/util/error.h"

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

}  // namespace

std::vector<double> plate_planes(const std::vector<Mesh>& placed, const PlateJobOptions& o, double* z_start,
                                 double* thickness) {
  if (placed.empty()) throw Error("a plate needs at least one member");
  double lowest = INFINITY, top = -INFINITY;
  for (const Mesh& m : placed) {
    validate_mesh(m);
    const ZRange z = z_range(m);
    lowest = std::min(lowest, z.min);
    top = std::max(top, z.max);
  }
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
  return layer_planes(*z_start, *thickness, top);
}

PlateJobStats export_plate(const std::vector<Mesh>& placed, const PlateJobOptions& o, const PrinterProfile& profile,
                           const std::string& output_path, const Progress& progress) {
  PlateJobStats st;
  const std::vector<double> planes = plate_planes(placed, o, &st.z_start, &st.thickness);
  const size_t L = planes.size(), n = placed.size();
  // Reusing, each member's transfer is prepared once for all ranges.
  std::vector<ExactTransfer> transfers;
  for (size_t m = 0; o.encoding && m < n; ++m) {
    if (o.edge_ends)
      transfers.emplace_back(*o.encoding, *o.edge_ends, placed[m]);
    else
      transfers.emplace_back(*o.encoding, placed[m]);
  }
  // Each member's own layer count: its direct slicing from the plate's z_start stops at its top
  // (a transfer's layers are those).
  std::vector<size_t> own(n, 0);
  for (size_t m = 0; m < n; ++m) {
    if (!transfers.empty()) {
      own[m] = transfers[m].layers();
      continue;
    }
    const double top = z_range(placed[m]).max;
    if (st.z_start < top) own[m] = layer_planes(st.z_start, st.thickness, top).size();
  }
  // A range holds every member's points (reusing, each layer's are the certificate's counts,
  // made already).
  constexpr size_t kPointBytes = 3 * sizeof(double);
  std::vector<size_t> first;
  if (transfers.empty()) {
    std::vector<const Mesh*> meshes;
    for (const Mesh& m : placed) meshes.push_back(&m);
    first = layer_chunks(meshes, planes, o.range_budget_bytes, kPointBytes);
  } else {
    std::vector<uint64_t> points(L, 0);
    for (const ExactTransfer& t : transfers)
      for (size_t k = 0; k < t.layers(); ++k) points[k] += t.layer_points()[k];
    const uint64_t budget =
        o.range_budget_bytes == 0 ? kReusedRangeBytes : std::min(o.range_budget_bytes, kReusedRangeBytes);
    first = layer_chunks(points, budget, kPointBytes);
  }
  st.ranges = first.size() - 1;
  st.layers = L;

  SliceChunks chunks{first, st.thickness, [&](size_t i, const Progress& range_progress) {
                       const auto t = std::chrono::steady_clock::now();
                       std::vector<SlicePart> s =
                           plate_range(placed, transfers, planes, own, first[i], first[i + 1], st, range_progress);
                       st.slicing_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
                       return s;
                     }};
  st.masks = export_masks(chunks, profile, output_path, progress);
  return st;
}

}  // namespace slicereuse
