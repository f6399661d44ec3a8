// "Hollow Mesh": the cavity the jobs' hollowing (hollow_wall_mm) would take out of the current
// mesh, shown as a mesh layer, with its volume and the resin it saves; nothing is printed.
#include "filter_params.h"
#include "filters_common.h"
#include "slicereuse/hollowing/hollow_layers.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/regions/layers_mesh.h"
#include "slicereuse/slicing/layer_view.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse::plugin {
namespace {

struct HollowMeshParams {
  double layer_thickness;
  double z_start;
  HollowingOptions cavity;
};

ParamList<HollowMeshParams> hollow_mesh_params() {
  ParamList<HollowMeshParams> l;
  add_planes(l);
  l.include(&HollowMeshParams::cavity, hollowing_params(kPrusaHollowingWallMm));
  return l;
}

// The part's volume as its layers print it: their regions' areas times the thickness.
double layers_volume_mm3(const Slices& s) {
  std::vector<double> area(s.layers());
  parallel_blocks(s.layers(), [&](size_t k) { area[k] = region_area_mm2(layer_region(LayerView(s, k))); }, {},
                  "measuring layers");
  double v = 0;
  for (double a : area) v += a;
  return v * s.thickness;
}

Result run_hollow_mesh(const HollowMeshParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const Mesh mesh = host.current_mesh();
  const std::string name = host.current_mesh_name();
  if (p.cavity.wall_mm == 0) throw Error("hollow_wall_mm is 0, which keeps the part solid: give the walls' thickness, "
                                         "e.g. PrusaSlicer's 3 mm");
  const Progress progress = host.progress();
  const Slices s = slice_layers(mesh, slice_options(p.layer_thickness, p.z_start), sub_progress(progress, 0, 0.2));
  const std::vector<ClipperLib::Paths> cavity = layers_cavity(s, p.cavity, sub_progress(progress, 0.2, 0.9));
  const double cavity_mm3 = cavity_volume_mm3(cavity, s.thickness);
  if (cavity_mm3 == 0)
    throw Error(format("%s has no cavity with walls of %g mm%s: no ball of %g mm radius fits inside it, so it stays "
                       "solid; nothing was added",
                       name.c_str(), p.cavity.wall_mm,
                       p.cavity.closing_mm > 0 ? format(" and a closing distance of %g mm", p.cavity.closing_mm).c_str() : "",
                       p.cavity.wall_mm + p.cavity.closing_mm));
  const double part_mm3 = layers_volume_mm3(s);
  const Mesh shown = layers_mesh(cavity, s.z_start, s.thickness);
  host.add_mesh_layer(name + " cavity", shown);
  size_t first = 0, last = 0;
  while (cavity[first].empty()) ++first;
  for (size_t k = 0; k < cavity.size(); ++k)
    if (!cavity[k].empty()) last = k;
  const double saved = 100 * cavity_mm3 / part_mm3;
  const double seconds = seconds_since(start);
  host.log(format("Hollow Mesh: %s with walls of %g mm (closing distance %g mm): a cavity of %.4g mm3 on layers %zu-%zu "
                  "of %zu, %.1f%% of the part's %.4g mm3 of resin saved; added as '%s cavity' (%zu faces), %.3f s",
                  name.c_str(), p.cavity.wall_mm, p.cavity.closing_mm, cavity_mm3, first, last, s.layers(), saved,
                  part_mm3, name.c_str(), shown.faces(), seconds));
  return {{"cavity_mm3", cavity_mm3},
          {"part_mm3", part_mm3},
          {"saved_percent", saved},
          {"layers", int64_t(s.layers())},
          {"seconds", seconds}};
}

}  // namespace

FilterSpec hollow_mesh_filter() {
  const std::string description = std::string(
      "<p>Shows the cavity that <i>Make Print Job</i> and <i>Make Plate Job</i> take out of the current mesh with "
      "<i>hollow_wall_mm</i>, as PrusaSlicer hollows (its <i>hollowing_min_thickness</i> and "
      "<i>hollowing_closing_distance</i>): the mesh sliced on the print job's planes, the cavity every point "
      "farther than the wall inside the part, in 3-D, computed on the layers' contours. Adds it as a new mesh "
      "layer, <i>&lt;mesh&gt; cavity</i>, each layer's cavity a slab one layer thick, and logs its volume and "
      "the share of the part's resin it saves. A wall too thick for any cavity is refused in words and nothing "
      "is added. The mesh is not changed: the jobs hollow the layers' contours.</p>") +
      kReference;
  return typed_filter({FilterId::HollowMesh, "Hollow Mesh", "hollow_mesh", description, Arity::CurrentMesh,
                       kLayerClass, true},
                      hollow_mesh_params(), run_hollow_mesh,
                      {"cavity_mm3", "part_mm3", "saved_percent", "layers", "seconds"});
}

}  // namespace slicereuse::plugin
