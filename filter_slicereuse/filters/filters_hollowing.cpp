// "Hollow Mesh": the cavity the jobs' hollowing (hollow_wall_mm) would take out of the current
// mesh, shown as a mesh layer, with its volume and the resin it saves. "Add Drain Holes": the
// holes the jobs would drill into it, as a point layer the user may edit and give back to the
// jobs (drain_points_layer). Nothing is printed.
#include "filter_params.h"
#include "filters_common.h"
#include "slicereuse/hollowing/drain_holes.h"
#include "slicereuse/hollowing/hollow_layers.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/regions/layers_mesh.h"
#include "slicereuse/slicing/layer_view.h"
#include "slicereuse/supports/locate_support_points.h"
#include "slicereuse/supports/support_points_file.h"
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

// The current mesh's layers and their cavity; Error when the walls leave none.
struct Hollowed {
  Slices layers;
  std::vector<ClipperLib::Paths> cavity;
  double cavity_mm3 = 0;
};

Hollowed hollow(const Mesh& mesh, const std::string& name, double layer_thickness, double z_start,
                const HollowingOptions& o, const Progress& progress) {
  if (o.wall_mm == 0)
    throw Error("hollow_wall_mm is 0, which keeps the part solid: give the walls' thickness, e.g. PrusaSlicer's 3 mm");
  Hollowed h;
  h.layers = slice_layers(mesh, slice_options(layer_thickness, z_start), sub_progress(progress, 0, 0.2));
  h.cavity = layers_cavity(h.layers, o, sub_progress(progress, 0.2, 1));
  h.cavity_mm3 = cavity_volume_mm3(h.cavity, h.layers.thickness);
  if (h.cavity_mm3 == 0)
    throw Error(format("%s has no cavity with walls of %g mm%s: no ball of %g mm radius fits inside it, so it stays "
                       "solid; nothing was added",
                       name.c_str(), o.wall_mm,
                       o.closing_mm > 0 ? format(" and a closing distance of %g mm", o.closing_mm).c_str() : "",
                       o.wall_mm + o.closing_mm));
  return h;
}

Result run_hollow_mesh(const HollowMeshParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const Mesh mesh = host.current_mesh();
  const std::string name = host.current_mesh_name();
  const Progress progress = host.progress();
  const Hollowed h = hollow(mesh, name, p.layer_thickness, p.z_start, p.cavity, sub_progress(progress, 0, 0.9));
  const std::vector<ClipperLib::Paths>& cavity = h.cavity;
  const double part_mm3 = layers_volume_mm3(h.layers);
  const double hollowing_seconds = seconds_since(start);
  const Mesh shown = layers_mesh(cavity, h.layers.z_start, h.layers.thickness);
  host.add_mesh_layer(name + " cavity", shown);
  size_t first = 0, last = 0;
  while (cavity[first].empty()) ++first;
  for (size_t k = 0; k < cavity.size(); ++k)
    if (!cavity[k].empty()) last = k;
  const double saved = 100 * h.cavity_mm3 / part_mm3;
  const double seconds = seconds_since(start);
  host.log(format("Hollow Mesh: %s with walls of %g mm (closing distance %g mm): a cavity of %.4g mm3 on layers %zu-%zu "
                  "of %zu, %.1f%% of the part's %.4g mm3 of resin saved; added as '%s cavity' (%zu faces), %.3f s "
                  "(hollowing %.3f s)",
                  name.c_str(), p.cavity.wall_mm, p.cavity.closing_mm, h.cavity_mm3, first, last, h.layers.layers(),
                  saved, part_mm3, name.c_str(), shown.faces(), seconds, hollowing_seconds));
  return {{"cavity_mm3", h.cavity_mm3},
          {"part_mm3", part_mm3},
          {"saved_percent", saved},
          {"layers", int64_t(h.layers.layers())},
          {"seconds", seconds}};
}

// ---- Add Drain Holes ------------------------------------------------------------------------

struct AddDrainHolesParams {
  double layer_thickness;
  double z_start;
  HollowingOptions cavity;
  DrainHoleParams holes;
  std::string holes_output;
};

