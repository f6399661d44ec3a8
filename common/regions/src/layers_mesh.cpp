#include "slicereuse/regions/layers_mesh.h"

#include "slicereuse/regions/clip_regions.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/regions/region_triangles.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse {
namespace {

void add_vertex(Mesh& m, const ClipperLib::IntPoint& p, double z) {
  m.V.insert(m.V.end(), {double(p.X) / kRegionScale, double(p.Y) / kRegionScale, z});
}

// One slab of region between z0 and z1.
Mesh slab(const ClipperLib::Paths& region, double z0, double z1) {
  Mesh m;
  const ClipperLib::Paths loops = clip_regions(region, {}, ClipperLib::ctUnion);
  for (const ClipperLib::Path& loop : loops) {
    const uint32_t first = uint32_t(m.vertices());
    const uint32_t n = uint32_t(loop.size());
    for (const ClipperLib::IntPoint& p : loop) add_vertex(m, p, z0), add_vertex(m, p, z1);
    // Outer loops run counter-clockwise and holes clockwise: the outside lies right of each edge.
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t a = first + 2 * i, b = first + 2 * ((i + 1) % n);
      m.F.insert(m.F.end(), {a, b, b + 1, a, b + 1, a + 1});
    }
  }
  for (const RegionTriangle& t : region_triangles(loops)) {
    const uint32_t first = uint32_t(m.vertices());
    for (const ClipperLib::IntPoint& p : t) add_vertex(m, p, z0), add_vertex(m, p, z1);
    m.F.insert(m.F.end(), {first, first + 4, first + 2, first + 1, first + 3, first + 5});
  }
  return m;
}

}  // namespace

Mesh layers_mesh(const std::vector<ClipperLib::Paths>& layers, double z_start, double thickness) {
  std::vector<Mesh> slabs(layers.size());
  parallel_blocks(layers.size(), [&](size_t k) {
    if (!layers[k].empty())
      slabs[k] = slab(layers[k], z_start + double(k) * thickness, z_start + double(k + 1) * thickness);
  }, {}, "meshing layers");
  Mesh out;
  for (const Mesh& s : slabs) {
    const uint32_t base = uint32_t(out.vertices());
    out.V.insert(out.V.end(), s.V.begin(), s.V.end());
    for (uint32_t f : s.F) out.F.push_back(base + f);
  }
  return out;
}

}  // namespace slicereuse
