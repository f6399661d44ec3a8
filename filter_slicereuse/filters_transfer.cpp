// "Transfer Slicing to Mesh": a source encoding applied to a family member with the same faces,
// or, through a map file from Cross-Parameterize Meshes, to a member with other faces.
#include "filters_common.h"
#include "slicereuse/formats/file_names.h"
#include "slicereuse/formats/map_files.h"
#include "slicereuse/formats/slice_files.h"
#include "slicereuse/transfer/transfer_contours.h"
#include "slicereuse/transfer/transfer_through_map.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"

namespace slicereuse::plugin {
// The transfer and print job filters have no format parameter: the output name decides, .srb
// (any case) being binary.
FileFormat format_for_name(const std::string& path) {
  return is_binary_file_name(path) ? FileFormat::Binary : FileFormat::Text;
}

Result run_transfer(const ParamValues& values, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const double mode_index = values.number("mode");
  if (mode_index != 0 && mode_index != 1)
    throw Error(format("mode must be 0 (exact) or 1 (barycentric), got %g", mode_index));
  const TransferMode mode = TransferMode(int(mode_index));
  const std::string& encoding_file = values.text("encoding_file");
  if (encoding_file.empty()) throw Error("encoding_file is empty: choose the source's encoding file");
  const std::string& contour_file = values.text("contour_file");
  const std::string& target_encoding_file = values.text("target_encoding_file");
  const std::string& map_file = values.text("map_file");
  check_outputs({{"contour_file", contour_file}, {"target_encoding_file", target_encoding_file}});

  const Progress progress = host.progress();
  const Slices encoding = read_encoding_file(encoding_file, sub_progress(progress, 0, 0.1));
  const SurfaceMap map = map_file.empty() ? SurfaceMap() : read_map_file(map_file, sub_progress(progress, 0.1, 0.2));
  const Mesh target = host.mesh_at(int(values.number("target_mesh")));
  TransferStats stats;
  const auto transfer_start = std::chrono::steady_clock::now();
  const TransferOptions options(mode, !target_encoding_file.empty());
  const Slices s = map_file.empty()
                       ? transfer_contours(encoding, target, options, &stats, sub_progress(progress, 0.2, 0.6))
                       : transfer_through_map(encoding, map, target, options, &stats, sub_progress(progress, 0.2, 0.6));
  const double transfer_seconds = seconds_since(transfer_start);
  StagedOutputs outputs;
  if (!contour_file.empty())
    write_contour_file(outputs.file(contour_file), s, format_for_name(contour_file),
                       sub_progress(progress, 0.6, 0.8));
  if (!target_encoding_file.empty())
    write_encoding_file(outputs.file(target_encoding_file), s, format_for_name(target_encoding_file),
                        sub_progress(progress, 0.8, 1));
  outputs.commit();

  const double seconds = seconds_since(start);
  std::string line = format("Transfer Slicing to Mesh: %zu points in %zu layers, %zu transferred, %zu re-sliced",
                            s.points(), s.layers(), stats.transferred_layers, stats.resliced_layers);
  if (!map_file.empty()) line += ", through the map";
  if (mode == TransferMode::Barycentric)
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
          {"max_plane_deviation", stats.max_plane_deviation},
          {"transfer_seconds", transfer_seconds},
          {"seconds", seconds}};
}

}  // namespace slicereuse::plugin
