#pragma once
// The host-independent face of the slicereuse filters: what each filter is called, which
// parameters it takes, which meshes it needs, and what it does. Written once (each filter's
// file declares its spec, its typed parameters (filter_params.h) and its run); host_adapter.h
// turns FilterSpec into MeshLab declarations and RichParameters, implements Host over a
// MeshDocument and turns Error into the host's error path, for both MeshLab API generations
// (their differences are in host_meshlab_2020.h / host_meshlab_2025.h).
// No Qt and no MeshLab headers here.
#include <charconv>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/slicing/slices.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/progress.h"

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

enum class FilterId { SliceWithEncoding, TransferSlicing, ExportMasks, CompareMasks, MakePrintJob,
                      CrossParameterize, FreeCachedMemory, MakePlateJob, ArrangePlates, GenerateSupportPoints,
                      TransferSupportPoints, BuildSupports, CheckPrintability, AddLabels,
                      HollowMesh, AddDrainHoles };

// Which meshes a filter works on (MeshLab's arity): none (files only), the current mesh, or the
// meshes its Mesh parameters name.
enum class Arity { None, CurrentMesh, MeshParameters };

// The menus a filter appears in (bits; MeshLab's FilterClass has one value per menu).
enum FilterClass : unsigned { kLayerClass = 1, kMeasureClass = 2, kRemeshingClass = 4 };

// Parameter values as the host adapter read them: numbers (Float/Int/Enum/Bool, and Mesh as
// the host's mesh reference: list index in 2020, mesh id in 2025) and texts.
// Inline, like float_as_typed, so another plugin can use the adapter without this plugin's code.
struct ParamValues {
  std::map<std::string, double> numbers;
  std::map<std::string, std::string> texts;
  double number(const std::string& name) const {  // throws Error if missing
    auto it = numbers.find(name);
    if (it == numbers.end()) throw Error("parameter '" + name + "' is missing");
    return it->second;
  }
  const std::string& text(const std::string& name) const {
    auto it = texts.find(name);
    if (it == texts.end()) throw Error("parameter '" + name + "' is missing");
    return it->second;
  }
};

// Both MeshLab generations keep Float parameters as float, so 0.1 typed by the user arrives as
// 0.100000001490116. The shortest decimal that rounds to that float is what the user typed;
// the adapter reads Float parameters through this, so both hosts slice on the planes the user
// meant.
inline double float_as_typed(float value) {
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf, value).ptr;
  double d = value;
  std::from_chars(buf, end, d);
  return d;
}

// What a filter needs from the host; implemented once over MeshLab's MeshDocument by
// DocumentHost in host_adapter.h. To add a method: declare it here, implement it in
// DocumentHost (the MeshDocument calls are the same in both generations; where they differ,
// add a function to both traits headers, host_meshlab_2020.h and host_meshlab_2025.h).
class Host {
 public:
  virtual ~Host() = default;
  virtual Mesh current_mesh() = 0;                   // throws Error if there is none
  virtual std::string current_mesh_name() = 0;       // its layer name; throws Error if there is none
  virtual Mesh mesh_at(int ref) = 0;                 // a Mesh parameter's value; Error if none
  // The loaded meshes that have faces, in the document's order, each with its layer name and
  // whether it is shown (the eye of MeshLab's layer dialog; every mesh pymeshlab and
  // meshlabserver load is shown); only the shown ones when visible_only.
  struct NamedMesh {
    std::string name;
    Mesh mesh;
  };
  virtual std::vector<NamedMesh> meshes_with_faces(bool visible_only) = 0;
  // Mesh files (read_mesh_file, mesh_file.h: STL, PLY, OBJ) read straight into Meshes, on all
  // cores, without a layer each, each named by its file name as the host names a loaded layer.
  // Coordinates are rounded to the host's own (float in 2020.09), so that a member read here is
  // the mesh the host's loader would give. Throws Error naming the file that cannot be read.
  virtual std::vector<NamedMesh> read_mesh_files(const std::vector<std::string>& paths) = 0;
  // The current layer's contours when it is a contour layer (a .ctr, .srb or .cli file opened
  // through the io_encoding plugin; see contour_layer.h); throws Error if it is not.
  virtual Slices current_contour_layer() = 0;
  // Adds a new layer showing polylines: points xyz (3n), segments as point index pairs.
  virtual void add_polyline_layer(const std::string& name, const std::vector<double>& xyz,
                                  const std::vector<uint32_t>& segments) = 0;
  // Adds a new layer of points (no faces): xyz and unit normals, 3n each. The user may select
  // and delete points there with the host's own tools.
  virtual void add_point_layer(const std::string& name, const std::vector<double>& xyz,
                               const std::vector<double>& normals) = 0;
  // Adds a new layer holding a triangle mesh.
  virtual void add_mesh_layer(const std::string& name, const Mesh& mesh) = 0;
  // Colours the vertices of a Mesh parameter's mesh: rgba holds 4 bytes per vertex, in the order
  // of mesh_at's vertices; Error if the count differs.
  virtual void set_vertex_colors(int ref, const std::vector<uint8_t>& rgba) = 0;
  virtual void log(const std::string& line) = 0;
  virtual Progress progress() = 0;
};

// Statistics a filter returns: pymeshlab gets them as its result dict, the log as one line.
using Result = std::map<std::string, std::variant<double, int64_t, std::string>>;

struct FilterSpec {
  FilterId id;
  std::string name;         // menu name, e.g. "Slice Mesh with Encoding"
  std::string python_name;  // e.g. "slice_mesh_with_encoding"
  std::string description;  // HTML, shown in the dialog and in pymeshlab's doc
  Arity arity;
  unsigned filter_class;    // FilterClass bits
  bool needs_faces;         // precondition: the current mesh must have faces
  std::vector<ParamSpec> params{};
  // Post-condition: the filter colours the vertices of the meshes its Mesh parameters name
  // (Host::set_vertex_colors), so the host must redraw them with their colours.
  bool colors_vertices = false;
  // Runs the filter: reads and checks the values (filter_params.h), does the work through the
  // host, returns the figures. Throws Error with a message that names the problem.
  std::function<Result(const ParamValues&, Host&)> run{};
  // The keys of its Result, declared once (docs/formats.md, "Filter result line", lists them);
  // a key ending in "_*" stands for one key per plate or member ("area_used_*").
  std::vector<std::string> results{};
};

const std::vector<FilterSpec>& filter_specs();
const FilterSpec* find_filter_spec(int id);  // nullptr if no filter has this id

}  // namespace slicereuse::plugin
