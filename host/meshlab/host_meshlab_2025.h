#pragma once
// What the MeshLab 2025.07 API (pymeshlab 2025.7; double Scalarm) needs that 2020.09 does
// differently: the traits struct MeshLab2025 for host_adapter.h. Shared by every slicereuse
// plugin built for 2025.07; host_meshlab_2020.h has the same members.
//
// A RichMesh value is the mesh's id (pymeshlab's mesh id, which is what a script passes).
#include <common/plugins/interfaces/filter_plugin.h>

#include <vector>

namespace slicereuse::plugin {

struct MeshLab2025 {
  using FilterPlugin = ::FilterPlugin;
  using Logger = const MeshLabPluginLogger;
  using FileOpenParam = RichFileOpen;
  using FileSaveParam = RichFileSave;
  static constexpr const char* kMeshRef = "id";

  static void add_mesh_param(RichParameterList& list, const QString& name, const MeshDocument& md,
                             const QString& label, const QString& tip) {
    list.addParam(RichMesh(name, md.mm() ? md.mm()->id() : 0, &md, label, tip));
  }
  static int enum_index(const Value& v) { return v.getInt(); }
  static QString file_name(const Value& v) { return v.getString(); }
  static int mesh_ref(const Value& v, const MeshDocument&) { return v.getInt(); }
  static MeshModel* mesh_by_ref(MeshDocument& md, int ref) {
    return ref >= 0 ? md.getMesh(unsigned(ref)) : nullptr;
  }
  static int mesh_count(const MeshDocument& md) { return int(md.meshNumber()); }
  // Every loaded mesh, in the document's order.
  static std::vector<MeshModel*> meshes(MeshDocument& md) {
    std::vector<MeshModel*> out;
    for (MeshModel& m : md.meshIterator()) out.push_back(&m);
    return out;
  }
  // Adds a layer filled by fill, not made current (addNewMesh(CMeshO) also updates its bounding
  // box and data mask).
  template <class Fill>
  static void add_layer(MeshDocument& md, const QString& name, Fill fill) {
    CMeshO mesh;
    fill(mesh);
    md.addNewMesh(mesh, name, false);
  }
  static void log(Logger& logger, const std::string& line) { logger.log(line); }
};

}  // namespace slicereuse::plugin
