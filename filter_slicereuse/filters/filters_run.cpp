// The list of filters and the helpers the filter implementations share (filters_common.h).
#include <cstdio>
#include <filesystem>

#include "filters_common.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"

namespace slicereuse::plugin {

const std::vector<FilterSpec>& filter_specs() {
  static const std::vector<FilterSpec> specs = {slice_filter(),      transfer_filter(),          export_masks_filter(),
                                                compare_masks_filter(), print_job_filter(),
                                                cross_parameterize_filter(), free_cached_memory_filter(), plate_job_filter(),
                                                arrange_plates_filter(), generate_support_points_filter(),
                                                transfer_support_points_filter(), build_supports_filter(),
                                                check_printability_filter(), add_labels_filter(),
                                                hollow_mesh_filter(), add_drain_holes_filter()};
  return specs;
}

const FilterSpec* find_filter_spec(int id) {
  for (const FilterSpec& f : filter_specs())
    if (int(f.id) == id) return &f;
  return nullptr;
}

const char* const kReference =
    "<p>Method: <i>T.-H. Kwok, H. Ye, Y. Chen, C. Zhou, W. Xu</i>, "
    "<b>\"Mass Customization: Reuse of Digital Slicing for Additive Manufacturing\"</b>, "
    "ASME IDETC/CIE 2016; J. Comput. Inf. Sci. Eng. 17(2), 2017.</p>";

SliceOptions slice_options(double layer_thickness, double z_start) {
  SliceOptions options;
  options.thickness = layer_thickness;
  options.z_start = z_start_option(z_start);
  return options;
}

JobMesh job_mesh(const std::string& mesh_file, Host& host) {
  if (mesh_file.empty()) return {host.current_mesh(), host.current_mesh_name(), 0};
  const auto start = std::chrono::steady_clock::now();
  Host::NamedMesh read = std::move(host.read_mesh_files({mesh_file}).at(0));
  return {std::move(read.mesh), std::move(read.name), seconds_since(start)};
}

void check_outputs(const std::vector<std::pair<std::string, std::string>>& named_paths) {
  namespace fs = std::filesystem;
  std::vector<std::pair<std::string, fs::path>> seen;
  for (const auto& [name, path] : named_paths) {
    if (path.empty()) continue;
    try {
      check_writable(path);
    } catch (const Error& e) {
      throw Error(name + ": " + e.what());
    }
    const fs::path normal = fs::absolute(path).lexically_normal();
    for (const auto& [other_name, other] : seen)
      if (other == normal)
        throw Error(name + " and " + other_name + " are the same file: " + path);
    seen.emplace_back(name, normal);
  }
}

namespace {

// A declared result key "prefix_*" stands for any key "prefix_<something>".
bool is_pattern(const std::string& declared) {
  return declared.size() > 2 && declared.compare(declared.size() - 2, 2, "_*") == 0;
}

bool declares(const FilterSpec& spec, const std::string& key) {
  for (const std::string& d : spec.results) {
    const size_t prefix = d.size() - 1;  // of a pattern: up to the "_"
    if (is_pattern(d) ? key.size() > prefix && key.compare(0, prefix, d, 0, prefix) == 0 : key == d) return true;
  }
  return false;
}

}  // namespace

void check_result_keys(const FilterSpec& spec, const Result& result) {
  for (const auto& entry : result)
    if (!declares(spec, entry.first))
      throw Error("internal error: " + spec.name + " returned '" + entry.first + "', which its spec does not declare");
  for (const std::string& d : spec.results)
    if (!is_pattern(d) && !result.count(d))
      throw Error("internal error: " + spec.name + " did not return '" + d + "', which its spec declares");
}

}  // namespace slicereuse::plugin
