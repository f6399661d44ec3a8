#include "slicereuse/plates/faded_layers.h"

#include <algorithm>

#include "slicereuse/regions/elephant_foot.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse {
namespace {

// PrusaSlicer's F and E (faded_layers.h) for an object of `layers` layers.
struct Fade {
  size_t faded = 0, span = 1;
};

Fade fade_of(const PrinterProfile& profile, size_t layers) {
  Fade f;
  f.faded = std::min(layers, size_t(std::max(1, profile.faded_layers)));
  f.span = std::max(size_t(1), f.faded > 0 ? f.faded - 1 : 0);
  return f;
}

// The layers with a compensation above 0, [0, E) (none without layers).
size_t compensated_layers(const PrinterProfile& profile, size_t layers) {
  if (!(profile.elephant_foot_mm > 0)) return 0;
  const Fade f = fade_of(profile, layers);
  return std::min(f.faded, f.span);
}

}  // namespace

double faded_compensation_mm(const PrinterProfile& profile, size_t layers, size_t k) {
  const Fade f = fade_of(profile, layers);
  if (k >= f.faded || k >= f.span) return 0;
  return double(f.span - k) * profile.elephant_foot_mm / double(f.span);
}

void compensate_faded_layers(std::vector<SlicePart>& parts, size_t a, const std::vector<size_t>& owners,
                             const std::vector<size_t>& object_layers, const PrinterProfile& profile,
                             bool on_all_cores) {
  if (!(profile.elephant_foot_mm > 0)) return;
  if (!owners.empty() && owners.size() != parts.size())
    throw Error(format("internal error: %zu owners for %zu parts of the faded layers", owners.size(), parts.size()));
  auto owner = [&](size_t i) { return owners.empty() ? size_t(0) : owners[i]; };
  auto has = [&](size_t i, size_t r) { return parts[i].first <= r && r < parts[i].first + parts[i].slices.layers(); };
  // Per part, the range's layers below cut are its owner's compensated ones.
  std::vector<size_t> cut(parts.size());
  for (size_t i = 0; i < parts.size(); ++i) {
    if (owner(i) >= object_layers.size())
      throw Error(format("internal error: part %zu's owner %zu has no layer count (%zu given)", i, owner(i),
                         object_layers.size()));
    const size_t c = compensated_layers(profile, object_layers[owner(i)]);
    cut[i] = c > a ? c - a : 0;
  }
  // Above every owner's fade (most ranges and layers): nothing to do.
  if (std::all_of(cut.begin(), cut.end(), [](size_t c) { return c == 0; })) return;
  // One compensated layer per owner and layer below its cut that any of its parts has: its
  // first part there and the layer.
  struct Layer {
    size_t part, layer;
  };
  std::vector<Layer> layers;
  std::vector<bool> listed(parts.size(), false);
  for (size_t i = 0; i < parts.size(); ++i) {
    if (listed[i]) continue;
    for (size_t j = i; j < parts.size(); ++j) listed[j] = listed[j] || owner(j) == owner(i);
    for (size_t r = 0; r < cut[i]; ++r)
      for (size_t j = i; j < parts.size(); ++j)
        if (owner(j) == owner(i) && has(j, r)) {
          layers.push_back({j, r});
          break;
        }
  }
  std::vector<SlicePart> out(layers.size());
  auto compensate = [&](size_t l) {
    const size_t first = layers[l].part, r = layers[l].layer;
    std::vector<LayerPart> together;
    for (size_t j = first; j < parts.size(); ++j)
      if (owner(j) == owner(first) && has(j, r)) together.push_back({&parts[j].slices, r - parts[j].first});
    const Slices& own = parts[first].slices;
    const size_t k = r - parts[first].first;
    Slices& made = out[l].slices;
    compensate_elephant_foot(LayerView(together.data(), together.size()), own.layer_z[k],
                             faded_compensation_mm(profile, object_layers[owner(first)], a + r),
                             profile.elephant_foot_min_width_mm, made);
    made.z_start = own.z_start + double(k) * own.thickness;
    made.thickness = own.thickness;
    out[l].first = r;
  };
  if (on_all_cores && layers.size() > 1) {
    parallel_blocks(layers.size(), compensate, {}, "compensating elephant foot");
  } else {
    for (size_t l = 0; l < layers.size(); ++l) compensate(l);
  }
  for (size_t i = 0; i < parts.size(); ++i) {
    SlicePart& p = parts[i];
    const size_t end = p.first + p.slices.layers();
    if (p.first >= cut[i]) {
      out.push_back(std::move(p));
    } else if (end > cut[i]) {
      out.emplace_back();
      layers_into(p.slices, cut[i] - p.first, p.slices.layers(), out.back().slices, true);
      out.back().first = cut[i];
      out.back().support = p.support;
    }
  }
  parts = std::move(out);
}

}  // namespace slicereuse
