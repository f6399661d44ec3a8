#include "slicereuse/hollowing/hollow_layers.h"

#include "region_clearance.h"
#include "slicereuse/regions/clip_regions.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/slicing/layer_view.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {

std::vector<ClipperLib::Paths> layers_cavity(const Slices& s, const HollowingOptions& options,
                                             const Progress& progress) {
  check_hollowing(options);
  if (options.wall_mm == 0) return std::vector<ClipperLib::Paths>(s.layers());
  return cavity_regions(layer_regions(s, sub_progress(progress, 0, 0.1), "hollowing"), s.thickness, options,
                        sub_progress(progress, 0.1, 1));
}

void subtract_cavity(Slices& s, size_t first, const std::vector<ClipperLib::Paths>& cavity) {
  const size_t n = s.layers();
  if (first + n > cavity.size())
    throw Error(format("internal error: layers %zu-%zu hollowed with a cavity of %zu layers", first, first + n,
                       cavity.size()));
  bool any = false;
  for (size_t i = 0; i < n && !any; ++i) any = !cavity[first + i].empty();
  if (!any) return;
  Slices out;
  out.z_start = s.z_start;
  out.thickness = s.thickness;
  out.fingerprint = s.fingerprint;
  out.layer_z = s.layer_z;
  out.layer_begin = {0};
  out.contour_begin = {0};
  Buffer<double>& xyz = out.xyz;
  xyz.reserve(s.xyz.size());
  for (size_t i = 0; i < n; ++i) {
    const ClipperLib::Paths& hole = cavity[first + i];
    if (hole.empty()) {
      for (uint64_t c = s.layer_begin[i]; c < s.layer_begin[i + 1]; ++c) {
        xyz.insert(xyz.end(), s.xyz.begin() + long(3 * s.contour_begin[c]),
                   s.xyz.begin() + long(3 * s.contour_begin[c + 1]));
        out.contour_begin.push_back(xyz.size() / 3);
        out.contour_open.push_back(s.contour_open[c]);
      }
    } else {
      const auto add_loop = [&](const ClipperLib::Path& loop, bool reversed) {
        if (loop.size() < 3) return;
        for (size_t j = 0; j < loop.size(); ++j) {
          const ClipperLib::IntPoint& q = loop[reversed ? loop.size() - 1 - j : j];
          xyz.insert(xyz.end(), {double(q.X) / kRegionScale, double(q.Y) / kRegionScale, s.layer_z[i]});
        }
        out.contour_begin.push_back(xyz.size() / 3);
        out.contour_open.push_back(0);
      };
      const ClipperLib::Paths region = layer_region(LayerView(s, i));
      // A cavity strictly inside the region (every layer's but those a drain hole opens to the
      // outside) is taken out by its loops reversed: the region's winding is 1 all over it, so
      // the nonzero rule leaves the same point set as Clipper's difference, for a fraction of it.
      if (clears(index_region(hole), index_region(region), 0)) {
        for (const ClipperLib::Path& loop : region) add_loop(loop, false);
        for (const ClipperLib::Path& loop : hole) add_loop(loop, true);
      } else {
        for (const ClipperLib::Path& loop : clip_regions(region, hole, ClipperLib::ctDifference)) add_loop(loop, false);
      }
    }
    out.layer_begin.push_back(out.contour_open.size());
  }
  s = std::move(out);
}

double cavity_volume_mm3(const std::vector<ClipperLib::Paths>& cavity, double thickness_mm) {
  double v = 0;
  for (const ClipperLib::Paths& layer : cavity) v += region_area_mm2(layer);
  return v * thickness_mm;
}

}  // namespace slicereuse
