#pragma once
// Contour layers: a MeshLab mesh (vcg, CMeshO of either generation) holding slices as an edge
// mesh, for the io_encoding plugin (open/save) and for filters that take the current layer as
// their contours (Host::current_contour_layer). Header-only and vcg-only, like mesh_convert.h;
// the conversion itself is the core's contour_mesh.h.
//
// A contour layer has (docs/formats.md, "Contour layers in MeshLab"):
//   vertices   the contour points, in order; edges join consecutive points, closed loops also
//              the last to the first (a one-point loop: the edge (v, v));
//   per vertex Scalarm attributes "layer" and "contour" (0-based indices), and with an
//              encoding "face" (face id) and the Point3m attribute "area_coordinates";
//   per mesh   ContourLayerInfo "slicereuse_contour_layer": thickness, z_start, every layer's z
//              (layers without contours have no vertex), fingerprint, and the hash of the layer
//              as filled.
// Scalarm is float in MeshLab 2020.09: coordinates and area coordinates are rounded there, so
// the layer also keeps the slices it was opened from and gives them back unchanged as long as
// the layer's hash is unchanged (an exact round trip); an edited layer is read from its
// vertices and attributes. Indices must stay below 2^24 to be exact in a float attribute.
#include <cmath>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/complex.h>

#include "mesh_convert.h"
#include "slicereuse/formats/contour_mesh.h"
#include "slicereuse/util/error.h"

