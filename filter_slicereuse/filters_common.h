#pragma once
// Helpers shared by the filter implementations (filters_*.cpp); internal to the plugin.
#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include "filter_api.h"
#include "slicereuse/format.h"

namespace slicereuse::plugin {

// The filters, called by run_filter.
Result run_slice(const ParamValues& values, Host& host);
Result run_transfer(const ParamValues& values, Host& host);
Result run_export_masks(const ParamValues& values, Host& host);
Result run_compare_masks(const ParamValues& values, Host& host);
Result run_cross_parameterize(const ParamValues& values, Host& host);

// Maps progress of one phase onto [from, to] of the whole filter.
Progress sub_progress(const Progress& progress, double from, double to);

// Makes several output files appear together: each is written under a staging name next to
// its final path (<path>.partial) and commit() renames them all into place. Until then the
// final names are untouched, so a run that fails half-way leaves neither file (nor replaces
// an older one); the destructor removes staging files of a run that did not commit.
class StagedOutputs {
 public:
  StagedOutputs() = default;
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;
  ~StagedOutputs();
  // Returns the staging path to write final_path's content to.
  std::string stage(const std::string& final_path);
  void commit();

 private:
  std::vector<std::pair<std::string, std::string>> files_;  // staging, final
};

// Checks that every non-empty output path can be written and that no two are the same file,
// naming the parameter in the error; called before any work is done.
void check_outputs(const std::vector<std::pair<const char*, std::string>>& named_paths);

double seconds_since(std::chrono::steady_clock::time_point start);

}  // namespace slicereuse::plugin
