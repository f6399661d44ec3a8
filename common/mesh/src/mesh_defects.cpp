#include "slicereuse/mesh/mesh_defects.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "slicereuse/mesh/mesh_topology.h"
#include "slicereuse/mesh/vec3.h"
#include "slicereuse/util/format.h"

namespace slicereuse {
namespace {

// Counts one more offender and keeps the lowest index as the one to name.
void count(uint64_t& n, uint64_t& first, uint64_t index) {
  ++n;
  first = std::min(first, index);
}

}  // namespace

MeshDefects find_mesh_defects(const Mesh& mesh) {
  MeshDefects d;
  const double* V = mesh.V.data();
  const uint32_t* F = mesh.F.data();
  for (size_t v = 0; v < mesh.vertices(); ++v)
    if (!std::isfinite(V[3 * v]) || !std::isfinite(V[3 * v + 1]) || !std::isfinite(V[3 * v + 2]))
      count(d.non_finite_vertices, d.first_non_finite_vertex, v);

  // Sorted corner triples find duplicates.
  std::vector<std::pair<std::array<uint32_t, 3>, uint32_t>> faces;
  faces.reserve(mesh.faces());
  for (uint32_t f = 0; f < mesh.faces(); ++f) {
    std::array<uint32_t, 3> c{F[3 * f], F[3 * f + 1], F[3 * f + 2]};
    std::sort(c.begin(), c.end());
    if (c[0] == c[1] || c[1] == c[2]) {
      count(d.repeated_vertex_faces, d.first_repeated_vertex_face, f);
      continue;
    }
    faces.emplace_back(c, f);
    const double* a = V + 3 * size_t(c[0]);
    const double* b = V + 3 * size_t(c[1]);
    const double* e = V + 3 * size_t(c[2]);
    const Vec3 n = cross(sub(b, a), sub(e, a));
    if (n[0] == 0 && n[1] == 0 && n[2] == 0) count(d.zero_area_faces, d.first_zero_area_face, f);
  }
  std::sort(faces.begin(), faces.end());
  for (size_t i = 1; i < faces.size(); ++i)
    if (faces[i].first == faces[i - 1].first) count(d.duplicate_faces, d.first_duplicate_face, faces[i].second);

  const MeshTopology t = mesh_topology(mesh);
  d.boundary_edges = t.boundary_edges;
  d.non_manifold_edges = t.nonmanifold_edges;
  return d;
}

std::string describe_mesh_defects(const MeshDefects& d) {
  std::string s;
  auto add = [&](const std::string& part) { s += (s.empty() ? "" : "; ") + part; };
  if (d.non_finite_vertices)
    add(format("%llu vertices with NaN or infinite coordinates (first: vertex %llu)",
               (unsigned long long)d.non_finite_vertices, (unsigned long long)d.first_non_finite_vertex));
  if (d.repeated_vertex_faces)
    add(format("%llu faces that name one vertex twice (first: face %llu)",
               (unsigned long long)d.repeated_vertex_faces, (unsigned long long)d.first_repeated_vertex_face));
  if (d.zero_area_faces)
    add(format("%llu zero-area faces (first: face %llu)", (unsigned long long)d.zero_area_faces,
               (unsigned long long)d.first_zero_area_face));
  if (d.duplicate_faces)
    add(format("%llu duplicated faces (first: face %llu)", (unsigned long long)d.duplicate_faces,
               (unsigned long long)d.first_duplicate_face));
  if (d.boundary_edges) add(format("%llu boundary edges (holes)", (unsigned long long)d.boundary_edges));
  if (d.non_manifold_edges)
    add(format("%llu non-manifold edges (shared by 3 or more faces)", (unsigned long long)d.non_manifold_edges));
  return s;
}

}  // namespace slicereuse