namespace slicereuse::plugin {

inline const char* const kLayerAttribute = "layer";
inline const char* const kContourAttribute = "contour";
inline const char* const kFaceAttribute = "face";
inline const char* const kAreaAttribute = "area_coordinates";
inline const char* const kInfoAttribute = "slicereuse_contour_layer";

struct ContourLayerInfo {
  double thickness = 0;
  double z_start = 0;
  std::vector<double> layer_z;
  Fingerprint fingerprint;
  uint64_t hash = 0;                    // contour_mesh_hash of the layer as filled
  std::shared_ptr<const Slices> exact;  // float builds only: the slices as opened
};

namespace detail {

template <class MeshT>
using ScalarAttribute = typename MeshT::template PerVertexAttributeHandle<typename MeshT::ScalarType>;
template <class MeshT>
using PointAttribute = typename MeshT::template PerVertexAttributeHandle<typename MeshT::CoordType>;

// Index attribute values must be whole numbers a uint32 holds.
inline uint32_t index_value(double v, const char* name, size_t vertex) {
  if (!(v >= 0 && v < 4294967296.0) || v != std::floor(v))
    throw Error("vertex " + std::to_string(vertex) + ": attribute '" + name + "' is " +
                std::to_string(v) + ", not an index");
  return uint32_t(v);
}

}  // namespace detail

// The contour layer of m as plain arrays (live vertices and edges, compacted); throws Error when
// m is not a contour layer.
template <class MeshT>
ContourMesh contour_mesh_from_vcg(MeshT& m) {
  using Alloc = vcg::tri::Allocator<MeshT>;
  auto info = Alloc::template FindPerMeshAttribute<ContourLayerInfo>(m, kInfoAttribute);
  auto layer = Alloc::template FindPerVertexAttribute<typename MeshT::ScalarType>(m, kLayerAttribute);
  auto contour = Alloc::template FindPerVertexAttribute<typename MeshT::ScalarType>(m, kContourAttribute);
  if (!Alloc::IsValidHandle(m, info) || !Alloc::IsValidHandle(m, layer) || !Alloc::IsValidHandle(m, contour))
    throw Error("the layer is not a contour layer (it lacks the per-vertex 'layer' and "
                "'contour' attributes or the layer table): open a .ctr, .srb or .cli file");
  const ContourLayerInfo& in = info();
  auto face = Alloc::template FindPerVertexAttribute<typename MeshT::ScalarType>(m, kFaceAttribute);
  auto area = Alloc::template FindPerVertexAttribute<typename MeshT::CoordType>(m, kAreaAttribute);
  const bool encoded = in.fingerprint.faces > 0 && Alloc::IsValidHandle(m, face) && Alloc::IsValidHandle(m, area);

  ContourMesh out;
  out.thickness = in.thickness;
  out.z_start = in.z_start;
  out.layer_z = in.layer_z;
  const size_t V = size_t(m.vn);
  out.position.resize(3 * V);
  out.layer.resize(V);
  out.contour.resize(V);
  if (encoded) {
    out.fingerprint = in.fingerprint;
    out.face.resize(V);
    out.area.resize(3 * V);
  }
  const std::vector<uint32_t> index = live_vertex_indices(m);
  for (size_t i = 0; i < m.vert.size(); ++i) {
    const size_t v = index[i];
    if (v == kDeletedVertex) continue;
    for (int a = 0; a < 3; ++a) out.position[3 * v + a] = double(m.vert[i].cP()[a]);
    out.layer[v] = detail::index_value(double(layer[i]), kLayerAttribute, v);
    out.contour[v] = detail::index_value(double(contour[i]), kContourAttribute, v);
    if (encoded) {
      out.face[v] = detail::index_value(double(face[i]), kFaceAttribute, v);
      for (int a = 0; a < 3; ++a) out.area[3 * v + a] = double(area[i][a]);
    }
  }
  out.edges.reserve(2 * size_t(m.en));
  for (size_t e = 0; e < m.edge.size(); ++e) {
    if (m.edge[e].IsD()) continue;
    for (int j = 0; j < 2; ++j)
      out.edges.push_back(live_index_of(m, index, m.edge[e].cV(j), "edge", e));
  }
  return out;
}

// Replaces m's content by the slices s (with xyz; the encoding when s has one). s is consumed:
// float builds keep it as the exact copy, double builds free it early.
template <class MeshT>
void fill_contour_layer(MeshT& m, Slices&& s) {
  using Alloc = vcg::tri::Allocator<MeshT>;
  using Scalar = typename MeshT::ScalarType;
  using Coord = typename MeshT::CoordType;
  if constexpr (!std::is_same_v<Scalar, double>) {
    // A float attribute holds whole numbers exactly only below 2^24.
    const uint64_t limit = uint64_t(1) << 24;
    if (s.contours() >= limit || s.layers() >= limit || (s.has_encoding() && s.fingerprint.faces > limit))
      throw Error("too many layers, contours or faces for this MeshLab's float attributes (at most "
                  "16777216 each); use the 2025 generation (pymeshlab)");
  }
  ContourMesh cm = contour_mesh_from_slices(s);
  // Round to what the layer stores, so that the hash below is the hash contour_mesh_from_vcg
  // gives for the filled layer (same vertices and edges, in the same order), without reading
  // the layer back.
  for (double& v : cm.position) v = double(Scalar(v));
  for (double& v : cm.area) v = double(Scalar(v));
  ContourLayerInfo info_value;
  info_value.thickness = s.thickness;
  info_value.z_start = s.z_start;
  info_value.layer_z = s.layer_z;
  if (s.has_encoding()) info_value.fingerprint = s.fingerprint;
  info_value.hash = contour_mesh_hash(cm);
  // Float builds keep s as the exact copy; double builds need it no longer (free it before the
  // layer takes its memory).
  if constexpr (!std::is_same_v<Scalar, double>)
    info_value.exact = std::make_shared<const Slices>(std::move(s));
  else
    s = Slices();

  const size_t V = cm.vertices();
  m.Clear();
  auto layer = Alloc::template GetPerVertexAttribute<Scalar>(m, kLayerAttribute);
  auto contour = Alloc::template GetPerVertexAttribute<Scalar>(m, kContourAttribute);
  if (V) {
    Alloc::AddVertices(m, V);  // m is empty: vertex v is m.vert[v]
    for (size_t v = 0; v < V; ++v) {
      m.vert[v].P() = Coord(Scalar(cm.position[3 * v]), Scalar(cm.position[3 * v + 1]), Scalar(cm.position[3 * v + 2]));
      layer[v] = Scalar(cm.layer[v]);
      contour[v] = Scalar(cm.contour[v]);
    }
  }
  if (cm.has_encoding()) {
    auto face = Alloc::template GetPerVertexAttribute<Scalar>(m, kFaceAttribute);
    auto area = Alloc::template GetPerVertexAttribute<Coord>(m, kAreaAttribute);
    for (size_t v = 0; v < V; ++v) {
      face[v] = Scalar(cm.face[v]);
      area[v] = Coord(Scalar(cm.area[3 * v]), Scalar(cm.area[3 * v + 1]), Scalar(cm.area[3 * v + 2]));
    }
  }
  if (!cm.edges.empty()) {
    auto ei = Alloc::AddEdges(m, cm.edges.size() / 2);
    for (size_t e = 0; e < cm.edges.size(); e += 2, ++ei) {
      ei->V(0) = &m.vert[cm.edges[e]];
      ei->V(1) = &m.vert[cm.edges[e + 1]];
    }
  }
  vcg::tri::UpdateBounding<MeshT>::Box(m);
  auto info = Alloc::template GetPerMeshAttribute<ContourLayerInfo>(m, kInfoAttribute);
  info() = std::move(info_value);
}

// The slices a contour layer holds: exactly what was opened while the layer is unchanged (float
// builds), else read from its vertices, edges and attributes. Throws Error naming the problem.
template <class MeshT>
Slices slices_of_contour_layer(MeshT& m) {
  const ContourMesh cm = contour_mesh_from_vcg(m);
  auto info = vcg::tri::Allocator<MeshT>::template FindPerMeshAttribute<ContourLayerInfo>(m, kInfoAttribute);
  const ContourLayerInfo& in = info();
  if (in.exact && contour_mesh_hash(cm) == in.hash) return *in.exact;
  return slices_from_contour_mesh(cm);
}

}  // namespace slicereuse::plugin
