// MeshLab 2020.09 shim: the MeshFilterInterface plugin that declares the filters of
// filter_api.h as RichParameters, implements Host over a MeshDocument, and reports every
// error through errorMessage + the log (meshlabserver prints only the log) + return false.
// Debian builds MeshLab with assertions on, so nothing here may reach one: parameter types are
// checked before each get*(), and no RichMesh is made from a missing current mesh.
#include <common/interfaces.h>

#include <algorithm>
#include <exception>

#include "filter_api.h"
#include "mesh_convert.h"
#include "slicereuse/error.h"

using namespace slicereuse;
using namespace slicereuse::plugin;

namespace {

QString qs(const std::string& s) { return QString::fromStdString(s); }

const char* rich_type(ParamType type) {
  switch (type) {
    case ParamType::Float: return "RichFloat";
    case ParamType::Int: return "RichInt";
    case ParamType::Bool: return "RichBool";
    case ParamType::Enum: return "RichEnum";
    case ParamType::String: return "RichString";
    case ParamType::FileOpen: return "RichOpenFile";
    case ParamType::FileSave: return "RichSaveFile";
    case ParamType::Mesh: return "RichMesh";
  }
  return "?";
}

bool has_type(const Value& v, ParamType type) {
  switch (type) {
    case ParamType::Float: return v.isFloat();
    case ParamType::Int: return v.isInt() && !v.isEnum();
    case ParamType::Bool: return v.isBool();
    case ParamType::Enum: return v.isEnum();
    case ParamType::String: return v.isString();
    case ParamType::FileOpen:
    case ParamType::FileSave: return v.isFileName();
    case ParamType::Mesh: return v.isMesh();
  }
  return false;
}

void add_param(const ParamSpec& p, MeshDocument& md, RichParameterList& list) {
  const QString name = qs(p.name), label = qs(p.label), tip = qs(p.tooltip);
  switch (p.type) {
    case ParamType::Float: list.addParam(RichFloat(name, float(p.default_number), label, tip)); break;
    case ParamType::Int: list.addParam(RichInt(name, int(p.default_number), label, tip)); break;
    case ParamType::Bool: list.addParam(RichBool(name, p.default_number != 0, label, tip)); break;
    case ParamType::Enum: {
      QStringList values;
      for (const std::string& v : p.enum_values) values << qs(v);
      list.addParam(RichEnum(name, int(p.default_number), values, label, tip));
      break;
    }
    case ParamType::String: list.addParam(RichString(name, qs(p.default_text), label, tip)); break;
    case ParamType::FileOpen:
      list.addParam(RichOpenFile(name, qs(p.default_text), qs(p.file_filter).split(' ', Qt::SkipEmptyParts),
                                 label, tip));
      break;
    case ParamType::FileSave:
      list.addParam(RichSaveFile(name, qs(p.default_text), qs(p.file_filter), label, tip));
      break;
    case ParamType::Mesh:
      // RichMesh(name, model, doc) asserts that model is in doc: with no mesh loaded
      // (meshlabserver without -i) use the index-only form; the script then supplies the index.
      if (md.mm() != nullptr)
        list.addParam(RichMesh(name, md.mm(), &md, label, tip));
      else
        list.addParam(RichMesh(name, -1, label, tip));
      break;
  }
}

ParamValues read_values(const FilterSpec& spec, const MeshDocument& md, const RichParameterList& list) {
  ParamValues values;
  for (const ParamSpec& p : spec.params) {
    const QString name = qs(p.name);
    if (!list.hasParameter(name)) throw Error("parameter '" + p.name + "' is missing");
    const Value& v = list.getParameterByName(name).value();
    if (!has_type(v, p.type))
      throw Error("parameter '" + p.name + "' has the wrong type; it must be a " + rich_type(p.type));
    switch (p.type) {
      case ParamType::Float: values.numbers[p.name] = float_as_typed(v.getFloat()); break;
      case ParamType::Int: values.numbers[p.name] = v.getInt(); break;
      case ParamType::Bool: values.numbers[p.name] = v.getBool() ? 1 : 0; break;
      case ParamType::Enum: values.numbers[p.name] = v.getEnum(); break;
      case ParamType::String: values.texts[p.name] = v.getString().toStdString(); break;
      case ParamType::FileOpen:
      case ParamType::FileSave: values.texts[p.name] = v.getFileName().toStdString(); break;
      case ParamType::Mesh: {
        const int index = md.meshList.indexOf(v.getMesh());
        if (index < 0) throw Error("parameter '" + p.name + "' does not name a loaded mesh");
        values.numbers[p.name] = index;
        break;
      }
    }
  }
  return values;
}

class DocumentHost : public Host {
 public:
  DocumentHost(MeshDocument& md, MeshLabInterface& plugin, vcg::CallBackPos* cb)
      : md_(md), plugin_(plugin), cb_(cb) {}

