// "Slice Mesh with Encoding": slice_layers on the current mesh, then the contour and encoding
// files (written together or not at all) and an optional preview layer.
#include <cmath>
#include <limits>

#include "filters_common.h"
#include "slicereuse/formats/slice_files.h"
#include "slicereuse/mesh/mesh_defects.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"

namespace slicereuse::plugin {
namespace {

// z_start at or below this means "the mesh's lowest vertex" (a spec default cannot be NaN
// or depend on the mesh).
constexpr double kLowestVertexBelow = -1e29;

// The contours of up to n evenly spaced layers as points and segments.
void preview_polylines(const Slices& s, size_t n, std::vector<double>& xyz,
                       std::vector<uint32_t>& segments) {
  const size_t layers = s.layers();
  n = std::min(n, layers);
  for (size_t i = 0; i < n; ++i) {
    const size_t k = (2 * i + 1) * layers / (2 * n);
    for (uint64_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c) {
      const uint64_t b = s.contour_begin[c], e = s.contour_begin[c + 1];
      if (e == b) continue;
      const uint32_t first = uint32_t(xyz.size() / 3);
      xyz.insert(xyz.end(), s.xyz.begin() + 3 * b, s.xyz.begin() + 3 * e);
      const uint32_t count = uint32_t(e - b);
      for (uint32_t j = 0; j + 1 < count; ++j) {
        segments.push_back(first + j);
        segments.push_back(first + j + 1);
      }
      if (!s.contour_open[c] && count > 2) {
        segments.push_back(first + count - 1);
        segments.push_back(first);
      }
    }
  }
}

}  // namespace

SliceOptions read_slice_options(const ParamValues& values) {
  SliceOptions options;
  options.thickness = values.number("layer_thickness");
  if (!(options.thickness > 0) || !std::isfinite(options.thickness))
    throw Error(format("layer_thickness must be greater than 0 mm (got %g)", options.thickness));
  const double z_start = values.number("z_start");
  if (!std::isfinite(z_start)) throw Error("z_start must be a finite number");
  options.z_start = z_start <= kLowestVertexBelow ? std::numeric_limits<double>::quiet_NaN() : z_start;
  return options;
}

Result run_slice(const ParamValues& values, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const SliceOptions options = read_slice_options(values);
  const double format_index = values.number("file_format");
  if (format_index != 0 && format_index != 1)
    throw Error(format("file_format must be 0 (text) or 1 (binary), got %g", format_index));
  const FileFormat file_format = FileFormat(int(format_index));
  const double preview = values.number("preview_layers");
  if (preview < 0) throw Error(format("preview_layers must be 0 or more (got %g)", preview));
  const std::string& contour_file = values.text("contour_file");
  const std::string& encoding_file = values.text("encoding_file");
  check_outputs({{"contour_file", contour_file}, {"encoding_file", encoding_file}});

  const Mesh mesh = host.current_mesh();
  if (mesh.faces() == 0) throw Error("the current mesh has no faces; there is nothing to slice");

  const Progress progress = host.progress();
  const auto slicing_start = std::chrono::steady_clock::now();
  const Slices s = slice_layers(mesh, options, sub_progress(progress, 0, 0.6));
  const double slicing_seconds = seconds_since(slicing_start);
  StagedOutputs outputs;
  if (!contour_file.empty())
    write_contour_file(outputs.file(contour_file), s, file_format, sub_progress(progress, 0.6, 0.8));
  if (!encoding_file.empty())
    write_encoding_file(outputs.file(encoding_file), s, file_format, sub_progress(progress, 0.8, 1));
  outputs.commit();

  if (preview >= 1) {
    std::vector<double> xyz;
    std::vector<uint32_t> segments;
    preview_polylines(s, size_t(preview), xyz, segments);
    host.add_polyline_layer("slice preview", xyz, segments);
  }

  const MeshDefects defects = find_mesh_defects(mesh);
  const double seconds = seconds_since(start);
  host.log(format("Slice Mesh with Encoding: %zu layers, %zu contours, %zu points, %zu open contours, "
                  "%.3f s (slicing %.3f s)",
                  s.layers(), s.contours(), s.points(), s.open_contours(), seconds, slicing_seconds));
  // Say why, where the numbers alone would puzzle: open contours come from the mesh's defects,
  // no contours from a mesh that lies between two planes.
  if (!defects.clean())
    host.log("Slice Mesh with Encoding: the mesh has " + describe_mesh_defects(defects) +
             (s.open_contours() ? "; open contours end where these are" : ""));
  if (s.contours() == 0) {
    const ZRange z = z_range(mesh);
    host.log(format("Slice Mesh with Encoding: no contours: no slicing plane cuts the mesh, which spans z %g to "
                    "%g mm (%zu layer(s) of %g mm, cut at their mid-heights, the first at z %g mm); a part "
                    "thinner than half a layer has none",
                    z.min, z.max, s.layers(), options.thickness, s.layers() ? s.layer_z[0] : 0.0));
  }
  return {{"layers", int64_t(s.layers())},
          {"contours", int64_t(s.contours())},
          {"points", int64_t(s.points())},
          {"open_contours", int64_t(s.open_contours())},
          {"duplicate_faces", int64_t(defects.duplicate_faces)},
          {"zero_area_faces", int64_t(defects.zero_area_faces)},
          {"repeated_vertex_faces", int64_t(defects.repeated_vertex_faces)},
          {"boundary_edges", int64_t(defects.boundary_edges)},
          {"non_manifold_edges", int64_t(defects.non_manifold_edges)},
          {"z_start", s.z_start},
          {"slicing_seconds", slicing_seconds},
          {"seconds", seconds}};
}

}  // namespace slicereuse::plugin
