// The support filters (issue #30). "Generate Support Points": the current mesh's islands and
// overhangs found from its slicing, points placed on them, written to a support-points file and
// shown as a point layer. "Transfer Support Points": a family source's points carried to the
// current mesh, certified and completed there. "Build Supports": the support structure of the
// current mesh's points (a point layer the user may have edited, or a points file) as a new layer.
#include <algorithm>
#include <cmath>

#include "filter_params.h"
#include "filters_common.h"
#include "slicereuse/formats/map_files.h"
#include "slicereuse/supports/generate_support_points.h"
#include "slicereuse/supports/locate_support_points.h"
#include "slicereuse/supports/support_points_file.h"
#include "slicereuse/supports/support_tree.h"
#include "slicereuse/supports/transfer_support_points.h"
#include "slicereuse/util/error.h"

namespace slicereuse::plugin {
namespace {

// points as a new point layer named after the mesh.
void add_points_layer(Host& host, const std::string& mesh_name, const SupportPoints& points) {
  host.add_point_layer(mesh_name + " support points", points.xyz, points.normal);
}

size_t count_kind(const SupportPoints& points, SupportKind kind) {
  return size_t(std::count(points.kind.begin(), points.kind.end(), uint8_t(kind)));
}

// ---- Generate Support Points ---------------------------------------------------------------

struct GenerateParams {
  std::string mesh_file;
  double layer_thickness;
  double z_start;
  SupportPointParams points;
  double object_elevation;
  std::string points_output;
};

ParamList<GenerateParams> generate_params() {
  ParamList<GenerateParams> l;
  add_mesh_file(l, &GenerateParams::mesh_file);
  add_planes(l);
  l.include(&GenerateParams::points, support_point_params())
      .number(&GenerateParams::object_elevation, "object_elevation", "Object elevation (mm)",
              SupportTreeOptions().object_elevation_mm, Range::at_least(0, "mm"),
              "Greater than 0 (the supports' default): the part will be raised on supports, so its first layer is "
              "an island that gets points too. 0: the part stands on the plate.");
  l.file(&GenerateParams::points_output, ParamType::FileSave, "support_points_file", "Write support points to",
         "*.srp", nullptr,
         "Where to write the points (support-points file, .srp), for Transfer Support Points, Build Supports or the "
         "print jobs. Empty: not written.");
  return l;
}

Result run_generate(const GenerateParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const JobMesh job = job_mesh(p.mesh_file, host);
  const Mesh& mesh = job.mesh;
  const Progress progress = host.progress();
  SliceOptions slicing = slice_options(p.layer_thickness, p.z_start);
  const Slices s = slice_layers(mesh, slicing, sub_progress(progress, 0, 0.4));
  const SupportPoints points =
      generate_support_points(mesh, s, support_point_options(p.points, p.object_elevation), nullptr,
                              sub_progress(progress, 0.4, 1));
  if (!p.points_output.empty()) write_support_points(p.points_output, points);
  add_points_layer(host, job.name, points);
  const size_t islands = count_kind(points, SupportKind::Island);
  const double seconds = seconds_since(start);
  host.log(format("Generate Support Points: %zu points (%zu on islands, %zu on overhangs) on %zu layers, %.3f s",
                  points.size(), islands, points.size() - islands, s.layers(), seconds));
  return {{"points", int64_t(points.size())},
          {"islands", int64_t(islands)},
          {"overhangs", int64_t(points.size() - islands)},
          {"seconds", seconds}};
}

// ---- Transfer Support Points ---------------------------------------------------------------

struct TransferPointsParams {
  std::string support_points_file;
  std::string map_file;
  double layer_thickness;
  double z_start;
  SupportPointParams points;
  double object_elevation;
  std::string points_output;
};

ParamList<TransferPointsParams> transfer_points_params() {
  ParamList<TransferPointsParams> l;
  l.file(&TransferPointsParams::support_points_file, ParamType::FileOpen, "support_points_file",
         "Source support points", "*.srp", "choose the source's support-points file",
         "The support-points file Generate Support Points wrote for a member of the family (the source).")
      .file(&TransferPointsParams::map_file, ParamType::FileOpen, "map_file", "Cross-parameterization map",
            "*.map *.srb", nullptr,
            "Map from the source onto the current mesh when their faces differ, written by Cross-Parameterize "
            "Meshes. Empty: the current mesh must have the source's faces.");
  add_planes(l);
  l.include(&TransferPointsParams::points, support_point_params())
      .number(&TransferPointsParams::object_elevation, "object_elevation", "Object elevation (mm)",
              SupportTreeOptions().object_elevation_mm, Range::at_least(0, "mm"),
              "Greater than 0: the part will be raised on supports, so its first layer needs points. 0: it stands "
              "on the plate.");
  l.file(&TransferPointsParams::points_output, ParamType::FileSave, "member_points_file", "Write support points to",
         "*.srp", nullptr, "Where to write the current mesh's points (support-points file, .srp). Empty: not written.");
  return l;
}

Result run_transfer_points(const TransferPointsParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const Mesh member = host.current_mesh();
  const Progress progress = host.progress();
  const SupportPoints source = read_support_points(p.support_points_file);
  const SurfaceMap map = p.map_file.empty() ? SurfaceMap() : read_map_file(p.map_file, sub_progress(progress, 0, 0.1));
  const Slices s = slice_layers(member, slice_options(p.layer_thickness, p.z_start), sub_progress(progress, 0.1, 0.4));
  SupportTransferStats st;
  const SupportPoints points =
      transfer_support_points(source, member, s, support_point_options(p.points, p.object_elevation), &st,
                              p.map_file.empty() ? nullptr : &map, sub_progress(progress, 0.4, 1));
  if (!p.points_output.empty()) write_support_points(p.points_output, points);
  add_points_layer(host, host.current_mesh_name(), points);
  const double seconds = seconds_since(start);
  host.log(format("Transfer Support Points: %zu of the source's points: %zu kept, %zu moved, %zu dropped; %zu added; "
                  "%zu points%s, %.3f s",
                  st.transferred, st.kept, st.moved, st.dropped, st.added, points.size(),
                  p.map_file.empty() ? "" : ", through the map", seconds));
  return {{"transferred", int64_t(st.transferred)}, {"kept", int64_t(st.kept)},       {"moved", int64_t(st.moved)},
          {"added", int64_t(st.added)},             {"dropped", int64_t(st.dropped)}, {"points", int64_t(points.size())},
          {"seconds", seconds}};
}

// ---- Build Supports ------------------------------------------------------------------------

struct BuildParams {
  int points_layer;
  std::string support_points_file;
  double layer_thickness;
  double z_start;
  SupportTreeOptions tree;
};

ParamList<BuildParams> build_params() {
  ParamList<BuildParams> l;
  l.mesh(&BuildParams::points_layer, "points_layer", "Support points layer",
         "The point layer of the current mesh's support points (Generate or Transfer Support Points add one; "
         "points may be deleted or moved on the surface there; a point farther than 1 mm from the surface is "
         "refused). Ignored when support_points_file is given. In a "
         ".mlx script: the 0-based index of the layer as loaded.")
      .file(&BuildParams::support_points_file, ParamType::FileOpen, "support_points_file", "Support points file",
            "*.srp", nullptr,
            "The current mesh's support-points file, instead of the point layer. Empty (the default): the point "
            "layer.");
  add_planes(l);
  l.include(&BuildParams::tree, support_tree_params());
  return l;
}

Result run_build(const BuildParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const Mesh part = host.current_mesh();
  SupportPoints points;
  if (p.support_points_file.empty()) {
    const Mesh layer = host.mesh_at(p.points_layer);
    if (layer.faces() > 0)
      throw Error(format("the support points layer (layer %d) is a mesh of %zu faces, not a point layer",
                         p.points_layer, layer.faces()));
    points = locate_support_points(part, layer.V, {}, kUserPointReachMm);
  } else {
    points = read_support_points(p.support_points_file);
    validate_support_points(points, &part);
    place_support_points(points, part);
  }
  const SliceOptions slicing = slice_options(p.layer_thickness, p.z_start);
  const double z_start = std::isnan(slicing.z_start) ? z_range(part).min : slicing.z_start;
  const size_t below = support_layers_below(p.tree, p.layer_thickness);
  const SupportTree tree = build_support_tree(
      part, points, support_ground_z(z_start, p.layer_thickness, p.tree), p.tree);
  host.add_mesh_layer(host.current_mesh_name() + " supports", tree.mesh);
  const double seconds = seconds_since(start);
  host.log(format("Build Supports: %zu points (%zu dropped: their surface faces up; %zu dropped: the part lies right under "
                  "them, or no pillar fits under them and their head would hang), %zu pillars to the %s, %zu "
                  "heads bridged to a neighbour's pillar, %zu ending on the part, ground at z %g mm (%zu layers below "
                  "the part's first), %zu faces, %.3f s",
                  points.size(), tree.up_facing, tree.unroutable, tree.pillars, p.tree.pad_enable ? "pad" : "plate", tree.bridged,
                  tree.on_part, tree.ground_z, below, tree.mesh.faces(), seconds));
  return {{"points", int64_t(points.size())},
          {"pillars", int64_t(tree.pillars)},
          {"bridged", int64_t(tree.bridged)},
          {"on_part", int64_t(tree.on_part)},
          {"layers_below", int64_t(below)},
          {"ground_z", tree.ground_z},
          {"seconds", seconds}};
}

}  // namespace

FilterSpec generate_support_points_filter() {
  const std::string description = std::string(
      "<p>Finds where the current mesh (or a mesh file, read without a layer) needs support to be printed layer by "
      "layer, from its slicing: "
      "<i>islands</i> (a region of a layer that rests on nothing below) and <i>overhangs</i> (the part of a "
      "layer reaching farther than the self-supporting distance beyond the layer below), and places support "
      "points on them, at most the minimal distance apart and denser with <i>density</i>, in the manner of "
      "PrusaSlicer's SLA support points.</p>"
      "<p>Each point is recorded in the encoding's own terms, the face it lies on and its area coordinates "
      "there, so that <i>Transfer Support Points</i> carries it to every member of the family. The points are "
      "written to a support-points file (.srp) and added as a new point layer, <i>&lt;mesh&gt; support "
      "points</i>, where they can be selected and deleted with MeshLab's tools before <i>Build Supports</i>.</p>") +
      kReference;
  return typed_filter({FilterId::GenerateSupportPoints, "Generate Support Points", "generate_support_points",
                       description, Arity::None, kLayerClass, false},
                      generate_params(), run_generate, {"points", "islands", "overhangs", "seconds"});
}

FilterSpec transfer_support_points_filter() {
  const std::string description = std::string(
      "<p>Carries a family source's support points (a support-points file from <i>Generate Support Points</i>) "
      "to the current mesh, as <i>Transfer Slicing to Mesh</i> carries contours: each point keeps its face and "
      "area coordinates and takes the current mesh's vertices (or goes through a cross-parameterization map "
      "when the faces differ).</p>"
      "<p>Each point is then checked on the current mesh, sliced on the same planes: <i>kept</i> where the "
      "surface still needs support there, <i>dropped</i> otherwise; islands and overhangs no kept point "
      "covers get new points (<i>added</i>, or <i>moved</i> when next to a dropped one). The points are "
      "written to a support-points file and added as a point layer, <i>&lt;mesh&gt; support points</i>.</p>") +
      kReference;
  return typed_filter({FilterId::TransferSupportPoints, "Transfer Support Points", "transfer_support_points",
                       description, Arity::CurrentMesh, kLayerClass, true},
                      transfer_points_params(), run_transfer_points,
                      {"transferred", "kept", "moved", "added", "dropped", "points", "seconds"});
}

FilterSpec build_supports_filter() {
  const std::string description = std::string(
      "<p>Builds the current mesh's support structure from its support points (a point layer, or a "
      "support-points file), after PrusaSlicer's SLA supports with its SL1S defaults: at each point a head "
      "(a cone whose tip enters the part), a pillar down to the pad or the plate standing on a base cone, or "
      "onto the part with a small head where the way down is blocked, or, where that takes less resin or the "
      "way down is blocked, a bridge at 45 degrees to a neighbouring pillar; pillars taller than 15 mm linked "
      "to a neighbour by bridges; optionally a pad under it all. A point "
      "whose surface faces up (within 30 degrees of straight up) gets none, as in PrusaSlicer.</p>"
      "<p>The part is not moved: the supports stand <i>object elevation</i> (rounded to whole layers) below "
      "its first layer, so the print jobs slice the part on its own planes and add those layers below it. "
      "The structure is added as a new mesh layer, <i>&lt;mesh&gt; supports</i>.</p>") +
      kReference;
  return typed_filter({FilterId::BuildSupports, "Build Supports", "build_supports", description,
                       Arity::CurrentMesh, kLayerClass, true},
                      build_params(), run_build,
                      {"points", "pillars", "bridged", "on_part", "layers_below", "ground_z", "seconds"});
}

}  // namespace slicereuse::plugin
