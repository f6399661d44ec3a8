// "Cross-Parameterize Meshes": the map between two loaded meshes of different connectivity
// (cross_parameterize), written as a map file for Transfer Slicing to Mesh, with its quality
// report, and both meshes coloured per vertex by corresponding patch.
#include <cmath>

#include "filter_params.h"
#include "filters_common.h"
#include "slicereuse/crossparam/cross_parameterize.h"
#include "slicereuse/formats/map_files.h"
#include "slicereuse/formats/pickpoints_file.h"
#include "slicereuse/util/error.h"

namespace slicereuse::plugin {
namespace {

// Kenneth Kelly's 20 colours of maximum contrast (without white and black), then hues a golden
// angle apart: neighbouring patch ids get clearly different colours, and a patch id always gets
// the same colour on both meshes.
void patch_color(uint32_t id, uint8_t rgba[4]) {
  static const uint32_t kKelly[20] = {0xF3C300, 0x875692, 0xF38400, 0xA1CAF1, 0xBE0032, 0xC2B280, 0x848482,
                                      0x008856, 0xE68FAC, 0x0067A5, 0xF99379, 0x604E97, 0xF6A600, 0xB3446C,
                                      0xDCD300, 0x882D17, 0x8DB600, 0x654522, 0xE25822, 0x2B3D26};
  uint32_t rgb;
  if (id < 20) {
    rgb = kKelly[id];
  } else {  // HSV with s = 0.7, v = 0.9, h stepping by the golden ratio of a turn
    const double h = std::fmod(id * 0.6180339887498949, 1.0) * 6, v = 0.9, s = 0.7;
    const int sector = int(h);
    const double f = h - sector, p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    const double c[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
    rgb = 0;
    for (int i = 0; i < 3; ++i) rgb = rgb << 8 | uint32_t(std::lround(c[sector % 6][i] * 255));
  }
  rgba[0] = uint8_t(rgb >> 16);
  rgba[1] = uint8_t(rgb >> 8);
  rgba[2] = uint8_t(rgb);
  rgba[3] = 255;
}

std::vector<uint8_t> patch_colors(const std::vector<uint32_t>& patch) {
  std::vector<uint8_t> rgba(4 * patch.size());
  for (size_t v = 0; v < patch.size(); ++v) patch_color(patch[v], &rgba[4 * v]);
  return rgba;
}


struct CrossParamParams {
  int source_mesh;
  int target_mesh;
  std::string source_landmarks;
  std::string target_landmarks;
  bool in_plane;
  std::string map_file;
};

ParamList<CrossParamParams> crossparam_params() {
  ParamList<CrossParamParams> l;
  l.mesh(&CrossParamParams::source_mesh, "source_mesh", "Source mesh",
         "The sliced family member (whose encoding will be transferred). In a .mlx script: the 0-based index of "
         "the mesh as loaded.")
      .mesh(&CrossParamParams::target_mesh, "target_mesh", "Target mesh",
            "The member with other connectivity that the source is mapped onto. In a .mlx script: the 0-based "
            "index of the mesh as loaded.")
      .file(&CrossParamParams::source_landmarks, ParamType::FileOpen, "source_landmarks", "Source landmarks", "*.pp",
            nullptr,
            "PickPoints file (.pp) of landmarks on the source, matched to the target's by name. Empty (with "
            "target_landmarks empty): found automatically.")
      .file(&CrossParamParams::target_landmarks, ParamType::FileOpen, "target_landmarks", "Target landmarks", "*.pp",
            nullptr,
            "PickPoints file (.pp) of the corresponding landmarks on the target, with the same names. Empty (with "
            "source_landmarks empty): found automatically.")
      .flag(&CrossParamParams::in_plane, "in_plane", "In-plane", true,
            "Keep heights: a source point at height h maps to height h on the target, so layers map onto the same "
            "layers (the method's in-plane constraint).")
      .file(&CrossParamParams::map_file, ParamType::FileSave, "map_file", "Map file", "*.map *.srb",
            "choose where to write the map (.map text or .srb binary)",
            "Where to write the map (text .map unless the name ends in .srb), for Transfer Slicing to Mesh's "
            "map_file.");
  return l;
}


Result run_cross_parameterize(const CrossParamParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  if (p.source_mesh == p.target_mesh)
    throw Error("source_mesh and target_mesh are the same mesh: choose the two meshes to map between");
  if (p.source_landmarks.empty() != p.target_landmarks.empty())
    throw Error(std::string(p.source_landmarks.empty() ? "source_landmarks" : "target_landmarks") +
                " is empty but the other landmark file is given: give both (.pp files from MeshLab's "
                "PickPoints, matched by name) or neither (automatic correspondence)");

  CrossParamOptions options;
  options.in_plane = p.in_plane;
  if (!p.source_landmarks.empty()) {
    LandmarkPairs pairs = landmark_pairs(p.source_landmarks, p.target_landmarks);
    options.source_landmarks = std::move(pairs.source);
    options.target_landmarks = std::move(pairs.target);
  }
  const Mesh source = host.mesh_at(p.source_mesh);
  const Mesh target = host.mesh_at(p.target_mesh);
  const Progress progress = host.progress();
  const CrossParamResult r = cross_parameterize(source, target, options, sub_progress(progress, 0, 0.9));
  write_map_file(p.map_file, r.map, sub_progress(progress, 0.9, 1));
  host.set_vertex_colors(p.source_mesh, patch_colors(r.source_patch));
  host.set_vertex_colors(p.target_mesh, patch_colors(r.target_patch));

  const CrossParamQuality& q = r.quality;
  const double seconds = seconds_since(start);
  host.log(format("Cross-Parameterize Meshes: %llu patches, genus %d, %llu flipped triangles, height error max %.3g "
                  "mm (RMS %.3g mm), area distortion %.3g, angle distortion %.3g deg, %.3f s (map %.3f s)",
                  (unsigned long long)q.patches, q.genus, (unsigned long long)q.flipped_triangles,
                  q.max_height_error, q.rms_height_error, q.area_distortion, q.angle_distortion, seconds,
                  q.seconds));
  return {{"patches", int64_t(q.patches)},
          {"genus", int64_t(q.genus)},
          {"flipped_triangles", int64_t(q.flipped_triangles)},
          {"max_height_error", q.max_height_error},
          {"rms_height_error", q.rms_height_error},
          {"area_distortion", q.area_distortion},
          {"angle_distortion", q.angle_distortion},
          {"map_seconds", q.seconds},
          {"seconds", seconds}};
}

}  // namespace

// Remeshing class: MeshLab lists its own maps between meshes there (Iso Parametrization and its
// transfer between meshes), while Texture holds filters that make UV coordinates and images.
FilterSpec cross_parameterize_filter() {
  const std::string description = std::string(
      "<p>Computes a map between two members of a product family whose meshes differ "
      "in connectivity (other vertex count, triangles or order: a remeshed model, "
      "another scan), so that <i>Transfer Slicing to Mesh</i> can reuse the source's "
      "slicing on the target. Each source vertex gets a point on the target (face "
      "and barycentric coordinates), written to the map file (.map text or .srb "
      "binary; see docs/formats.md) with both meshes' fingerprints.</p>"
      "<p>With <b>in-plane</b> on (the method's constraint), a point at height h "
      "maps to a point at height h on the target, so each source layer maps into the "
      "same layer of the target. Corresponding landmarks (MeshLab PickPoints .pp "
      "files, matched by point name; a landmark snaps to the nearest surface point) "
      "steer the correspondence; without them it is found automatically. Meshes "
      "of different genus cannot be mapped and are refused.</p>"
      "<p>Reports flipped triangles (0 for a bijective map), the maximum and RMS "
      "height error of mapped vertices (mm), area and angle distortion, and the "
      "time. Colours both meshes per vertex by corresponding patch: the same colour "
      "marks corresponding regions, to check the map at a glance.</p>") +
      kReference;
  return typed_filter({FilterId::CrossParameterize, "Cross-Parameterize Meshes", "cross_parameterize_meshes",
                       description, Arity::MeshParameters, kRemeshingClass, true, {}, true},
                      crossparam_params(), run_cross_parameterize,
                      {"patches", "genus", "flipped_triangles", "max_height_error", "rms_height_error",
                       "area_distortion", "angle_distortion", "map_seconds", "seconds"});
}

}  // namespace slicereuse::plugin
