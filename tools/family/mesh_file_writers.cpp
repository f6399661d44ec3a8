// Member mesh file writers for tests and benchmarks (mesh_file_writers.h): the whole file is
// made in memory, then written through AtomicFile.
#include "mesh_file_writers.h"

#include <charconv>
#include <cstdint>
#include <cstring>
#include <string>

#include "slicereuse/util/atomic_file.h"

namespace slicereuse::test {
namespace {

template <class T>
void append_number(std::string& out, T v) {
  char buf[32];
  out.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

void append_floats(std::string& out, const Mesh& mesh, uint32_t v) {
  for (int k = 0; k < 3; ++k) {
    out += ' ';
    append_number(out, float(mesh.V[3 * size_t(v) + size_t(k)]));
  }
}

std::string binary_stl(const Mesh& mesh) {
  std::string out(80, ' ');
  const uint32_t n = uint32_t(mesh.faces());
  out.append(reinterpret_cast<const char*>(&n), 4);
  for (size_t f = 0; f < mesh.faces(); ++f) {
    float facet[12] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) facet[3 + 3 * k + c] = float(mesh.V[3 * size_t(mesh.F[3 * f + size_t(k)]) + size_t(c)]);
    out.append(reinterpret_cast<const char*>(facet), sizeof facet);
    out.append(2, '\0');
  }
  return out;
}

std::string ascii_stl(const Mesh& mesh) {
  std::string out = "solid test\n";
  for (size_t f = 0; f < mesh.faces(); ++f) {
    out += "facet normal 0 0 0\nouter loop\n";
    for (int k = 0; k < 3; ++k) {
      out += "vertex";
      append_floats(out, mesh, mesh.F[3 * f + size_t(k)]);
      out += '\n';
    }
    out += "endloop\nendfacet\n";
  }
  return out + "endsolid test\n";
}

std::string ply(const Mesh& mesh, bool binary) {
  std::string out = std::string("ply\nformat ") + (binary ? "binary_little_endian" : "ascii") +
                    " 1.0\nelement vertex " + std::to_string(mesh.vertices()) +
                    "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                    std::to_string(mesh.faces()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  for (size_t v = 0; v < mesh.vertices(); ++v) {
    if (binary) {
      const float xyz[3] = {float(mesh.V[3 * v]), float(mesh.V[3 * v + 1]), float(mesh.V[3 * v + 2])};
      out.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
    } else {
      append_floats(out, mesh, uint32_t(v));
      out += '\n';
    }
  }
  for (size_t f = 0; f < mesh.faces(); ++f) {
    if (binary) {
      out += char(3);
      out.append(reinterpret_cast<const char*>(&mesh.F[3 * f]), 12);
    } else {
      out += '3';
      for (int k = 0; k < 3; ++k) {
        out += ' ';
        append_number(out, mesh.F[3 * f + size_t(k)]);
      }
      out += '\n';
    }
  }
  return out;
}

std::string obj(const Mesh& mesh) {
  std::string out = "# slicereuse test mesh\n";
  for (size_t v = 0; v < mesh.vertices(); ++v) {
    out += 'v';
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      append_number(out, mesh.V[3 * v + size_t(k)]);
    }
    out += '\n';
  }
  for (size_t f = 0; f < mesh.faces(); ++f) {
    out += 'f';
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      append_number(out, mesh.F[3 * f + size_t(k)] + 1);
    }
    out += '\n';
  }
  return out;
}

}  // namespace

const char* mesh_file_extension(MeshFileKind kind) {
  switch (kind) {
    case MeshFileKind::StlBinary:
    case MeshFileKind::StlAscii: return ".stl";
    case MeshFileKind::PlyBinary:
    case MeshFileKind::PlyAscii: return ".ply";
    case MeshFileKind::Obj: return ".obj";
  }
  return "";
}

const char* mesh_file_kind_name(MeshFileKind kind) {
  switch (kind) {
    case MeshFileKind::StlBinary: return "binary STL";
    case MeshFileKind::StlAscii: return "ASCII STL";
    case MeshFileKind::PlyBinary: return "binary PLY";
    case MeshFileKind::PlyAscii: return "ASCII PLY";
    case MeshFileKind::Obj: return "OBJ";
  }
  return "";
}

void write_mesh_file(const std::string& path, const Mesh& mesh, MeshFileKind kind) {
  const std::string bytes = kind == MeshFileKind::StlBinary ? binary_stl(mesh)
                            : kind == MeshFileKind::StlAscii ? ascii_stl(mesh)
                            : kind == MeshFileKind::Obj      ? obj(mesh)
                                                             : ply(mesh, kind == MeshFileKind::PlyBinary);
  AtomicFile file(path);
  file.write(bytes.data(), bytes.size());
  file.commit();
}

}  // namespace slicereuse::test
