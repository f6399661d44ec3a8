#pragma once
// The filters' test host: FakeHost, a document of meshes as MeshLab would hold them, without
// MeshLab; and what the filter tests ask of a spec and a result.
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "filter_api.h"
#include "slicereuse/formats/mesh_file.h"
#include "slicereuse/util/error.h"

namespace slicereuse::plugin {

// A document of meshes as MeshLab would hold them: mesh_at(i) is the i-th, the current one is
// `current`; what the filters add or colour is recorded.
class FakeHost : public Host {
 public:
  std::vector<Mesh> meshes;
  int current = 0;
  std::vector<std::string> lines;
  std::vector<std::string> added_layers;
  std::map<int, std::vector<uint8_t>> colors;

  Mesh current_mesh() override {
    if (meshes.empty()) throw Error("there is no current mesh: open a mesh first");
    return meshes.at(size_t(current));
  }
  std::string current_mesh_name() override { return "mesh" + std::to_string(current); }
  Mesh mesh_at(int ref) override {
    if (ref < 0 || size_t(ref) >= meshes.size()) throw Error("there is no mesh with index " + std::to_string(ref));
    return meshes[size_t(ref)];
  }
  // Mesh i is named "mesh<i>" and shown unless hidden[i].
  std::set<size_t> hidden;
  std::vector<NamedMesh> meshes_with_faces(bool visible_only) override {
    std::vector<NamedMesh> out;
    for (size_t i = 0; i < meshes.size(); ++i)
      if (meshes[i].faces() > 0 && !(visible_only && hidden.count(i))) out.push_back({"mesh" + std::to_string(i), meshes[i]});
    return out;
  }
  // Read as the 2025 host reads them (double coordinates), named by file name.
  std::vector<NamedMesh> read_mesh_files(const std::vector<std::string>& paths) override {
    std::vector<NamedMesh> out;
    for (const std::string& p : paths) out.push_back({std::filesystem::path(p).filename().string(), read_mesh_file(p)});
    return out;
  }
  // The current layer is a contour layer holding these when contour_layer has layers.
  Slices contour_layer;
  Slices current_contour_layer() override {
    if (contour_layer.layers() == 0) throw Error("the layer is not a contour layer");
    return contour_layer;
  }
  // Each added polyline, point or mesh layer by name (a polyline layer's points).
  std::map<std::string, std::vector<double>> polyline_layers;
  void add_polyline_layer(const std::string& name, const std::vector<double>& xyz, const std::vector<uint32_t>&) override {
    added_layers.push_back(name);
    polyline_layers[name] = xyz;
  }
  std::map<std::string, std::vector<double>> point_layers;
  std::map<std::string, Mesh> mesh_layers;
  void add_point_layer(const std::string& name, const std::vector<double>& xyz, const std::vector<double>&) override {
    added_layers.push_back(name);
    point_layers[name] = xyz;
  }
  void add_mesh_layer(const std::string& name, const Mesh& mesh) override {
    added_layers.push_back(name);
    mesh_layers[name] = mesh;
  }
  void set_vertex_colors(int ref, const std::vector<uint8_t>& rgba) override { colors[ref] = rgba; }
  void log(const std::string& line) override { lines.push_back(line); }
  Progress progress() override { return {}; }
};

inline const FilterSpec& spec_named(const std::string& python_name) {
  for (const FilterSpec& f : filter_specs())
    if (f.python_name == python_name) return f;
  throw Error("no filter " + python_name);
}

// The values a host reads from a dialog left at its defaults, with `changes` applied.
inline ParamValues defaults(const FilterSpec& f, const std::map<std::string, std::string>& texts = {},
                     const std::map<std::string, double>& numbers = {}) {
  ParamValues v;
  for (const ParamSpec& p : f.params) {
    const bool text = p.type == ParamType::String || p.type == ParamType::FileOpen || p.type == ParamType::FileSave;
    if (text) v.texts[p.name] = p.default_text;
    else v.numbers[p.name] = p.default_number;
  }
  for (const auto& [name, value] : texts) v.texts.at(name) = value;
  for (const auto& [name, value] : numbers) v.numbers.at(name) = value;
  return v;
}

inline std::set<std::string> keys_of(const Result& r) {
  std::set<std::string> keys;
  for (const auto& entry : r) keys.insert(entry.first);
  return keys;
}

inline int64_t count(const Result& r, const std::string& key) { return std::get<int64_t>(r.at(key)); }

}  // namespace slicereuse::plugin
