#pragma once
// The one MeshLab host adapter, for both API generations: everything between filter_api.h and
// MeshLab that does not depend on the generation, written once as templates over a small
// traits struct `Api` (host_meshlab_2020.h: MeshLab2020, host_meshlab_2025.h: MeshLab2025) that
// names only what truly differs. Header-only; include it after the traits header.
//
//   add_parameters<Api>(params, md, list)       ParamSpecs -> RichParameters (defaults, labels)
//   read_parameters<Api>(params, md, list)      RichParameters -> ParamValues; Error names the
//                                                parameter if it is missing or of another type
//                                                (values are checked by filter_params.h)
//   DocumentHost<Api>                           Host over a MeshDocument (meshes, new layers,
//                                                vertex colours,
//                                                log, progress clamped and throttled)
//   failure_of(context, body)                   runs body; the message for the host's error path
//                                                if it threw (never an exception type name)
//   result_line(python_name, result)            the machine-readable log line of a result
//   result_variants(result)                     Result -> pymeshlab's result dict
//   meshlab_arity / meshlab_class / meshlab_preconditions / meshlab_postconditions / run_logged:
//                                                the filter plugin's declarations and apply
//
// Another plugin of the same generation (e.g. the io_encoding IO plugin) uses the parameter,
// host, error and result pieces with the same traits: it links the CMake target
// slicereuse_host (host/CMakeLists.txt), which puts this folder on its include path.
//
// Result line, logged after every successful filter in both hosts (meshlabserver has no result
// dict; its log is the only output a script run gives):
//   slicereuse-result <python_name> {"key": value, ...}
// one line, keys sorted, a JSON object: integers as integers, doubles with 17 significant
// digits (null if not finite), texts as JSON strings. pymeshlab's dict holds the same keys with
// the same values, except texts, which pymeshlab cannot return (they are in the line only).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <new>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include <QString>
#include <QStringList>
#include <QVariant>

#include "contour_layer.h"
#include "filter_api.h"
#include "mesh_convert.h"
#include "slicereuse/formats/mesh_file.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/json_string.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse::plugin {

inline QString to_qstring(const std::string& s) { return QString::fromStdString(s); }

// ---- Parameters ---------------------------------------------------------------------------

// What a parameter must be, in words, for error messages.
inline std::string param_kind(const ParamSpec& p) {
  switch (p.type) {
    case ParamType::Float: return "a number";
    case ParamType::Int: return "a whole number";
    case ParamType::Bool: return "true or false";
    case ParamType::Enum: {
      std::string values;
      for (size_t i = 0; i < p.enum_values.size(); ++i)
        values += (i ? ", " : "") + std::to_string(i) + " (" + p.enum_values[i] + ")";
      return "one of " + values;
    }
    case ParamType::String: return "a text";
    case ParamType::FileOpen: return "the name of a file to read";
    case ParamType::FileSave: return "the name of a file to write";
    case ParamType::Mesh: return "a mesh";
  }
  return "?";
}

// Doc is MeshDocument or const MeshDocument, as the generation's init call passes it.
template <class Api, class Doc>
void add_parameters(const std::vector<ParamSpec>& params, Doc& md, RichParameterList& list) {
  for (const ParamSpec& p : params) {
    const QString name = to_qstring(p.name), label = to_qstring(p.label), tip = to_qstring(p.tooltip);
    switch (p.type) {
      case ParamType::Float: list.addParam(RichFloat(name, Scalarm(p.default_number), label, tip)); break;
      case ParamType::Int: list.addParam(RichInt(name, int(p.default_number), label, tip)); break;
      case ParamType::Bool: list.addParam(RichBool(name, p.default_number != 0, label, tip)); break;
      case ParamType::Enum: {
        QStringList values;
        for (const std::string& v : p.enum_values) values << to_qstring(v);
        list.addParam(RichEnum(name, int(p.default_number), values, label, tip));
        break;
      }
      case ParamType::String: list.addParam(RichString(name, to_qstring(p.default_text), label, tip)); break;
      case ParamType::FileOpen:
        list.addParam(typename Api::FileOpenParam(name, to_qstring(p.default_text),
                                                  to_qstring(p.file_filter).split(' ', Qt::SkipEmptyParts),
                                                  label, tip));
        break;
      case ParamType::FileSave:
        list.addParam(typename Api::FileSaveParam(name, to_qstring(p.default_text), to_qstring(p.file_filter),
                                                  label, tip));
        break;
      case ParamType::Mesh: Api::add_mesh_param(list, name, md, label, tip); break;
    }
  }
}

