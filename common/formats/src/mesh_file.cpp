// read_mesh_file (mesh_file.h): reads the whole file into memory, hands it to the reader its
// extension names, then does what MeshLab does after every load: drops the faces that use a
// vertex twice (vertices are all kept); a mesh left without faces is refused.
#include "slicereuse/formats/mesh_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "mesh_file_read.h"
#include "slicereuse/util/buffer.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/input_file.h"

namespace slicereuse {
namespace {

enum class MeshFormat { None, Stl, Ply, Obj };

MeshFormat mesh_format(const std::string& path) {
  const size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return MeshFormat::None;
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "stl") return MeshFormat::Stl;
  if (ext == "ply") return MeshFormat::Ply;
  if (ext == "obj") return MeshFormat::Obj;
  return MeshFormat::None;
}

// Keeps the faces whose three vertices differ, in order (vcg's RemoveDegenerateFace).
void drop_degenerate_faces(std::vector<uint32_t>& F) {
  size_t kept = 0;
  for (size_t f = 0; f + 2 < F.size(); f += 3) {
    const uint32_t a = F[f], b = F[f + 1], c = F[f + 2];
    if (a == b || a == c || b == c) continue;
    F[kept] = a, F[kept + 1] = b, F[kept + 2] = c;
    kept += 3;
  }
  F.resize(kept);
}

}  // namespace

bool is_mesh_file_name(const std::string& path) { return mesh_format(path) != MeshFormat::None; }

Mesh read_mesh_file(const std::string& path) {
  const MeshFormat format = mesh_format(path);
  if (format == MeshFormat::None)
    throw Error("'" + path + "' is not a mesh file this reader takes: the name must end in .stl, .ply or .obj");
  Buffer<char> data;
  {
    const detail::InputFile f = detail::open_input_file(path, "the mesh file");
    data.resize(size_t(f.size()));
    if (!data.empty() && std::fread(data.data(), 1, data.size(), f.get()) != data.size())
      throw Error("cannot read '" + path + "': " + std::strerror(errno));
  }
  const char* kind = format == MeshFormat::Stl ? "STL" : format == MeshFormat::Ply ? "PLY" : "OBJ";
  const detail::MeshBytes in{path, kind, data.data(), data.data() + data.size()};
  Mesh mesh = format == MeshFormat::Stl   ? detail::read_stl_mesh(in)
              : format == MeshFormat::Ply ? detail::read_ply_mesh(in)
                                          : detail::read_obj_mesh(in);
  const size_t faces_read = mesh.faces();
  drop_degenerate_faces(mesh.F);
  if (mesh.F.empty())
    in.fail(faces_read == 0 ? std::string("the file has no faces")
                            : "all " + std::to_string(faces_read) + " faces use a vertex twice: no face is left");
  return mesh;
}

}  // namespace slicereuse
