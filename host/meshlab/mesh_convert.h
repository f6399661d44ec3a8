#pragma once
// Conversions between a vcg triangle mesh (MeshLab's CMeshO, float in 2020.09, double in
// 2025.07) and slicereuse::Mesh, used by host_adapter.h. Header-only and vcg-only, so it compiles
// against either generation's vcglib; include it after the host's MeshLab headers.
//
// mesh_from_vcg: live vertices and faces in storage order, deleted ones skipped and indices
//   compacted. Coordinates are taken as stored (cm.Tr is ignored, like most MeshLab filters).
//   Two members with the same faces therefore give the same F, whatever the scalar type.
// set_vertex_colors_vcg: colours the live vertices, in mesh_from_vcg's order, from rgba (4 bytes
//   per vertex); Error if the counts differ.
// fill_polyline_mesh: turns points xyz (3n) and segments (point index pairs) into an edge mesh.
// fill_point_mesh: points xyz (3n) with their normals (3n) as a mesh of vertices only.
// fill_triangle_mesh: a slicereuse::Mesh as a vcg mesh, with per-vertex normals for shading.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/complex.h>

#include "slicereuse/mesh/mesh.h"
#include "slicereuse/util/error.h"

namespace slicereuse::plugin {

// Live vertices are numbered 0, 1, ... in storage order; deleted ones map to kDeletedVertex.
constexpr uint32_t kDeletedVertex = std::numeric_limits<uint32_t>::max();

template <class MeshT>
std::vector<uint32_t> live_vertex_indices(const MeshT& m) {
  std::vector<uint32_t> index(m.vert.size(), kDeletedVertex);
  uint32_t live = 0;
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD()) index[i] = live++;
  return index;
}

// The live index of the vertex vp points at; throws Error naming the element (kind, number)
// that uses a deleted vertex.
template <class MeshT, class VertexPointer>
uint32_t live_index_of(const MeshT& m, const std::vector<uint32_t>& index, VertexPointer vp, const char* kind,
                       size_t number) {
  const uint32_t i = index[size_t(vp - &m.vert[0])];
  if (i == kDeletedVertex) throw Error(std::string(kind) + " " + std::to_string(number) + " uses a deleted vertex");
  return i;
}

template <class MeshT>
Mesh mesh_from_vcg(const MeshT& m) {
  Mesh out;
  const std::vector<uint32_t> index = live_vertex_indices(m);
  out.V.reserve(3 * size_t(m.vn));
  for (size_t i = 0; i < m.vert.size(); ++i) {
    if (index[i] == kDeletedVertex) continue;
    for (int a = 0; a < 3; ++a) out.V.push_back(double(m.vert[i].cP()[a]));
  }
  out.F.reserve(3 * size_t(m.fn));
  for (size_t f = 0; f < m.face.size(); ++f) {
    const auto& face = m.face[f];
    if (face.IsD()) continue;
    for (int j = 0; j < 3; ++j)
      out.F.push_back(live_index_of(m, index, face.cV(j), "mesh face", f));
  }
  return out;
}

template <class MeshT>
void set_vertex_colors_vcg(MeshT& m, const std::vector<uint8_t>& rgba) {
  if (rgba.size() != 4 * size_t(m.vn))
    throw Error("internal error: " + std::to_string(rgba.size() / 4) + " vertex colours for " +
                std::to_string(m.vn) + " vertices");
  size_t i = 0;
  for (auto& v : m.vert)
    if (!v.IsD()) {
      v.C() = vcg::Color4b(rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]);
      i += 4;
    }
}

// Appends the points of xyz (3 numbers each) as vertices of m; returns the first of them.
template <class MeshT>
typename MeshT::VertexIterator append_vertices(MeshT& m, const std::vector<double>& xyz) {
  using Coord = typename MeshT::CoordType;
  using Scalar = typename MeshT::ScalarType;
  const size_t n = xyz.size() / 3;
  const auto first = vcg::tri::Allocator<MeshT>::AddVertices(m, n);
  auto v = first;
  for (size_t i = 0; i < n; ++i, ++v)
    v->P() = Coord(Scalar(xyz[3 * i]), Scalar(xyz[3 * i + 1]), Scalar(xyz[3 * i + 2]));
  return first;
}

template <class MeshT>
void fill_polyline_mesh(MeshT& m, const std::vector<double>& xyz, const std::vector<uint32_t>& segments) {
  const size_t n = xyz.size() / 3;
  if (n == 0) return;
  append_vertices(m, xyz);
  if (!segments.empty()) {
    auto e = vcg::tri::Allocator<MeshT>::AddEdges(m, segments.size() / 2);
    const size_t first = m.vert.size() - n;
    for (size_t s = 0; s + 1 < segments.size(); s += 2, ++e) {
      e->V(0) = &m.vert[first + segments[s]];
      e->V(1) = &m.vert[first + segments[s + 1]];
    }
  }
  vcg::tri::UpdateBounding<MeshT>::Box(m);
}

template <class MeshT>
void fill_point_mesh(MeshT& m, const std::vector<double>& xyz, const std::vector<double>& normals) {
  using Coord = typename MeshT::CoordType;
  using Scalar = typename MeshT::ScalarType;
  const size_t n = xyz.size() / 3;
  if (n == 0) return;
  auto v = append_vertices(m, xyz);
  for (size_t i = 0; i < n; ++i, ++v)
    v->N() = Coord(Scalar(normals[3 * i]), Scalar(normals[3 * i + 1]), Scalar(normals[3 * i + 2]));
  vcg::tri::UpdateBounding<MeshT>::Box(m);
}

template <class MeshT>
void fill_triangle_mesh(MeshT& m, const Mesh& mesh) {
  if (mesh.vertices() == 0) return;
  append_vertices(m, mesh.V);
  if (mesh.faces() > 0) {
    auto f = vcg::tri::Allocator<MeshT>::AddFaces(m, mesh.faces());
    for (size_t i = 0; i < mesh.faces(); ++i, ++f)
      for (int j = 0; j < 3; ++j) f->V(j) = &m.vert[mesh.F[3 * i + size_t(j)]];
  }
  vcg::tri::UpdateNormal<MeshT>::PerVertexNormalizedPerFace(m);
  vcg::tri::UpdateBounding<MeshT>::Box(m);
}

}  // namespace slicereuse::plugin
