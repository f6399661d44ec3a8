// OBJ reader (mesh_file.h): "v" and "f" lines as vcg's import_obj.h reads them into a triangle
// mesh; every other line is ignored. Faces of 5 or more vertices are refused: MeshLab
// triangulates them with GLU's tessellator, whose triangles this reader cannot reproduce.
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "mesh_file_read.h"

namespace slicereuse::detail {
namespace {

// OBJ's blanks: a '\r' of a CRLF line ending too.
bool obj_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::string_view next_word(const char*& p, const char* e) { return next_token(p, e, obj_blank); }

}  // namespace

Mesh read_obj_mesh(const MeshBytes& in) {
  Mesh mesh;
  // A "v" line takes at least 8 bytes and an "f" line at least 8: these never reserve more than
  // the file holds.
  mesh.V.reserve(3 * size_t(in.size() / 32));
  mesh.F.reserve(3 * size_t(in.size() / 32));
  const char* p = in.b;
  uint64_t line = 0;
  while (p < in.e) {
    const char* nl = static_cast<const char*>(std::memchr(p, '\n', size_t(in.e - p)));
    const char* end = nl ? nl : in.e;
    const char* q = p;
    p = nl ? nl + 1 : in.e;
    ++line;
    auto fail = [&](const std::string& what) { in.fail("line " + std::to_string(line) + ": " + what); };
    const char* last = end;
    while (last > q && last[-1] == '\r') --last;
    if (last > q && last[-1] == '\\')
      fail("the line ends in a backslash (continued on the next line), which this reader does not take: join the lines");
    if (q < end && *q == '#') continue;
    const std::string_view key = next_word(q, end);
    if (key == "v") {
      double xyz[3];
      for (double& c : xyz) {
        const std::string_view w = next_word(q, end);
        if (w.empty()) fail("a vertex needs three coordinates: 'v x y z'");
        if (!parse_real(w.data(), w.data() + w.size(), c)) fail("expected a vertex coordinate, found " + quote_token(w.data(), end));
        if (!std::isfinite(c))
          fail("vertex " + std::to_string(mesh.V.size() / 3 + 1) + " has a coordinate that is not a finite number (NaN or infinity)");
      }
      if (mesh.V.size() / 3 >= UINT32_MAX) fail("more vertices than 32-bit indices reach");
      mesh.V.insert(mesh.V.end(), xyz, xyz + 3);
    } else if (key == "f") {
      uint32_t v[4];
      int n = 0;
      const int64_t read = int64_t(mesh.V.size() / 3);
      for (std::string_view w; !(w = next_word(q, end)).empty(); ++n) {
        if (n == 4)
          fail("a face of 5 or more vertices, which MeshLab triangulates in a way this reader does not reproduce: "
               "triangulate the mesh first");
        const char* slash = static_cast<const char*>(std::memchr(w.data(), '/', w.size()));
        const char* ie = slash ? slash : w.data() + w.size();
        int64_t i;
        if (!parse_integer(w.data(), ie, i)) fail("expected a vertex index, found " + quote_token(w.data(), end));
        const int64_t at = i > 0 ? i - 1 : read + i;
        if (i == 0 || at < 0 || at >= read)
          fail("the face uses vertex " + std::to_string(i) + " but " + std::to_string(read) +
               " vertices are read so far (indices count from 1; negative ones back from the last)");
        v[n] = uint32_t(at);
      }
      if (n < 3) continue;  // vcg skips faces of fewer than 3 vertices
      mesh.F.insert(mesh.F.end(), {v[0], v[1], v[2]});
      if (n == 4) mesh.F.insert(mesh.F.end(), {v[0], v[2], v[3]});
    } else if (key == "q") {
      fail("a QOBJ quad ('q'), which this reader does not take");
    }
  }
  return mesh;
}

}  // namespace slicereuse::detail
