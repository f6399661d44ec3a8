#pragma once
// read_mesh_file: the triangle mesh in the file at path, as the Mesh MeshLab's loader
// (pymeshlab load_new_mesh) makes of it: the same vertices in the same order, the same faces in
// the same order, the same values (docs/formats.md, "Member mesh files"). The format is chosen
// by the extension, in any case: .stl (binary or ASCII), .ply (ascii, binary_little_endian,
// binary_big_endian), .obj.
//   STL: binary when the size is exactly 84 + 50 * (the u32 facet count at byte 80), or when one
//     of the 1000 bytes after byte 84 is above 127 (then the size may differ from that by at most
//     5%, and the file must hold every facet); else ASCII: a first line, then facets
//     "facet normal a b c outer loop vertex x y z (3 times) endloop endfacet", any number of
//     "endsolid ..." / "solid ..." lines between them. Coordinates are floats (ASCII: read as
//     strtof reads them). Vertices equal as floats (-0.0 equals +0.0) are one vertex: the first
//     in file order, kept at the place of its first occurrence.
//   PLY: the header's elements in order; vertex x, y, z of any numeric type (float to double
//     exactly, ASCII float text read as a float), face "vertex_indices" or "vertex_index" lists
//     (any integer count and index types); every other property and element is stepped over.
//     A face of n > 3 vertices becomes the fan (v0,v1,v2), (v0,v2,v3), ...
//   OBJ: "v x y z" (read as doubles, as atof reads them), "f" with "i", "i/t", "i//n", "i/t/n"
//     (a negative i counts back from the last vertex read so far); a face of 4 vertices becomes
//     (0,1,2), (0,2,3), one of fewer than 3 is skipped; every other line is ignored.
//   Every format: faces that use a vertex twice are dropped; every vertex is kept, used or not,
//   in file order.
// Throws Error naming the file, the problem and where it is (line, face, vertex, byte, sizes):
// an unknown extension, a missing or unreadable file, a malformed or truncated file, a count
// larger than the file can hold, a face index out of range, a non-finite coordinate (MeshLab
// would drop that vertex), an OBJ face of 5 or more vertices (MeshLab triangulates it with GLU,
// which this reader does not reproduce: triangulate such files first), a file without faces.
//
// is_mesh_file_name: whether read_mesh_file takes path's extension (.stl, .ply, .obj, any case).
#include <string>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

Mesh read_mesh_file(const std::string& path);

bool is_mesh_file_name(const std::string& path);

}  // namespace slicereuse
