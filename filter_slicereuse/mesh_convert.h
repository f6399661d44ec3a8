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
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/complex.h>

#include "slicereuse/error.h"
#include "slicereuse/mesh.h"

namespace slicereuse::plugin {

template <class MeshT>
Mesh mesh_from_vcg(const MeshT& m) {
  constexpr uint32_t kDeleted = std::numeric_limits<uint32_t>::max();
  Mesh out;
  std::vector<uint32_t> index(m.vert.size(), kDeleted);
  out.V.reserve(3 * size_t(m.vn));
  uint32_t live = 0;
  for (size_t i = 0; i < m.vert.size(); ++i) {
    const auto& v = m.vert[i];
    if (v.IsD()) continue;
    index[i] = live++;
    out.V.push_back(double(v.cP()[0]));
    out.V.push_back(double(v.cP()[1]));
    out.V.push_back(double(v.cP()[2]));
  }
  out.F.reserve(3 * size_t(m.fn));
  for (size_t f = 0; f < m.face.size(); ++f) {
    const auto& face = m.face[f];
    if (face.IsD()) continue;
    for (int j = 0; j < 3; ++j) {
      const uint32_t i = index[size_t(face.cV(j) - &m.vert[0])];
      if (i == kDeleted)
        throw Error("mesh face " + std::to_string(f) + " uses a deleted vertex");
      out.F.push_back(i);
    }
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

template <class MeshT>
void fill_polyline_mesh(MeshT& m, const std::vector<double>& xyz, const std::vector<uint32_t>& segments) {
  using Coord = typename MeshT::CoordType;
  using Scalar = typename MeshT::ScalarType;
  const size_t n = xyz.size() / 3;
  if (n == 0) return;
  auto v = vcg::tri::Allocator<MeshT>::AddVertices(m, n);
  for (size_t i = 0; i < n; ++i, ++v)
    v->P() = Coord(Scalar(xyz[3 * i]), Scalar(xyz[3 * i + 1]), Scalar(xyz[3 * i + 2]));
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

}  // namespace slicereuse::plugin