template <class Api>
bool has_type(const RichParameter& rp, ParamType type) {
  switch (type) {
    case ParamType::Float: return dynamic_cast<const RichFloat*>(&rp) != nullptr;
    case ParamType::Int: return dynamic_cast<const RichInt*>(&rp) != nullptr;
    case ParamType::Bool: return dynamic_cast<const RichBool*>(&rp) != nullptr;
    case ParamType::Enum: return dynamic_cast<const RichEnum*>(&rp) != nullptr;
    case ParamType::String: return dynamic_cast<const RichString*>(&rp) != nullptr;
    case ParamType::FileOpen: return dynamic_cast<const typename Api::FileOpenParam*>(&rp) != nullptr;
    case ParamType::FileSave: return dynamic_cast<const typename Api::FileSaveParam*>(&rp) != nullptr;
    case ParamType::Mesh: return dynamic_cast<const RichMesh*>(&rp) != nullptr;
  }
  return false;
}

// Reads every parameter of params from list. The type is checked before any value is read:
// MeshLab's getters assert (2020, Debian builds with assertions on) or convert silently (2025)
// on a value of another type, e.g. from a hand-written .mlx script.
template <class Api>
ParamValues read_parameters(const std::vector<ParamSpec>& params, const MeshDocument& md,
                            const RichParameterList& list) {
  ParamValues values;
  for (const ParamSpec& p : params) {
    const QString name = to_qstring(p.name);
    if (!list.hasParameter(name)) throw Error("parameter '" + p.name + "' is missing");
    const RichParameter& rp = list.getParameterByName(name);
    if (!has_type<Api>(rp, p.type))
      throw Error("parameter '" + p.name + "' must be " + param_kind(p) + ", but it is a " +
                  rp.stringType().toStdString());
    const Value& v = rp.value();
    switch (p.type) {
      case ParamType::Float: values.numbers[p.name] = float_as_typed(float(v.getFloat())); break;
      case ParamType::Int: values.numbers[p.name] = v.getInt(); break;
      case ParamType::Bool: values.numbers[p.name] = v.getBool() ? 1 : 0; break;
      // Its range is checked where it is read (filter_params.h), with every other value's.
      case ParamType::Enum: values.numbers[p.name] = Api::enum_index(v); break;
      case ParamType::String: values.texts[p.name] = v.getString().toStdString(); break;
      case ParamType::FileOpen:
      case ParamType::FileSave: values.texts[p.name] = Api::file_name(v).toStdString(); break;
      case ParamType::Mesh: {
        const int ref = Api::mesh_ref(v, md);
        if (ref < 0) throw Error("parameter '" + p.name + "' does not name a loaded mesh");
        values.numbers[p.name] = ref;
        break;
      }
    }
  }
  return values;
}

// ---- The document host ---------------------------------------------------------------------

// MeshLab's callback takes whole percents: clamped to 0..100, and calls that would not move it
// are skipped (a filter may report progress millions of times).
inline Progress progress_of(vcg::CallBackPos* cb) {
  if (cb == nullptr) return {};
  return [cb, last = -1](double fraction, const char* phase) mutable {
    const int percent = !(fraction > 0) ? 0 : fraction >= 1 ? 100 : int(fraction * 100);
    if (percent == last) return true;
    last = percent;
    return cb(percent, phase);
  };
}

template <class Api>
class DocumentHost : public Host {
 public:
  DocumentHost(MeshDocument& md, typename Api::Logger& logger, vcg::CallBackPos* cb)
      : md_(md), logger_(logger), cb_(cb) {}

