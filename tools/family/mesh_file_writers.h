#pragma once
// write_mesh_file: a mesh as one of the member mesh files read_mesh_file reads
// (slicereuse/formats/mesh_file.h), for its tests and bench_mesh_files. Coordinates are written
// as floats (STL and PLY: 32-bit floats, the ASCII ones as the shortest text that reads back as
// the same float) except OBJ (the shortest text of the double), so a mesh whose coordinates are
// floats reads back bit for bit. STL has no shared vertices: read back, its vertices come in the
// order faces first use them. PLY binary: float x, y, z and uchar count, int vertex_indices.
#include <string>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse::test {

enum class MeshFileKind { StlBinary, StlAscii, PlyBinary, PlyAscii, Obj };

// The extension the kind's files carry (".stl", ".ply", ".obj").
const char* mesh_file_extension(MeshFileKind kind);
// The kind's name for messages and tables ("binary STL", ...).
const char* mesh_file_kind_name(MeshFileKind kind);

void write_mesh_file(const std::string& path, const Mesh& mesh, MeshFileKind kind);

}  // namespace slicereuse::test
