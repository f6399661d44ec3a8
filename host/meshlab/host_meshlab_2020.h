#pragma once
// What the MeshLab 2020.09 API (Debian's MeshLab and meshlabserver; float Scalarm) needs that
// 2025.07 does differently: the traits struct MeshLab2020 for host_adapter.h. Shared by every
// slicereuse plugin built for 2020.09; host_meshlab_2025.h has the same members.
//
// A RichMesh value is a MeshModel*; a script (.mlx) names it by its 0-based position in the
// document's mesh list, so the adapter's mesh reference is that list index.
#include <common/interfaces.h>

#include <QList>
#include <vector>

namespace slicereuse::plugin {

struct MeshLab2020 {
  using FilterPlugin = MeshFilterInterface;
  using Logger = MeshLabInterface;
  using FileOpenParam = RichOpenFile;
  using FileSaveParam = RichSaveFile;
  static constexpr const char* kMeshRef = "index";

  static void add_mesh_param(RichParameterList& list, const QString& name, MeshDocument& md,
                             const QString& label, const QString& tip) {
    // RichMesh(name, model, doc) asserts that model is in doc: with no mesh loaded
    // (meshlabserver without -i) use the index-only form; the script then supplies the index.
    if (md.mm() != nullptr)
      list.addParam(RichMesh(name, md.mm(), &md, label, tip));
    else
      list.addParam(RichMesh(name, -1, label, tip));
  }
  static int enum_index(const Value& v) { return v.getEnum(); }
  static QString file_name(const Value& v) { return v.getFileName(); }
  static int mesh_ref(const Value& v, const MeshDocument& md) { return md.meshList.indexOf(v.getMesh()); }
  static MeshModel* mesh_by_ref(MeshDocument& md, int ref) {
    return ref >= 0 && ref < md.meshList.size() ? md.meshList[ref] : nullptr;
  }
  static int mesh_count(const MeshDocument& md) { return md.meshList.size(); }
  // Every loaded mesh, in the document's order.
  static std::vector<MeshModel*> meshes(MeshDocument& md) { return {md.meshList.begin(), md.meshList.end()}; }
  // Adds an empty layer, not made current, and lets fill write its CMeshO.
  template <class Fill>
  static void add_layer(MeshDocument& md, const QString& name, Fill fill) {
    fill(md.addNewMesh("", name, false)->cm);
  }
  static void log(Logger& logger, const std::string& line) { logger.Log(GLLogStream::FILTER, line); }
};

}  // namespace slicereuse::plugin
