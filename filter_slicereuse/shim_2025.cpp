// MeshLab 2025.07 shim (pymeshlab 2025.7, double scalar): the FilterPlugin over
// host_adapter.h with the MeshLab2025 traits. Errors become MLException, which pymeshlab raises
// as PyMeshLabException; the result becomes pymeshlab's result dict.
#include "host_meshlab_2025.h"
// (the traits header first: host_adapter.h needs the MeshLab declarations)
#include "host_adapter.h"

namespace slicereuse::plugin {

class SliceReusePlugin : public QObject, public FilterPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
  Q_INTERFACES(FilterPlugin)

 public:
  SliceReusePlugin() {
    for (const FilterSpec& f : filter_specs()) {
      typeList.push_back(int(f.id));
      actionList.push_back(new QAction(to_qstring(f.name), this));
    }
  }

  QString pluginName() const override { return "FilterSliceReuse"; }
  QString vendor() const override { return "slicereuse"; }
  QString filterName(ActionIDType id) const override { return to_qstring(spec(id).name); }
  QString pythonFilterName(ActionIDType id) const override { return to_qstring(spec(id).python_name); }
  QString filterInfo(ActionIDType id) const override { return to_qstring(spec(id).description); }
  FilterClass getClass(const QAction* a) const override { return meshlab_class<FilterPlugin>(spec(ID(a))); }
  FilterArity filterArity(const QAction* a) const override { return meshlab_arity<FilterPlugin>(spec(ID(a))); }
  int getPreConditions(const QAction* a) const override { return meshlab_preconditions(spec(ID(a))); }
  // The filters read meshes and write files; the document changes are an added layer and
  // Cross-Parameterize Meshes' vertex colours.
  int postCondition(const QAction* a) const override { return meshlab_postconditions(spec(ID(a))); }

  RichParameterList initParameterList(const QAction* a, const MeshDocument& md) override {
    RichParameterList list;
    add_parameters<MeshLab2025>(spec(ID(a)).params, md, list);
    return list;
  }

  std::map<std::string, QVariant> applyFilter(const QAction* a, const RichParameterList& list,
                                              MeshDocument& md, unsigned int& postConditionMask,
                                              vcg::CallBackPos* cb) override {
    postConditionMask = meshlab_postconditions(spec(ID(a)));
    Result result;
    if (const auto failure = run_logged<MeshLab2025>(ID(a), md, list, *this, cb, result))
      throw MLException(to_qstring(*failure));
    return result_variants(result);
  }

 private:
  static const FilterSpec& spec(ActionIDType id) {
    const FilterSpec* f = find_filter_spec(id);
    if (f == nullptr) throw MLException("slicereuse: unknown filter id " + QString::number(id));
    return *f;
  }
};

}  // namespace slicereuse::plugin

#include "shim_2025.moc"
