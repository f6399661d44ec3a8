// "Transfer Slicing to Mesh": a source encoding applied to a family member with the same faces,
// or, through a map file from Cross-Parameterize Meshes, to a member with other faces.
#include "filter_params.h"
#include "filters_common.h"
#include "slicereuse/crossparam/surface_map.h"
#include "slicereuse/formats/file_names.h"
#include "slicereuse/formats/map_files.h"
#include "slicereuse/formats/slice_files.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "slicereuse/transfer/transfer_through_map.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"

namespace slicereuse::plugin {
// The transfer and print job filters have no format parameter: the output name decides, .srb
// (in any case) being binary.
FileFormat format_for_name(const std::string& path) {
  return is_binary_file_name(path) ? FileFormat::Binary : FileFormat::Text;
}

namespace {

struct TransferParams {
  std::string encoding_file;
  int target_mesh;
  TransferMode mode;
  std::string map_file;
  std::string contour_file;
  std::string target_encoding_file;
};

ParamList<TransferParams> transfer_params() {
  ParamList<TransferParams> l;
  l.file(&TransferParams::encoding_file, ParamType::FileOpen, "encoding_file", "Source encoding file", "*.enc *.srb",
         "choose the source's encoding file",
         "Encoding file written by Slice Mesh with Encoding for a member of the family.")
      .mesh(&TransferParams::target_mesh, "target_mesh", "Target mesh",
            "The family member that receives the slicing: with the sliced mesh's faces, or the target of map_file. "
            "In a .mlx script: the 0-based index of the mesh as loaded.")
      .choice(&TransferParams::mode, "mode", "Mode", {"exact", "barycentric"}, TransferMode::Exact,
              "exact: identical to slicing the target (points stay on the planes), and the fastest; barycentric: "
              "the method's area-coordinate mapping, points may leave the planes (through a map it is placed on "
              "the target's section, and is the slower mode).")
      .file(&TransferParams::map_file, ParamType::FileOpen, "map_file", "Cross-parameterization map", "*.map *.srb",
            nullptr,
            "Map from the sliced mesh onto a target with other faces, written by Cross-Parameterize Meshes (.map "
            "text or .srb binary). Empty: the target must have the sliced mesh's faces.")
      .file(&TransferParams::contour_file, ParamType::FileSave, "contour_file", "Contour file", "*.ctr *.srb", nullptr,
            "Where to write the target's contour points (text .ctr unless the name ends in .srb). Empty: not "
            "written.")
      .file(&TransferParams::target_encoding_file, ParamType::FileSave, "target_encoding_file",
            "Target encoding file", "*.enc *.srb", nullptr,
            "Where to write the target's own encoding (text .enc unless the name ends in .srb). Empty: not "
            "written. Through a map, exact mode only (barycentric points do not lie on the target's edges).");
  return l;
}

Result run_transfer(const TransferParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();

  const Progress progress = host.progress();
  const Slices encoding = read_encoding_file(p.encoding_file, sub_progress(progress, 0, 0.1));
  const SurfaceMap map = p.map_file.empty() ? SurfaceMap() : read_map_file(p.map_file, sub_progress(progress, 0.1, 0.2));
  const Mesh target = host.mesh_at(p.target_mesh);
  TransferStats stats;
  const auto transfer_start = std::chrono::steady_clock::now();
  const TransferOptions options(p.mode, !p.target_encoding_file.empty());
  const Slices s = p.map_file.empty()
                       ? transfer_contours(encoding, target, options, &stats, sub_progress(progress, 0.2, 0.6))
                       : transfer_through_map(encoding, map, target, options, &stats, sub_progress(progress, 0.2, 0.6));
  const double transfer_seconds = seconds_since(transfer_start);
  StagedOutputs outputs;
  if (!p.contour_file.empty())
    write_contour_file(outputs.file(p.contour_file), s, format_for_name(p.contour_file),
                       sub_progress(progress, 0.6, 0.8));
  if (!p.target_encoding_file.empty())
    write_encoding_file(outputs.file(p.target_encoding_file), s, format_for_name(p.target_encoding_file),
                        sub_progress(progress, 0.8, 1));
  outputs.commit();

  const double seconds = seconds_since(start);
  std::string line = format("Transfer Slicing to Mesh: %zu points in %zu layers, %zu transferred, %zu re-sliced",
                            s.points(), s.layers(), stats.transferred_layers, stats.resliced_layers);
  if (!p.map_file.empty()) line += ", through the map";
  if (p.mode == TransferMode::Barycentric)
    line += format(", max plane deviation %.3g mm", stats.max_plane_deviation);
  if (stats.dropped_contours > 0)
    line += format(", %zu contours dropped (no surface of the target at their height near their images)",
                   stats.dropped_contours);
  if (stats.unplaced_points > 0)
    line += format(", %zu points not placed on the target's section (no section near their images)",
                   stats.unplaced_points);
  host.log(line + format(", %.3f s (transfer %.3f s)", seconds, transfer_seconds));
  return {{"points", int64_t(s.points())},
          {"layers", int64_t(s.layers())},
          {"transferred_layers", int64_t(stats.transferred_layers)},
          {"resliced_layers", int64_t(stats.resliced_layers)},
          {"through_map", int64_t(!p.map_file.empty())},
          {"max_plane_deviation", stats.max_plane_deviation},
          {"dropped_contours", int64_t(stats.dropped_contours)},
          {"unplaced_points", int64_t(stats.unplaced_points)},
          {"transfer_seconds", transfer_seconds},
          {"seconds", seconds}};
}

}  // namespace

FilterSpec transfer_filter() {
  const std::string description = std::string(
      "<p>Computes the layer contours of a customized family member from the "
      "encoding of a member that was sliced before (<i>Slice Mesh with "
      "Encoding</i>), instead of slicing it again. Without a map, the target mesh "
      "must have exactly the same triangles as the sliced one (same connectivity, "
      "only vertex positions differ); this is checked with a fingerprint of the "
      "faces. A target with other triangles (remeshed, renumbered, another scan) "
      "needs a <i>map file</i> from <i>Cross-Parameterize Meshes</i>.</p>"
      "<p><b>exact</b> mode moves every point along its mesh edge to where the same "
      "plane cuts that edge on the target; through a map, it traces the target's "
      "own contour from the faces the mapped points land on. A layer it cannot "
      "certify is re-sliced directly on the target, so the result equals slicing "
      "the target. <b>barycentric</b> mode applies the encoded area coordinates to "
      "the target's faces (the method's Eq. 2), or carries each point through the "
      "map and places it on the target's section at its layer's height (the nearest "
      "point of it); the largest distance of a carried point from its plane before "
      "that (mm) is reported, and so are contours dropped because the target has no "
      "surface at their height near them.</p>"
      "<p>Writes the target's contour file and, in exact mode, its own encoding, so "
      "it can be a source later. Both appear together or not at all.</p>") +
      kReference;
  return typed_filter({FilterId::TransferSlicing, "Transfer Slicing to Mesh", "transfer_slicing_to_mesh",
                       description, Arity::MeshParameters, kLayerClass, true},
                      transfer_params(), run_transfer,
                      {"points", "layers", "transferred_layers", "resliced_layers", "through_map",
                       "max_plane_deviation", "dropped_contours", "unplaced_points", "transfer_seconds", "seconds"});
}

}  // namespace slicereuse::plugin
