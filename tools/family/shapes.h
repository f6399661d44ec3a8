#pragma once
// Closed, consistently oriented (outward normals) test meshes with known sections, PLY I/O for
// them, and the checks the tests use to prove a mesh is a closed oriented 2-manifold.
// The mass-customization family generator built on these lives in family.h.
#include <cstdint>
#include <string>
#include <vector>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse::test {

// Axis-aligned box [x0,x1]x[y0,y1]x[z0,z1], each side split into n x n quads (2 triangles each),
// corners and edges shared: 6n^2+2 vertices, 12n^2 faces.
Mesh make_box(double x0, double y0, double z0, double x1, double y1, double z1, int n = 1);
// append_mesh: b's vertices and faces after a's (turned inside out when inverted: a cavity), as
// separate shells of one mesh.
void append_mesh(Mesh& a, const Mesh& b, bool inverted = false);
// Printability's test parts, both [x0,x1]x[y0,y1]x[z0,z1] with walls `wall` thick:
// make_hollow_box: a closed box around a sealed cavity (a second box turned inside out, so the
//   nonzero rule leaves it empty): a resin trap;
// make_cup: a floor and four walls (boxes overlapping at the corners, filled by the nonzero rule
//   as one), open at the top: a suction cup as it prints, mouth away from the plate.
Mesh make_hollow_box(double x0, double y0, double z0, double x1, double y1, double z1, double wall);
Mesh make_cup(double x0, double y0, double z0, double x1, double y1, double z1, double wall);
// UV sphere centred at the origin with `rings` latitude bands (rings >= 2) and `segments`
// longitudes (>= 3); the poles (0,0,+-radius) are single vertices: 2 + (rings-1)*segments
// vertices, 2*segments*(rings-1) faces.
Mesh make_sphere(double radius, int rings, int segments);
// Torus around the z axis centred at the origin: major radius R, minor radius r (r < R),
// major_segments*minor_segments vertices, twice as many faces.
Mesh make_torus(double R, double r, int major_segments, int minor_segments);

// Faces of a closed genus-0 grid whose vertices are numbered: pole 0, then rings-1 rings of
// `segments` vertices each (ring-major), then the other pole. Orientation follows the numbering;
// pass the mesh to orient_outward afterwards when unsure.
std::vector<uint32_t> pole_grid_faces(int rings, int segments);
// Faces of a closed genus-1 grid of rows x cols vertices (row-major), wrapping both ways.
std::vector<uint32_t> torus_grid_faces(int rows, int cols);

// Signed volume enclosed by a closed mesh (positive when its normals point outward).
double signed_volume(const Mesh& mesh);
// Reverses every face when the signed volume is negative.
void orient_outward(Mesh& mesh);

// Edge census of a mesh: `edges` undirected edges; `bad_edges` of them are not shared by exactly
// two faces traversing them in opposite directions (a closed oriented 2-manifold has none).
struct EdgeCensus {
  size_t edges = 0;
  size_t bad_edges = 0;
};
EdgeCensus edge_census(const Mesh& mesh);

// Binary little-endian PLY with vertex (double x,y,z) and face (uchar count, uint vertex_indices),
// written through AtomicFile; read_mesh_file (slicereuse/formats/mesh_file.h) reads it back bit
// for bit.
void write_ply(const std::string& path, const Mesh& mesh);

}  // namespace slicereuse::test
