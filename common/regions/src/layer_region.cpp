#include "slicereuse/regions/layer_region.h"

#include <cmath>

#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse {

ClipperLib::Paths layer_paths(const LayerView& layer) {
  ClipperLib::Paths paths;
  for (const LayerPart& part : layer) {
    const Slices& s = *part.slices;
    for (uint64_t c = s.layer_begin[part.layer]; c < s.layer_begin[part.layer + 1]; ++c) {
      if (s.contour_open[c]) continue;
      ClipperLib::Path path;
      path.reserve(s.contour_begin[c + 1] - s.contour_begin[c]);
      for (uint64_t p = s.contour_begin[c]; p < s.contour_begin[c + 1]; ++p)
        path.emplace_back(region_units(s.xyz[3 * p]), region_units(s.xyz[3 * p + 1]));
      paths.push_back(std::move(path));
    }
  }
  return paths;
}

ClipperLib::Paths layer_region(const LayerView& layer) {
  ClipperLib::Paths region;
  ClipperLib::Clipper clipper;
  clipper.AddPaths(layer_paths(layer), ClipperLib::ptSubject, true);
  clipper.Execute(ClipperLib::ctUnion, region, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return region;
}

std::vector<ClipperLib::Paths> layer_regions(const Slices& s, const Progress& progress, const char* phase) {
  std::vector<ClipperLib::Paths> regions(s.layers());
  parallel_blocks(s.layers(), [&](size_t k) { regions[k] = layer_region(LayerView(s, k)); }, progress, phase);
  return regions;
}

std::vector<ClipperLib::Paths> layers_paths(const Slices& s) {
  std::vector<ClipperLib::Paths> paths(s.layers());
  for (size_t k = 0; k < s.layers(); ++k) paths[k] = layer_paths(LayerView(s, k));
  return paths;
}

void region_into_layer(const ClipperLib::Paths& region, double z, Slices& out) {
  out = Slices{};
  out.layer_z = {z};
  out.layer_begin = {0, 0};
  out.contour_begin = {0};
  size_t points = 0;
  for (const ClipperLib::Path& path : region) points += path.size();
  out.xyz.resize(3 * points);
  size_t p = 0;
  for (const ClipperLib::Path& path : region) {
    if (path.size() < 3) continue;
    for (const ClipperLib::IntPoint& q : path) {
      out.xyz[3 * p] = double(q.X) / kRegionScale;
      out.xyz[3 * p + 1] = double(q.Y) / kRegionScale;
      out.xyz[3 * p + 2] = z;
      ++p;
    }
    out.contour_begin.push_back(p);
    out.contour_open.push_back(0);
  }
  out.xyz.resize(3 * p);
  out.layer_begin[1] = out.contour_open.size();
}

double region_area_mm2(const ClipperLib::Paths& region) {
  double a = 0;
  for (const ClipperLib::Path& path : region) a += ClipperLib::Area(path);
  return a / (kRegionScale * kRegionScale);
}

}  // namespace slicereuse