  Mesh current_mesh() override {
    if (md_.mm() == nullptr) throw Error("there is no current mesh: open a mesh first");
    return mesh_from_vcg(md_.mm()->cm);
  }

  Mesh mesh_at(int ref) override {
    const MeshModel* m = Api::mesh_by_ref(md_, ref);
    if (m == nullptr)
      throw Error("there is no mesh with " + std::string(Api::kMeshRef) + " " + std::to_string(ref) +
                  " (" + std::to_string(Api::mesh_count(md_)) + " meshes are loaded)");
    return mesh_from_vcg(m->cm);
  }

  // Converted one mesh per core: each conversion is a pass over the mesh that fills fresh memory.
  std::vector<NamedMesh> meshes_with_faces(bool visible_only) override {
    std::vector<const MeshModel*> chosen;
    for (MeshModel* m : Api::meshes(md_))
      if (m->cm.fn > 0 && (!visible_only || m->isVisible())) chosen.push_back(m);
    std::vector<NamedMesh> out(chosen.size());
    for (size_t i = 0; i < chosen.size(); ++i) out[i].name = chosen[i]->label().toStdString();
    parallel_blocks(chosen.size(), [&](size_t i) { out[i].mesh = mesh_from_vcg(chosen[i]->cm); }, {}, "reading meshes");
    return out;
  }

  std::vector<NamedMesh> read_mesh_files(const std::vector<std::string>& paths) override {
    std::vector<NamedMesh> out(paths.size());
    parallel_blocks(
        paths.size(),
        [&](size_t i) {
          out[i].name = std::filesystem::path(paths[i]).filename().string();
          out[i].mesh = read_mesh_file(paths[i]);
          using Scalar = typename CMeshO::ScalarType;
          if constexpr (!std::is_same_v<Scalar, double>)
            for (double& x : out[i].mesh.V) x = double(Scalar(x));
        },
        progress_of(cb_), "reading mesh files");
    return out;
  }

  std::string current_mesh_name() override {
    if (md_.mm() == nullptr) throw Error("there is no current mesh: open a mesh first");
    return md_.mm()->label().toStdString();
  }

  Slices current_contour_layer() override {
    if (md_.mm() == nullptr) throw Error("there is no current layer: open a contour file first");
    return slices_of_contour_layer(md_.mm()->cm);
  }

  // Not made current: a following filter should still act on the mesh the user chose.
  void add_polyline_layer(const std::string& name, const std::vector<double>& xyz,
                          const std::vector<uint32_t>& segments) override {
    Api::add_layer(md_, to_qstring(name), [&](CMeshO& m) { fill_polyline_mesh(m, xyz, segments); });
  }

  void add_point_layer(const std::string& name, const std::vector<double>& xyz,
                       const std::vector<double>& normals) override {
    Api::add_layer(md_, to_qstring(name), [&](CMeshO& m) { fill_point_mesh(m, xyz, normals); });
  }

  void add_mesh_layer(const std::string& name, const Mesh& mesh) override {
    Api::add_layer(md_, to_qstring(name), [&](CMeshO& m) { fill_triangle_mesh(m, mesh); });
  }

  // Marks the colours as present (MM_VERTCOLOR) so that the GUI draws them; the filter's
  // post-condition (meshlab_postconditions) makes it refresh them.
  void set_vertex_colors(int ref, const std::vector<uint8_t>& rgba) override {
    MeshModel* m = Api::mesh_by_ref(md_, ref);
    if (m == nullptr) throw Error("there is no mesh with " + std::string(Api::kMeshRef) + " " + std::to_string(ref));
    m->updateDataMask(MeshModel::MM_VERTCOLOR);
    set_vertex_colors_vcg(m->cm, rgba);
  }

  void log(const std::string& line) override { Api::log(logger_, line); }

  Progress progress() override { return progress_of(cb_); }

 private:
  MeshDocument& md_;
  typename Api::Logger& logger_;
  vcg::CallBackPos* cb_;
};

// ---- Errors and results --------------------------------------------------------------------

