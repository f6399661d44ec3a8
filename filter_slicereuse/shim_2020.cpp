// MeshLab 2020.09 shim: the MeshFilterInterface plugin over host_adapter.h with the MeshLab2020
// traits. Errors go to errorMessage + the log (meshlabserver prints only the log) + return
// false. Debian builds MeshLab with assertions on, so nothing may reach one: the adapter checks
// parameter types before reading them and makes no RichMesh from a missing current mesh.
#include "host_meshlab_2020.h"
// (the traits header first: host_adapter.h needs the MeshLab declarations)
#include "host_adapter.h"

using namespace slicereuse::plugin;

class FilterSliceReusePlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  FilterSliceReusePlugin() {
    for (const FilterSpec& f : filter_specs()) {
      typeList << int(f.id);
      actionList << new QAction(to_qstring(f.name), this);
    }
  }

  QString pluginName() const override { return "FilterSliceReuse"; }
  QString filterName(FilterIDType id) const override { return text(id, &FilterSpec::name); }
  QString filterInfo(FilterIDType id) const override { return text(id, &FilterSpec::description); }
  QString filterScriptFunctionName(FilterIDType id) override { return text(id, &FilterSpec::python_name); }
  FilterClass getClass(QAction* a) override { return meshlab_class<MeshFilterInterface>(spec(a)); }
  FILTER_ARITY filterArity(QAction* a) const override { return meshlab_arity<MeshFilterInterface>(spec(a)); }
  int getPreConditions(QAction* a) const override { return meshlab_preconditions(spec(a)); }
  // Only Cross-Parameterize Meshes changes existing meshes (their vertex colours); slicing may
  // add a new layer.
  int postCondition(QAction* a) const override { return meshlab_postconditions(spec(a)); }

  void initParameterSet(QAction* a, MeshDocument& md, RichParameterList& list) override {
    add_parameters<MeshLab2020>(spec(a).params, md, list);
  }

  bool applyFilter(QAction* a, MeshDocument& md, const RichParameterList& list,
                   vcg::CallBackPos* cb) override {
    Result result;
    if (const auto failure = run_logged<MeshLab2020>(ID(a), md, list, *this, cb, result)) {
      errorMessage = to_qstring(*failure);
      Log(GLLogStream::WARNING, "Error: " + *failure);
      return false;
    }
    return true;
  }

 private:
  QString text(FilterIDType id, std::string FilterSpec::*field) const {
    const FilterSpec* f = find_filter_spec(id);
    return f ? to_qstring(f->*field) : QString();
  }
  // MeshLab asks only about the actions this plugin listed.
  const FilterSpec& spec(QAction* a) const { return *find_filter_spec(ID(a)); }
};

#include "shim_2020.moc"
