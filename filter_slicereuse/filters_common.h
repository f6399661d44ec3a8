#pragma once
// Helpers shared by the filter implementations (filters_*.cpp); internal to the plugin.
#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include "filter_api.h"
#include "slicereuse/formats/slice_files.h"
#include "slicereuse/masks/export_masks.h"
#include "slicereuse/masks/printer_profile.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/util/format.h"

namespace slicereuse::plugin {

// The filters, called by run_filter.
Result run_slice(const ParamValues& values, Host& host);
Result run_transfer(const ParamValues& values, Host& host);
Result run_export_masks(const ParamValues& values, Host& host);
Result run_compare_masks(const ParamValues& values, Host& host);
Result run_print_job(const ParamValues& values, Host& host);
Result run_cross_parameterize(const ParamValues& values, Host& host);

// Parameters that several filters share, read and checked once (errors name the parameter).
SliceOptions read_slice_options(const ParamValues& values);        // layer_thickness, z_start
PrinterProfile read_printer_profile(const ParamValues& values);    // printer_params()
const std::string& mask_output_path(const ParamValues& values);    // output_path
// Logs the warning for a part that does not fit the display.
void log_display_warning(Host& host, const char* filter, const MaskExportStats& stats,
                         const PrinterProfile& profile);
// Binary when the name ends in .srb, text otherwise.
FileFormat format_for_name(const std::string& path);

// Checks that every non-empty output path can be written and that no two are the same file,
// naming the parameter in the error; called before any work is done.
void check_outputs(const std::vector<std::pair<const char*, std::string>>& named_paths);

double seconds_since(std::chrono::steady_clock::time_point start);

}  // namespace slicereuse::plugin
