// "Add Labels": where the jobs would cut the current mesh's label into its base, shown as the
// label's outline on the base (a layer of polylines), without making a print file.
#include <filesystem>

#include "filter_params.h"
#include "filters_common.h"
#include "slicereuse/mesh/mesh.h"
#include "slicereuse/plates/base_label.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/slicing/layer_planes.h"
#include "slicereuse/slicing/slice_layers.h"

namespace slicereuse::plugin {
namespace {

struct AddLabelsParams {
  std::string label;
  double height_mm;
  double depth_mm;
  double layer_thickness;
};

ParamList<AddLabelsParams> add_labels_params() {
  const LabelOptions d;
  ParamList<AddLabelsParams> l;
  l.text(&AddLabelsParams::label, "label", "Label", "",
         "The text to cut into the base: letters, digits, '-', '_', '.', '/', '+', '#'. Empty (the default): the "
         "mesh's name without its extension, as the jobs' labels.")
      .number(&AddLabelsParams::height_mm, "label_height_mm", "Label height (mm)", d.height_mm, Range::above(0, "mm"),
              "Height of the letters; where they do not fit, a tenth less at a time, down to a third of this, turned "
              "if need be (as the jobs' labels).")
      .number(&AddLabelsParams::depth_mm, "label_depth_mm", "Label depth (mm)", d.depth_mm, Range::above(0, "mm"),
              "How deep the letters are cut: the label must fit the base as all the layers down to that depth share it.")
      .number(&AddLabelsParams::layer_thickness, "layer_thickness", "Layer thickness (mm)", 0.05, Range::above(0, "mm"),
              "The layers the base is read from, sliced from the mesh's lowest vertex, as a print job slices it.");
  return l;
}

Result run_add_labels(const AddLabelsParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const Mesh mesh = host.current_mesh();
  const std::string name = host.current_mesh_name();
  if (mesh.faces() == 0) throw Error("the current mesh has no faces: it has no base to label");
  const std::string text = p.label.empty() ? std::filesystem::path(name).stem().string() : p.label;
  LabelOptions o;
  o.height_mm = p.height_mm;
  o.min_height_mm = p.height_mm / 3;
  o.depth_mm = p.depth_mm;
  const ZRange z = z_range(mesh);
  const std::vector<double> planes = layer_planes(z.min, p.layer_thickness, z.max);
  const size_t layers = engraved_layers(o.depth_mm, p.layer_thickness, planes.size());
  const Slices first = slice_planes(mesh, {planes.begin(), planes.begin() + long(layers)}, host.progress(), false);
  const BaseLabel b = place_base_label(first, double(planes.size()) * p.layer_thickness, text, name, o);
  if (!b.placement.placed) throw Error(b.why);
  // The label's outline on the base: each loop of its region, closed, at the mesh's lowest z.
  std::vector<double> xyz;
  std::vector<uint32_t> segments;
  for (const ClipperLib::Path& loop : b.placement.region) {
    const uint32_t first_point = uint32_t(xyz.size() / 3);
    for (size_t i = 0; i < loop.size(); ++i) {
      xyz.insert(xyz.end(), {double(loop[i].X) / kRegionScale, double(loop[i].Y) / kRegionScale, z.min});
      segments.insert(segments.end(), {first_point + uint32_t(i), first_point + uint32_t((i + 1) % loop.size())});
    }
  }
  host.add_polyline_layer(format("label %s", text.c_str()), xyz, segments);
  host.log(format("Add Labels: '%s' on the base of %s, %.3g mm high, centred at (%.2f, %.2f) mm, turned %.0f degrees, "
                  "%.3g mm deep (%zu layers of %.3g mm)",
                  text.c_str(), name.c_str(), b.placement.height_mm, b.placement.x_mm + 0.0, b.placement.y_mm + 0.0,
                  b.placement.angle_deg + 0.0, o.depth_mm, b.layers, p.layer_thickness));
  return {{"label_height_mm", b.placement.height_mm},
          {"x_mm", b.placement.x_mm},
          {"y_mm", b.placement.y_mm},
          {"angle_deg", b.placement.angle_deg},
          {"seconds", seconds_since(start)}};
}

}  // namespace

FilterSpec add_labels_filter() {
  const std::string description = std::string(
      "<p>Shows where the current mesh's label would be cut into its base: the label (the mesh's name, or the "
      "text given) placed as <i>Make Print Job</i> and <i>Make Plate Job</i> place it with <i>labels</i> on, "
      "mirrored to read from below, as large as fits up to the label height on the region the base's layers "
      "share down to the label's depth, 1 mm inside its edges, turned if need be. Adds a layer with the "
      "label's outline on the base, and gives its height, centre and turn; a label that fits nowhere, or a "
      "mesh less than 1 mm taller than the label is deep, is refused in words. The mesh is not changed: the "
      "jobs cut the label from the layers' contours.</p>") +
      kReference;
  return typed_filter({FilterId::AddLabels, "Add Labels", "add_labels", description, Arity::CurrentMesh,
                       kLayerClass, false},
                      add_labels_params(), run_add_labels, {"label_height_mm", "x_mm", "y_mm", "angle_deg", "seconds"});
}

}  // namespace slicereuse::plugin