ParamList<AddDrainHolesParams> add_drain_holes_params() {
  ParamList<AddDrainHolesParams> l;
  add_planes(l);
  l.include(&AddDrainHolesParams::cavity, hollowing_params(kPrusaHollowingWallMm))
      .include(&AddDrainHolesParams::holes, drain_hole_params())
      .file(&AddDrainHolesParams::holes_output, ParamType::FileSave, "drain_holes_file", "Write drain holes to",
            "*.srp", nullptr,
            "Where to write the holes (a support-points file, .srp, of their mouths), for the jobs' "
            "drain_holes_file. Empty (the default): not written.");
  return l;
}

Result run_add_drain_holes(const AddDrainHolesParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const Mesh mesh = host.current_mesh();
  const std::string name = host.current_mesh_name();
  if (p.holes.diameter_mm == 0) throw Error("drain_hole_mm is 0, which drills no holes: give their diameter, e.g. 4 mm");
  Hollowed h = hollow(mesh, name, p.layer_thickness, p.z_start, p.cavity, host.progress());
  std::vector<DrainHole> holes = add_drain_holes(h.cavity, p.holes.diameter_mm, size_t(p.holes.per_cavity));
  try {
    check_drain_holes_fit(holes, p.holes.diameter_mm, h.layers);
  } catch (const Error& e) {
    throw Error(name + ": " + e.what());
  }
  find_drain_hole_mouths(mesh, h.layers.z_start, h.layers.thickness, holes);
  std::vector<double> xyz, normals;
  for (const DrainHole& d : holes) {
    xyz.insert(xyz.end(), {d.x_mm, d.y_mm, d.z_mm});
    normals.insert(normals.end(), d.axis.begin(), d.axis.end());
  }
  if (!p.holes_output.empty())
    write_support_points(p.holes_output, locate_support_points(mesh, xyz, {}, kUserPointReachMm, "drain hole"));
  host.add_point_layer(name + " drain holes", xyz, normals);
  for (size_t i = 0; i < holes.size(); ++i)
    host.log(format("Add Drain Holes: hole %zu of %g mm opens at (%.2f, %.2f, %.2f) mm, up into the cavity's layer %zu",
                    i + 1, p.holes.diameter_mm, holes[i].x_mm + 0.0, holes[i].y_mm + 0.0, holes[i].z_mm + 0.0,
                    holes[i].layer));
  const double seconds = seconds_since(start);
  host.log(format("Add Drain Holes: %zu drain holes into %s's cavity of %.4g mm3 (walls of %g mm), added as '%s drain "
                  "holes', %.3f s",
                  holes.size(), name.c_str(), h.cavity_mm3, p.cavity.wall_mm, name.c_str(), seconds));
  return {{"drain_holes", int64_t(holes.size())}, {"cavity_mm3", h.cavity_mm3}, {"seconds", seconds}};
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

FilterSpec add_drain_holes_filter() {
  const std::string description = std::string(
      "<p>Shows where <i>Make Print Job</i> and <i>Make Plate Job</i> drill the current mesh's drain holes when "
      "they hollow it: the mesh sliced on the print job's planes and hollowed as they do, then under each "
      "cavity a vertical hole of <i>drain_hole_mm</i> (PrusaSlicer's 4 mm) from its lowest layer down through "
      "the bottom wall, <i>drain_holes</i> of them spread over that layer. Adds a point layer, <i>&lt;mesh&gt; "
      "drain holes</i>: a point where each hole opens on the surface, its normal the hole's axis outwards.</p>"
      "<p>The layer can be edited with MeshLab's tools (delete points, move them on the surface, add others) "
      "and given to the jobs as <i>drain_points_layer</i>: their holes are then drilled at those points, along "
      "the surface's normal through the wall, on every member of the family at the same place on its own "
      "surface; or written to a file (<i>drain_holes_file</i>) for the jobs.</p>") +
      kReference;
  return typed_filter({FilterId::AddDrainHoles, "Add Drain Holes", "add_drain_holes", description, Arity::CurrentMesh,
                       kLayerClass, true},
                      add_drain_holes_params(), run_add_drain_holes, {"drain_holes", "cavity_mm3", "seconds"});
}

}  // namespace slicereuse::plugin