// Runs body(); if it throws, returns "<context>: <what went wrong>" for the host's error path
// (2020: errorMessage and the log, then return false; 2025: MLException), else nothing.
template <class Body>
std::optional<std::string> failure_of(const std::string& context, Body&& body) noexcept {
  try {
    body();
    return std::nullopt;
  } catch (const std::bad_alloc&) {
    return context + ": out of memory";
  } catch (const std::exception& e) {
    return context + ": " + e.what();
  } catch (...) {
    return context + ": unexpected error";
  }
}

inline std::string result_line(const std::string& python_name, const Result& result) {
  std::string line = "slicereuse-result " + python_name + " {";
  for (const auto& [key, value] : result) {
    if (line.back() != '{') line += ", ";
    line += json_string(key) + ": ";
    if (const double* d = std::get_if<double>(&value)) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.17g", *d);
      line += std::isfinite(*d) ? buf : "null";
    } else if (const int64_t* i = std::get_if<int64_t>(&value)) {
      line += std::to_string(*i);
    } else {
      line += json_string(std::get<std::string>(value));
    }
  }
  return line + "}";
}

// pymeshlab converts only bool, int, float, double and Eigen values into its result dict (and
// prints a warning for anything else): counts that overflow int become doubles, texts are left
// out (they are in the result line).
inline std::map<std::string, QVariant> result_variants(const Result& result) {
  std::map<std::string, QVariant> out;
  for (const auto& [key, value] : result) {
    if (const double* d = std::get_if<double>(&value)) {
      out[key] = QVariant(*d);
    } else if (const int64_t* i = std::get_if<int64_t>(&value)) {
      const bool fits = *i >= INT32_MIN && *i <= INT32_MAX;
      out[key] = fits ? QVariant(int(*i)) : QVariant(double(*i));
    }
  }
  return out;
}

// ---- The filter plugin's declarations and apply ---------------------------------------------

// Plugin: the generation's filter plugin base (MeshFilterInterface, FilterPlugin), whose
// arity and class enums have the same names and values in both.
template <class Plugin>
auto meshlab_arity(const FilterSpec& f) {
  switch (f.arity) {
    case Arity::None: return Plugin::NONE;
    case Arity::CurrentMesh: return Plugin::SINGLE_MESH;
    case Arity::MeshParameters: return Plugin::FIXED;
  }
  return Plugin::UNKNOWN_ARITY;
}

template <class Plugin>
typename Plugin::FilterClass meshlab_class(const FilterSpec& f) {
  int c = 0;
  if (f.filter_class & kLayerClass) c |= Plugin::Layer;
  if (f.filter_class & kMeasureClass) c |= Plugin::Measure;
  if (f.filter_class & kRemeshingClass) c |= Plugin::Remeshing;
  return typename Plugin::FilterClass(c);
}

inline int meshlab_preconditions(const FilterSpec& f) {
  return f.needs_faces ? int(MeshModel::MM_FACENUMBER) : int(MeshModel::MM_NONE);
}

// What a filter changes in the meshes it names (the GUI refreshes exactly that).
inline int meshlab_postconditions(const FilterSpec& f) {
  return f.colors_vertices ? int(MeshModel::MM_VERTCOLOR) : int(MeshModel::MM_NONE);
}

// Applies filter id to md: reads the parameters, runs the filter, logs the result line.
// Returns the failure message if anything went wrong (the plugin maps it to its error path).
template <class Api>
std::optional<std::string> run_logged(int id, MeshDocument& md, const RichParameterList& list,
                                      typename Api::Logger& logger, vcg::CallBackPos* cb, Result& result) {
  const FilterSpec* f = find_filter_spec(id);
  if (f == nullptr) return "slicereuse: unknown filter id " + std::to_string(id);
  return failure_of(f->name, [&] {
    const ParamValues values = read_parameters<Api>(f->params, md, list);
    DocumentHost<Api> host(md, logger, cb);
    result = f->run(values, host);
    host.log(result_line(f->python_name, result));
  });
}

}  // namespace slicereuse::plugin
