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
                                                arrange_plates_filter()};
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

void check_outputs(const std::vector<std::pair<const char*, std::string>>& named_paths) {
  namespace fs = std::filesystem;
  std::vector<std::pair<const char*, fs::path>> seen;
  for (const auto& [name, path] : named_paths) {
    if (path.empty()) continue;
    try {
      check_writable(path);
    } catch (const Error& e) {
      throw Error(std::string(name) + ": " + e.what());
    }
    const fs::path normal = fs::absolute(path).lexically_normal();
    for (const auto& [other_name, other] : seen)
      if (other == normal)
        throw Error(std::string(name) + " and " + other_name + " are the same file: " + path);
    seen.emplace_back(name, normal);
  }
}

}  // namespace slicereuse::plugin
