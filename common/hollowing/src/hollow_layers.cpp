#include "slicereuse/hollowing/hollow_layers.h"

#include <algorithm>

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

namespace {

// How near (in Clipper units, 1 nm) a contour rounded to the region grid may come to the cavity:
// beyond it, the contour as it is (each point within half a unit of its rounding in x and y)
// neither meets the cavity nor winds otherwise around its points.
constexpr double kRoundingClearance = 2;

// Whether contours (a layer's closed ones, rounded: layer_paths) wind exactly once around every
// point of the cavity (a region): none comes near its boundary, none lies inside it, and they
// wind once around a point of each of its loops. Then the winding is the same over each of the
// cavity's pieces, boundary included.
bool winds_once_around(const ClipperLib::Paths& contours, const ClipperLib::Paths& cavity, const IndexedRegion& cut) {
  if (!boundaries_apart(index_region(contours), cut, kRoundingClearance)) return false;
  for (const ClipperLib::Path& c : contours)
    if (!c.empty() && region_covers(cavity, c[0])) return false;
  for (const ClipperLib::Path& loop : cavity)
    if (winding_number(contours, loop[0]) != 1) return false;
  return true;
}

}  // namespace

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
  size_t points = s.points();  // the contours' and the cavity's, which most layers keep as they are
  for (size_t i = 0; i < n; ++i)
    for (const ClipperLib::Path& loop : cavity[first + i]) points += loop.size();
  xyz.reserve(3 * points);
  // Appended by resizing and writing in place: a vector's insert of a few doubles costs more.
  const auto add_contour = [&](uint64_t c, bool open) {
    const size_t at = xyz.size();
    xyz.resize(at + 3 * (s.contour_begin[c + 1] - s.contour_begin[c]));
    std::copy(s.xyz.begin() + long(3 * s.contour_begin[c]), s.xyz.begin() + long(3 * s.contour_begin[c + 1]),
              xyz.begin() + long(at));
    out.contour_begin.push_back(xyz.size() / 3);
    out.contour_open.push_back(open);
  };
  for (size_t i = 0; i < n; ++i) {
    const ClipperLib::Paths& hole = cavity[first + i];
    if (hole.empty()) {
      for (uint64_t c = s.layer_begin[i]; c < s.layer_begin[i + 1]; ++c) add_contour(c, s.contour_open[c]);
    } else {
      const auto add_loop = [&](const ClipperLib::Path& loop, bool reversed) {
        if (loop.size() < 3) return;
        size_t at = xyz.size();
        xyz.resize(at + 3 * loop.size());
        for (size_t j = 0; j < loop.size(); ++j, at += 3) {
          const ClipperLib::IntPoint& q = loop[reversed ? loop.size() - 1 - j : j];
          xyz[at] = double(q.X) / kRegionScale;
          xyz[at + 1] = double(q.Y) / kRegionScale;
          xyz[at + 2] = s.layer_z[i];
        }
        out.contour_begin.push_back(xyz.size() / 3);
        out.contour_open.push_back(0);
      };
      // Where the layer's own contours wind exactly once around all of the cavity, their nonzero
      // fill less the cavity is theirs and the cavity's loops reversed: no Clipper at all.
      const IndexedRegion cut = index_region(hole);
      if (winds_once_around(layer_paths(LayerView(s, i)), hole, cut)) {
        for (uint64_t c = s.layer_begin[i]; c < s.layer_begin[i + 1]; ++c)
          if (!s.contour_open[c]) add_contour(c, false);
        for (const ClipperLib::Path& loop : hole) add_loop(loop, true);
      } else {
        // Else from the layer's region (overlapping shells merged: it winds once over all of
        // itself), the same way when the cavity lies strictly inside it, else by Clipper.
        const ClipperLib::Paths region = layer_region(LayerView(s, i));
        if (clears(cut, index_region(region), 0)) {
          for (const ClipperLib::Path& loop : region) add_loop(loop, false);
          for (const ClipperLib::Path& loop : hole) add_loop(loop, true);
        } else {
          for (const ClipperLib::Path& loop : clip_regions(region, hole, ClipperLib::ctDifference))
            add_loop(loop, false);
        }
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
