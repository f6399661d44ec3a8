// "Add Labels": where the jobs would cut the current mesh's label into its base, shown as the
// label's outline on the base (a layer of polylines), without making a print file.
#include <filesystem>

#include "filter_params.h"
#include "filters_common.h"
#include "slicereuse/mesh/mesh.h"
#include "slicereuse/plates/base_label.h"
#include "slicereuse/plates/side_label.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/slicing/layer_planes.h"
#include "slicereuse/slicing/slice_layers.h"

namespace slicereuse::plugin {
namespace {

struct AddLabelsParams {
  std::string label;
  double height_mm;
  double depth_mm;
  LabelSide side;
  double layer_thickness;
};

ParamList<AddLabelsParams> add_labels_params() {
  const LabelOptions d;
  ParamList<AddLabelsParams> l;
  l.text(&AddLabelsParams::label, "label", "Label", "",
         "The text to cut into the base or side: letters, digits, '-', '_', '.', '/', '+', '#'. Empty (the default): the "
         "mesh's name without its extension, as the jobs' labels.")
      .number(&AddLabelsParams::height_mm, "label_height_mm", "Label height (mm)", d.height_mm, Range::above(0, "mm"),
              "Height of the letters; where they do not fit, a tenth less at a time, down to a third of this, turned "
              "if need be (as the jobs' labels).")
      .number(&AddLabelsParams::depth_mm, "label_depth_mm", "Label depth (mm)", d.depth_mm, Range::above(0, "mm"),
              "How deep the letters are cut: on the base, the label must fit the region all the layers down to that "
              "depth share.")
      .choice(&AddLabelsParams::side, "label_side", "Label side", label_side_names(), d.side, kLabelSideTooltip)
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
  o.side = p.side;
  const ZRange z = z_range(mesh);
  const std::vector<double> planes = layer_planes(z.min, p.layer_thickness, z.max);
  // The label's outline on the face: each loop of its region, closed.
  std::vector<double> xyz;
  std::vector<uint32_t> segments;
  const auto add_loop = [&](size_t n, const auto& point) {
    const uint32_t first_point = uint32_t(xyz.size() / 3);
    for (size_t i = 0; i < n; ++i) {
      const std::array<double, 3> q = point(i);
      xyz.insert(xyz.end(), q.begin(), q.end());
      segments.insert(segments.end(), {first_point + uint32_t(i), first_point + uint32_t((i + 1) % n)});
    }
  };
  double height = 0, x = 0, y = 0, z_mm = z.min, angle = 0;
  if (o.side == LabelSide::Base) {
    const size_t layers = engraved_layers(o.depth_mm, p.layer_thickness, planes.size());
    const Slices first = slice_planes(mesh, {planes.begin(), planes.begin() + long(layers)}, host.progress(), false);
    const BaseLabel b = place_base_label(first, double(planes.size()) * p.layer_thickness, text, name, o);
    if (!b.placement.placed) throw Error(b.why);
    for (const ClipperLib::Path& loop : b.placement.region)
      add_loop(loop.size(), [&](size_t i) {
        return std::array<double, 3>{double(loop[i].X) / kRegionScale, double(loop[i].Y) / kRegionScale, z.min};
      });
    height = b.placement.height_mm;
    x = b.placement.x_mm;
    y = b.placement.y_mm;
    angle = b.placement.angle_deg;
    host.log(format("Add Labels: '%s' on the base of %s, %.3g mm high, centred at (%.2f, %.2f) mm, turned %.0f "
                    "degrees, %.3g mm deep (%zu layers of %.3g mm)",
                    text.c_str(), name.c_str(), height, x + 0.0, y + 0.0, angle + 0.0, o.depth_mm, b.layers,
                    p.layer_thickness));
  } else {
    const Slices all = slice_planes(mesh, planes, host.progress(), false);
    const SideLabel s = place_side_label(all, p.layer_thickness, 0, text, name, o);
    if (s.cuts.empty()) throw Error(s.why);
    for (const std::vector<std::array<double, 3>>& loop : s.outline)
      add_loop(loop.size(), [&](size_t i) { return loop[i]; });
    height = s.height_mm;
    x = s.x_mm;
    y = s.y_mm;
    z_mm = s.z_mm;
    host.log(format("Add Labels: '%s' on the %s side of %s, %.3g mm high, centred at (%.2f, %.2f, %.2f) mm, %.3g mm "
                    "deep (%zu layers of %.3g mm)",
                    text.c_str(), side_name(o.side), name.c_str(), height, x + 0.0, y + 0.0, z_mm + 0.0, o.depth_mm,
                    s.cuts.size(), p.layer_thickness));
  }
  host.add_polyline_layer(format("label %s", text.c_str()), xyz, segments);
  return {{"label_height_mm", height},
          {"x_mm", x},
          {"y_mm", y},
          {"z_mm", z_mm},
          {"angle_deg", angle},
          {"seconds", seconds_since(start)}};
}

}  // namespace

FilterSpec add_labels_filter() {
  const std::string description = std::string(
      "<p>Shows where the current mesh's label would be cut into its base or a side: the label (the mesh's name, "
      "or the text given) placed as <i>Make Print Job</i> and <i>Make Plate Job</i> place it with <i>labels</i> "
      "on. On the base: mirrored to read from below, as large as fits up to the label height on the region the "
      "base's layers share down to the label's depth, 1 mm inside its edges, turned if need be. On a side (front "
      "-y, back +y, left -x, right +x): upright, readable from outside, centred along the side, as large as fits "
      "where the side is flat within half the depth and solid behind the letters, as near its middle height as "
      "that is. Adds a layer with the label's outline on the face, and gives its height, centre and turn; a label "
      "that fits nowhere, or a mesh less than 1 mm taller than a base label is deep, is refused in words. The mesh "
      "is not changed: the jobs cut the label from the layers' contours.</p>") +
      kReference;
  return typed_filter({FilterId::AddLabels, "Add Labels", "add_labels", description, Arity::CurrentMesh,
                       kLayerClass, false},
                      add_labels_params(), run_add_labels, {"label_height_mm", "x_mm", "y_mm", "z_mm", "angle_deg", "seconds"});
}

}  // namespace slicereuse::plugin