  Mesh current_mesh() override {
    if (md_.mm() == nullptr) throw Error("there is no current mesh: open a mesh first");
    return mesh_from_vcg(md_.mm()->cm);
  }

  Mesh mesh_at(int index) override {
    if (index < 0 || index >= md_.meshList.size())
      throw Error("mesh index " + std::to_string(index) + " out of range: " +
                  std::to_string(md_.meshList.size()) + " meshes are loaded");
    return mesh_from_vcg(md_.meshList[index]->cm);
  }

  void add_polyline_layer(const std::string& name, const std::vector<double>& xyz,
                          const std::vector<uint32_t>& segments) override {
    MeshModel* layer = md_.addNewMesh("", qs(name), false);
    fill_polyline_mesh(layer->cm, xyz, segments);
  }

  void log(const std::string& line) override { plugin_.Log(GLLogStream::FILTER, line); }

  Progress progress() override {
    if (cb_ == nullptr) return {};
    // MeshLab's callback takes whole percents; skip calls that would not move it.
    return [cb = cb_, last = -1](double fraction, const char* phase) mutable {
      const int percent = std::clamp(int(fraction * 100), 0, 100);
      if (percent == last) return true;
      last = percent;
      return cb(percent, phase);
    };
  }

 private:
  MeshDocument& md_;
  MeshLabInterface& plugin_;
  vcg::CallBackPos* cb_;
};

}  // namespace

class FilterSliceReusePlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  FilterSliceReusePlugin() {
    for (const FilterSpec& f : filter_specs()) {
      typeList << int(f.id);
      actionList << new QAction(qs(f.name), this);
    }
  }

  QString pluginName() const override { return "FilterSliceReuse"; }
  QString filterName(FilterIDType id) const override { return spec(id) ? qs(spec(id)->name) : QString(); }
  QString filterInfo(FilterIDType id) const override { return spec(id) ? qs(spec(id)->description) : QString(); }
  QString filterScriptFunctionName(FilterIDType id) override {
    return spec(id) ? qs(spec(id)->python_name) : QString();
  }

  FilterClass getClass(QAction* a) override {
    switch (FilterId(ID(a))) {
      case FilterId::CompareMasks: return FilterClass(Measure | Layer);
      default: return Layer;
    }
  }

  FILTER_ARITY filterArity(QAction* a) const override {
    switch (FilterId(ID(a))) {
      case FilterId::SliceWithEncoding: return SINGLE_MESH;
      case FilterId::TransferSlicing: return FIXED;
      default: return NONE;
    }
  }

  // Only slicing needs the current mesh to have faces; the file-only filters need no mesh.
  int getPreConditions(QAction* a) const override {
    return FilterId(ID(a)) == FilterId::SliceWithEncoding ? int(MeshModel::MM_FACENUMBER)
                                                          : int(MeshModel::MM_NONE);
  }
  // No filter changes an existing mesh (slicing may add a new layer).
  int postCondition(QAction*) const override { return MeshModel::MM_NONE; }

  void initParameterSet(QAction* a, MeshDocument& md, RichParameterList& list) override {
    if (const FilterSpec* f = spec(ID(a)))
      for (const ParamSpec& p : f->params) add_param(p, md, list);
  }

  bool applyFilter(QAction* a, MeshDocument& md, const RichParameterList& list,
                   vcg::CallBackPos* cb) override {
    const FilterSpec* f = spec(ID(a));
    if (f == nullptr) return fail("unknown filter " + a->text().toStdString());
    try {
      const ParamValues values = read_values(*f, md, list);
      DocumentHost host(md, *this, cb);
      run_filter(f->id, values, host);
      return true;
    } catch (const std::exception& e) {
      return fail(f->name + ": " + e.what());
    } catch (...) {
      return fail(f->name + ": unexpected error");
    }
  }

 private:
  static const FilterSpec* spec(FilterIDType id) {
    for (const FilterSpec& f : filter_specs())
      if (int(f.id) == id) return &f;
    return nullptr;
  }

  bool fail(const std::string& message) {
    errorMessage = qs(message);
    Log(GLLogStream::WARNING, "Error: " + message);
    return false;
  }
};

#include "shim_2020.moc"
