// MeshLab 2025.07 shim (pymeshlab 2025.7, double scalar): turns filter_specs() into a
// FilterPlugin, reads RichParameterList into ParamValues, implements Host over MeshDocument and
// maps the core's errors to MLException, which pymeshlab raises as PyMeshLabException.
#include <new>

#include <common/plugins/interfaces/filter_plugin.h>

#include "filter_api.h"
#include "mesh_convert.h"
#include "slicereuse/error.h"

namespace slicereuse::plugin {
namespace {

QString qstr(const std::string& s) { return QString::fromStdString(s); }

const FilterSpec& spec_of(MeshLabPlugin::ActionIDType id) {
  for (const FilterSpec& f : filter_specs())
    if (int(f.id) == id) return f;
  throw MLException("slicereuse: unknown filter id " + QString::number(id));
}

RichParameterList parameters(const FilterSpec& f, const MeshDocument& md) {
  RichParameterList list;
  for (const ParamSpec& p : f.params) {
    const QString name = qstr(p.name), label = qstr(p.label), tip = qstr(p.tooltip);
    switch (p.type) {
      case ParamType::Float: list.addParam(RichFloat(name, Scalarm(p.default_number), label, tip)); break;
      case ParamType::Int: list.addParam(RichInt(name, int(p.default_number), label, tip)); break;
      case ParamType::Bool: list.addParam(RichBool(name, p.default_number != 0, label, tip)); break;
      case ParamType::Enum: {
        QStringList values;
        for (const std::string& v : p.enum_values) values << qstr(v);
        list.addParam(RichEnum(name, int(p.default_number), values, label, tip));
        break;
      }
      case ParamType::String: list.addParam(RichString(name, qstr(p.default_text), label, tip)); break;
      case ParamType::FileOpen:
        list.addParam(RichFileOpen(name, qstr(p.default_text), qstr(p.file_filter).split(' '), label, tip));
        break;
      case ParamType::FileSave:
        list.addParam(RichFileSave(name, qstr(p.default_text), qstr(p.file_filter), label, tip));
        break;
      case ParamType::Mesh:
        list.addParam(RichMesh(name, md.mm() ? md.mm()->id() : 0, &md, label, tip));
        break;
    }
  }
  return list;
}

ParamValues read_values(const FilterSpec& f, const RichParameterList& par) {
  ParamValues v;
  for (const ParamSpec& p : f.params) {
    const QString name = qstr(p.name);
    switch (p.type) {
      case ParamType::Float: v.numbers[p.name] = float_as_typed(float(par.getFloat(name))); break;
      case ParamType::Int: v.numbers[p.name] = par.getInt(name); break;
      case ParamType::Bool: v.numbers[p.name] = par.getBool(name) ? 1 : 0; break;
      case ParamType::Enum: v.numbers[p.name] = par.getEnum(name); break;
      case ParamType::Mesh: v.numbers[p.name] = par.getMeshId(name); break;
      case ParamType::String: v.texts[p.name] = par.getString(name).toStdString(); break;
      case ParamType::FileOpen: v.texts[p.name] = par.getOpenFileName(name).toStdString(); break;
      case ParamType::FileSave: v.texts[p.name] = par.getSaveFileName(name).toStdString(); break;
    }
  }
  return v;
}

class DocumentHost : public Host {
 public:
  DocumentHost(MeshDocument& md, vcg::CallBackPos* cb, const MeshLabPluginLogger& logger)
      : md_(md), cb_(cb), logger_(logger) {}

  Mesh current_mesh() override {
    if (!md_.mm()) throw Error("there is no current mesh: load a mesh first");
    return mesh_from_vcg(md_.mm()->cm);
  }

  Mesh mesh_at(int id) override {
    MeshModel* m = id >= 0 ? md_.getMesh(unsigned(id)) : nullptr;
    if (!m) throw Error("target_mesh: there is no mesh with id " + std::to_string(id));
    return mesh_from_vcg(m->cm);
  }

