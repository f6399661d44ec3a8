// "Slice Mesh with Encoding": slice_layers on the current mesh, then the contour and encoding
// files (written together or not at all) and an optional preview layer.
#include "filter_params.h"
#include "filters_common.h"
#include "slicereuse/formats/slice_files.h"
#include "slicereuse/mesh/mesh_defects.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"

namespace slicereuse::plugin {
namespace {

struct SliceParams {
  std::string mesh_file;
  double layer_thickness;
  double z_start;
  std::string contour_file;
  std::string encoding_file;
  FileFormat file_format;
  int preview_layers;
};

ParamList<SliceParams> slice_params() {
  ParamList<SliceParams> l;
  add_mesh_file(l, &SliceParams::mesh_file)
      .number(&SliceParams::layer_thickness, "layer_thickness", "Layer thickness (mm)", 0.1, Range::above(0, "mm"),
           "Distance between consecutive slicing planes, in mm; must be greater than 0.")
      .number(&SliceParams::z_start, "z_start", "Start height (mm)", kLowestVertexZStart, Range::any(),
              "Height of the bottom of the first layer, in mm. Any value at or below -1e29 (the default, -1e30) "
              "means: the lowest vertex of the mesh.")
      .file(&SliceParams::contour_file, ParamType::FileSave, "contour_file", "Contour file", "*.ctr *.srb", nullptr,
            "Where to write the contour points (format chosen by File format). Empty: no contour file is written.")
      .file(&SliceParams::encoding_file, ParamType::FileSave, "encoding_file", "Encoding file", "*.enc *.srb", nullptr,
            "Where to write the encoding (face and area coordinates of every point) used by Transfer Slicing to "
            "Mesh. Empty: no encoding file is written.")
      .choice(&SliceParams::file_format, "file_format", "File format", {"text", "binary"}, FileFormat::Text,
              "text: readable .ctr/.enc files; binary: compact, faster .srb files with checksums. Both keep every "
              "coordinate exactly.")
      .whole(&SliceParams::preview_layers, "preview_layers", "Preview layers", 0, Range::at_least(0, "layers"),
             "Adds the contours of up to this many evenly spaced layers as a new edge-mesh layer, for a visual "
             "check. 0: no layer is added.");
  return l;
}

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

Result run_slice(const SliceParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const SliceOptions options = slice_options(p.layer_thickness, p.z_start);

  const JobMesh job = job_mesh(p.mesh_file, host);
  const Mesh& mesh = job.mesh;
  if (mesh.faces() == 0) throw Error("the current mesh has no faces; there is nothing to slice");

  const Progress progress = host.progress();
  const auto slicing_start = std::chrono::steady_clock::now();
  const Slices s = slice_layers(mesh, options, sub_progress(progress, 0, 0.6));
  const double slicing_seconds = seconds_since(slicing_start);
  StagedOutputs outputs;
  if (!p.contour_file.empty())
    write_contour_file(outputs.file(p.contour_file), s, p.file_format, sub_progress(progress, 0.6, 0.8));
  if (!p.encoding_file.empty())
    write_encoding_file(outputs.file(p.encoding_file), s, p.file_format, sub_progress(progress, 0.8, 1));
  outputs.commit();

  if (p.preview_layers >= 1) {
    std::vector<double> xyz;
    std::vector<uint32_t> segments;
    preview_polylines(s, size_t(p.preview_layers), xyz, segments);
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
  const ZRange z = z_range(mesh);
  if (s.contours() == 0) {
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
          {"mesh_z_min", z.min},
          {"mesh_z_max", z.max},
          {"read_seconds", job.read_seconds},
          {"slicing_seconds", slicing_seconds},
          {"seconds", seconds}};
}

}  // namespace

FilterSpec slice_filter() {
  const std::string description = std::string(
      "<p>Slices the current mesh (or a mesh file, read without a layer) into horizontal layers of closed contours for "
      "layer-based 3D printing, and records for every contour point its "
      "<i>encoding</i>: the mesh face it lies on and its area (barycentric) "
      "coordinates there. The encoding lets <i>Transfer Slicing to Mesh</i> produce "
      "the contours of any customized member of the same product family (same "
      "triangles, moved vertices) without slicing it again.</p>"
      "<p>Layer <i>k</i> spans [z_start + k&middot;h, z_start + (k+1)&middot;h] and "
      "is cut by its mid-plane z_start + (k+&frac12;)&middot;h, where h is the layer "
      "thickness; layers are added while their bottom is below the mesh top. "
      "Lengths are in mm (mesh units). Outer contours run counter-clockwise and holes "
      "clockwise seen from +z; holes in the mesh give open contours, which are kept "
      "and counted.</p>"
      "<p>Writes a contour file and an encoding file (text .ctr / .enc, or binary "
      ".srb; see docs/formats.md). Both appear together or not at all. Optionally "
      "adds a few layers' contours as a new edge-mesh layer to look at.</p>") +
      kReference;
  return typed_filter({FilterId::SliceWithEncoding, "Slice Mesh with Encoding", "slice_mesh_with_encoding",
                       description, Arity::None, kLayerClass, false},
                      slice_params(), run_slice,
                      {"layers", "contours", "points", "open_contours", "duplicate_faces", "zero_area_faces",
                       "repeated_vertex_faces", "boundary_edges", "non_manifold_edges", "z_start", "mesh_z_min",
                       "mesh_z_max", "read_seconds", "slicing_seconds", "seconds"});
}

}  // namespace slicereuse::plugin
