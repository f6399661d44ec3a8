#pragma once
// The host-independent face of the slicereuse filters: what each filter is called, which
// parameters it takes, and what it does. Written once; a shim per MeshLab API generation
// (shim_2020.cpp, shim_2025.cpp) turns FilterSpec into that generation's declarations and
// RichParameters, implements Host over its MeshDocument, and turns Error into its error path.
// No Qt and no MeshLab headers here.
#include <cstdint>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "slicereuse/mesh.h"
#include "slicereuse/progress.h"

namespace slicereuse::plugin {

enum class ParamType { Float, Int, Bool, Enum, String, FileOpen, FileSave, Mesh };

struct ParamSpec {
  std::string name;     // snake_case; also the pymeshlab keyword and the .mlx name
  ParamType type;
  std::string label;    // short text in the dialog
  std::string tooltip;  // one or two sentences: meaning, unit, effect of 0/empty
  double default_number = 0;       // Float, Int, Enum (index), Bool (0/1)
  std::string default_text;        // String, FileOpen, FileSave
  std::vector<std::string> enum_values;  // Enum
  std::string file_filter;         // FileOpen/FileSave, e.g. "*.enc *.srb"
};

enum class FilterId { SliceWithEncoding, TransferSlicing, ExportMasks, CompareMasks };

struct FilterSpec {
  FilterId id;
  std::string name;         // menu name, e.g. "Slice Mesh with Encoding"
  std::string python_name;  // e.g. "slice_mesh_with_encoding"
  std::string description;  // HTML, shown in the dialog and in pymeshlab's doc
  bool needs_current_mesh;  // false: runs on files only (masks, compare)
  std::vector<ParamSpec> params;
};

const std::vector<FilterSpec>& filter_specs();
const FilterSpec& filter_spec(FilterId id);

// Parameter values as the shim read them: numbers (Float/Int/Enum/Bool/Mesh index) and texts.
struct ParamValues {
  std::map<std::string, double> numbers;
  std::map<std::string, std::string> texts;
  double number(const std::string& name) const;      // throws Error if missing
  const std::string& text(const std::string& name) const;
};

// Both MeshLab generations keep Float parameters as float, so 0.1 typed by the user arrives as
// 0.100000001490116. The shortest decimal that rounds to that float is what the user typed;
// shims read Float parameters through this, so both hosts slice on the planes the user meant.
double float_as_typed(float value);

// What a filter needs from the host; implemented by each shim.
class Host {
 public:
  virtual ~Host() = default;
  virtual Mesh current_mesh() = 0;                   // throws Error if there is none
  virtual Mesh mesh_at(int index) = 0;               // a Mesh parameter's value
  // Adds a new layer showing polylines: points xyz (3n), segments as point index pairs.
  virtual void add_polyline_layer(const std::string& name, const std::vector<double>& xyz,
                                  const std::vector<uint32_t>& segments) = 0;
  virtual void log(const std::string& line) = 0;
  virtual Progress progress() = 0;
};

// Statistics a filter returns: pymeshlab gets them as its result dict, the log as one line.
using Result = std::map<std::string, std::variant<double, int64_t, std::string>>;

// Runs a filter; throws Error (with a message that names the problem) on bad input.
Result run_filter(FilterId id, const ParamValues& values, Host& host);

}  // namespace slicereuse::plugin
