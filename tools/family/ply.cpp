// PLY writing for test meshes (see shapes.h); read_mesh_file (slicereuse/formats/mesh_file.h)
// reads them back.
#include <cstring>
#include <string>
#include <vector>

#include "shapes.h"
#include "slicereuse/util/atomic_file.h"

namespace slicereuse::test {

void write_ply(const std::string& path, const Mesh& mesh) {
  const std::string header =
      "ply\nformat binary_little_endian 1.0\ncomment slicereuse test mesh\nelement vertex " +
      std::to_string(mesh.vertices()) +
      "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
      std::to_string(mesh.faces()) + "\nproperty list uchar uint vertex_indices\nend_header\n";
  std::vector<char> out(header.size() + mesh.V.size() * 8 + mesh.faces() * 13);
  char* p = out.data();
  std::memcpy(p, header.data(), header.size());
  p += header.size();
  std::memcpy(p, mesh.V.data(), mesh.V.size() * 8);
  p += mesh.V.size() * 8;
  for (size_t f = 0; f < mesh.faces(); ++f, p += 13) {
    *p = 3;
    std::memcpy(p + 1, &mesh.F[3 * f], 12);
  }
  AtomicFile file(path);
  file.write(out.data(), out.size());
  file.commit();
}

}  // namespace slicereuse::test
