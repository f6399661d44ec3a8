// "Cross-Parameterize Meshes": the map between two loaded meshes of different connectivity
// (cross_parameterize), written as a map file for Transfer Slicing to Mesh, with its quality
// report, and both meshes coloured per vertex by corresponding patch.
#include <cmath>

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

}  // namespace

Result run_cross_parameterize(const ParamValues& values, Host& host) {
  const auto start = std::chrono::steady_clock::now();
  const int source_ref = int(values.number("source_mesh")), target_ref = int(values.number("target_mesh"));
  if (source_ref == target_ref)
    throw Error("source_mesh and target_mesh are the same mesh: choose the two meshes to map between");
  const std::string& source_landmarks = values.text("source_landmarks");
  const std::string& target_landmarks = values.text("target_landmarks");
  if (source_landmarks.empty() != target_landmarks.empty())
    throw Error(std::string(source_landmarks.empty() ? "source_landmarks" : "target_landmarks") +
                " is empty but the other landmark file is given: give both (.pp files from MeshLab's "
                "PickPoints, matched by name) or neither (automatic correspondence)");
  const std::string& map_file = values.text("map_file");
  if (map_file.empty()) throw Error("map_file is empty: choose where to write the map (.map text or .srb binary)");
  check_outputs({{"map_file", map_file}});

  CrossParamOptions options;
  options.in_plane = values.number("in_plane") != 0;
  if (!source_landmarks.empty()) {
    LandmarkPairs pairs = landmark_pairs(source_landmarks, target_landmarks);
    options.source_landmarks = std::move(pairs.source);
    options.target_landmarks = std::move(pairs.target);
  }
  const Mesh source = host.mesh_at(source_ref);
  const Mesh target = host.mesh_at(target_ref);
  const Progress progress = host.progress();
  const CrossParamResult r = cross_parameterize(source, target, options, sub_progress(progress, 0, 0.9));
  write_map_file(map_file, r.map, sub_progress(progress, 0.9, 1));
  host.set_vertex_colors(source_ref, patch_colors(r.source_patch));
  host.set_vertex_colors(target_ref, patch_colors(r.target_patch));

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

}  // namespace slicereuse::plugin
