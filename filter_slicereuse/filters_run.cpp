// run_filter's dispatch and the helpers shared by the filter implementations.
#include <cstdio>
#include <filesystem>

#include "filters_common.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"

namespace slicereuse::plugin {

Result run_filter(FilterId id, const ParamValues& values, Host& host) {
  switch (id) {
    case FilterId::SliceWithEncoding: return run_slice(values, host);
    case FilterId::TransferSlicing: return run_transfer(values, host);
    case FilterId::ExportMasks: return run_export_masks(values, host);
    case FilterId::CompareMasks: return run_compare_masks(values, host);
    case FilterId::MakePrintJob: return run_print_job(values, host);
    case FilterId::CrossParameterize: return run_cross_parameterize(values, host);
  }
  throw Error("unknown filter id " + std::to_string(int(id)));
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

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace slicereuse::plugin