  void add_polyline_layer(const std::string& name, const std::vector<double>& xyz,
                          const std::vector<uint32_t>& segments) override {
    CMeshO polylines;
    fill_polyline_mesh(polylines, xyz, segments);
    // Not made current: a following filter should still act on the mesh the user chose.
    md_.addNewMesh(polylines, qstr(name), false);
  }

  void log(const std::string& line) override { logger_.log(line); }

  Progress progress() override {
    if (!cb_) return {};
    vcg::CallBackPos* cb = cb_;
    return [cb](double fraction, const char* phase) { return cb(int(100 * fraction), phase); };
  }

 private:
  MeshDocument& md_;
  vcg::CallBackPos* cb_;
  const MeshLabPluginLogger& logger_;
};

// pymeshlab converts only bool, int, float, double and Eigen values into its result dict (and
// prints a warning for anything else), so counts that overflow int become doubles and texts
// go to the log only.
std::map<std::string, QVariant> to_variants(const Result& result, const MeshLabPluginLogger& logger) {
  std::map<std::string, QVariant> out;
  for (const auto& [key, value] : result) {
    if (const double* d = std::get_if<double>(&value)) {
      out[key] = QVariant(*d);
    } else if (const int64_t* i = std::get_if<int64_t>(&value)) {
      const bool fits = *i >= INT32_MIN && *i <= INT32_MAX;
      out[key] = fits ? QVariant(int(*i)) : QVariant(double(*i));
    } else {
      logger.log(key + ": " + std::get<std::string>(value));
    }
  }
  return out;
}

}  // namespace

class SliceReusePlugin : public QObject, public FilterPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
  Q_INTERFACES(FilterPlugin)

 public:
  SliceReusePlugin() {
    for (const FilterSpec& f : filter_specs()) {
      typeList.push_back(int(f.id));
      actionList.push_back(new QAction(qstr(f.name), this));
    }
  }

  QString pluginName() const override { return "FilterSliceReuse"; }
  QString vendor() const override { return "slicereuse"; }
  QString filterName(ActionIDType id) const override { return qstr(spec_of(id).name); }
  QString pythonFilterName(ActionIDType id) const override { return qstr(spec_of(id).python_name); }
  QString filterInfo(ActionIDType id) const override { return qstr(spec_of(id).description); }
  FilterClass getClass(const QAction*) const override { return FilterPlugin::Other; }
  FilterArity filterArity(const QAction* a) const override {
    return spec_of(ID(a)).needs_current_mesh ? SINGLE_MESH : NONE;
  }
  int getPreConditions(const QAction* a) const override {
    return spec_of(ID(a)).needs_current_mesh ? int(MeshModel::MM_FACEVERT) : int(MeshModel::MM_NONE);
  }
  // The filters read meshes and write files; the only document change is an added layer.
  int postCondition(const QAction*) const override { return MeshModel::MM_NONE; }

  RichParameterList initParameterList(const QAction* a, const MeshDocument& md) override {
    return parameters(spec_of(ID(a)), md);
  }

  std::map<std::string, QVariant> applyFilter(const QAction* a, const RichParameterList& par,
                                              MeshDocument& md, unsigned int& postConditionMask,
                                              vcg::CallBackPos* cb) override {
    postConditionMask = MeshModel::MM_NONE;
    try {
      const FilterSpec& f = spec_of(ID(a));
      DocumentHost host(md, cb, *this);
      return to_variants(run_filter(f.id, read_values(f, par), host), *this);
    } catch (const MLException&) {
      throw;
    } catch (const std::bad_alloc&) {
      throw MLException("slicereuse: out of memory");
    } catch (const std::exception& e) {
      throw MLException(QString::fromUtf8(e.what()));
    }
  }
};

}  // namespace slicereuse::plugin

#include "shim_2025.moc"
