#include "transfer_layers.h"

#include <algorithm>
#include <cstring>

#include "slicereuse/slicing/layer_planes.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/memory_budget.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse {
namespace {

constexpr size_t kLayersPerBlock = 64;

// Layer k of the result is layer pick[k].layer of *pick[k].from.
struct Pick {
  const Slices* from;
  size_t layer;
};

Slices assemble(const std::vector<Pick>& pick, std::vector<double> planes, bool with_encoding,
                const Progress& progress) {
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
  if (with_encoding) {
    out.face.resize(P);
    out.edge.resize(P);
    out.t.resize(P);
  }
  for_each_layer(L, progress, [&](size_t k) {
    const Slices& s = *pick[k].from;
    const size_t p0 = layer_point_begin(s, pick[k].layer), n = layer_point_end(s, pick[k].layer) - p0;
    const size_t q = point_begin[k];
    std::memcpy(&out.xyz[3 * q], &s.xyz[3 * p0], 3 * n * sizeof(double));
    if (with_encoding) {
      std::memcpy(&out.face[q], &s.face[p0], n * sizeof(uint32_t));
      std::memcpy(&out.edge[q], &s.edge[p0], n);
      std::memcpy(&out.t[q], &s.t[p0], n * sizeof(double));
    }
  });
  return out;
}

}  // namespace

Slices layout_of(const Slices& enc, size_t a, size_t b) {
  const size_t points = enc.contour_begin[enc.layer_begin[b]] - enc.contour_begin[enc.layer_begin[a]];
  // Every transfer's output is allocated here: refused with the figures, not a bad_alloc, when
  // it would not fit.
  check_memory_for(points * 3 * sizeof(double), format("transferring %zu contour points", points),
                   "slice the source at a thicker layer, or with fewer layers (z_start)");
  Slices out;
  layers_into(enc, a, b, out, false);
  return out;
}

Slices layout_of(const Slices& enc) { return layout_of(enc, 0, enc.layers()); }

std::vector<double> target_planes(const Slices& enc, const Mesh& target) {
  if (!(enc.thickness > 0)) return enc.layer_z;
  std::vector<double> planes = layer_planes(enc.z_start, enc.thickness, z_range(target).max);
  std::copy_n(enc.layer_z.begin(), std::min(planes.size(), enc.layers()), planes.begin());
  return planes;
}

void for_each_layer(size_t L, const Progress& progress, const std::function<void(size_t)>& body) {
  parallel_blocks(
      (L + kLayersPerBlock - 1) / kLayersPerBlock,
      [&](size_t b) {
        for (size_t k = b * kLayersPerBlock; k < std::min(L, (b + 1) * kLayersPerBlock); ++k) body(k);
      },
      progress, "transferring");
}

Slices slice_every_plane(const Mesh& target, std::vector<double> planes, bool with_encoding, TransferStats& st,
                         const Progress& progress) {
  st.resliced_layers = planes.size();
  st.transferred_layers = 0;
  return slice_planes(target, std::move(planes), progress, with_encoding);
}

Slices splice_resliced(Slices done, const std::vector<size_t>& done_layer, std::vector<double> planes,
                       const Mesh& target, bool with_encoding, TransferStats& st, const Progress& progress) {
  const size_t L = planes.size();
  std::vector<size_t> redo;
  std::vector<double> redo_planes;
  bool identity = done.layers() == L;
  for (size_t k = 0; k < L; ++k) {
    if (done_layer[k] == kNoLayer) {
      redo.push_back(k);
      redo_planes.push_back(planes[k]);
    }
    identity &= done_layer[k] == k;
  }
  if (identity) {
    st.transferred_layers = L;
    st.resliced_layers = 0;
    done.layer_z = std::move(planes);
    return done;
  }
  if (2 * redo.size() > L) return slice_every_plane(target, std::move(planes), with_encoding, st, progress);
  st.resliced_layers = redo.size();
  st.transferred_layers = L - redo.size();
  // Slicing reports the first half of the progress, splicing the second.
  const Slices fresh = slice_planes(target, std::move(redo_planes), sub_progress(progress, 0, 0.5), with_encoding);
  std::vector<Pick> pick(L);
  for (size_t k = 0, r = 0; k < L; ++k)
    pick[k] = done_layer[k] == kNoLayer ? Pick{&fresh, r++} : Pick{&done, done_layer[k]};
  return assemble(pick, std::move(planes), with_encoding, sub_progress(progress, 0.5, 1));
}

}  // namespace slicereuse
