#include "slicereuse/formats/contour_mesh.h"

#include <xxhash.h>

#include <limits>
#include <string>

#include "area_coordinates.h"
#include "slicereuse/util/error.h"

namespace slicereuse {
namespace {

std::string num(uint64_t v) { return std::to_string(v); }

}  // namespace

ContourMesh contour_mesh_from_slices(const Slices& s) {
  validate_slices(s);
  if (!s.has_points()) throw Error("the slices carry no contour points (xyz)");
  const size_t P = s.points(), C = s.contours();
  if (P >= std::numeric_limits<uint32_t>::max() || C >= std::numeric_limits<uint32_t>::max())
    throw Error(num(P) + " points in " + num(C) + " contours are more than a mesh can index");
  ContourMesh m;
  m.thickness = s.thickness;
  m.z_start = s.z_start;
  m.layer_z = s.layer_z;
  m.position.assign(s.xyz.begin(), s.xyz.end());
  m.layer.resize(P);
  m.contour.resize(P);
  m.edges.resize(2 * (P - s.open_contours()));
  size_t e = 0;
  for (size_t k = 0; k < s.layers(); ++k)
    for (uint64_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c) {
      const uint64_t b = s.contour_begin[c], end = s.contour_begin[c + 1];
      for (uint64_t p = b; p < end; ++p) {
        m.layer[p] = uint32_t(k);
        m.contour[p] = uint32_t(c);
        if (p + 1 < end) {
          m.edges[e++] = uint32_t(p);
          m.edges[e++] = uint32_t(p + 1);
        }
      }
      if (!s.contour_open[c]) {
        m.edges[e++] = uint32_t(end - 1);
        m.edges[e++] = uint32_t(b);
      }
    }
  if (s.has_encoding()) {
    m.fingerprint = s.fingerprint;
    m.face.assign(s.face.begin(), s.face.end());
    m.area.resize(3 * P);
    for (size_t p = 0; p < P; ++p) encode_area_coordinates(s.edge[p], s.t[p], &m.area[3 * p]);
  }
  return m;
}

Slices slices_from_contour_mesh(const ContourMesh& m) {
  const size_t V = m.vertices(), L = m.layer_z.size();
  if (m.position.size() != 3 * V || m.contour.size() != V)
    throw Error("the contour layer's per-vertex arrays disagree in size");
  if (m.has_encoding() && (m.face.size() != V || m.area.size() != 3 * V))
    throw Error("the contour layer's encoding arrays disagree in size");
  if (m.edges.size() % 2) throw Error("the contour layer's edge array has an odd length");

  Slices s;
  s.thickness = m.thickness;
  s.z_start = m.z_start;
  s.layer_z = m.layer_z;
  s.layer_begin.assign(L + 1, 0);
  s.contour_begin.push_back(0);
  // Contours are runs of equal contour index; their layers must not decrease.
  std::vector<uint32_t> local(V);  // vertex -> its position within its contour
  for (size_t v = 0; v < V; ++v) {
    if (m.layer[v] >= L)
      throw Error("vertex " + num(v) + " is in layer " + num(m.layer[v]) + " but there are only " +
                  num(L) + " layers");
    const bool starts = v == 0 || m.contour[v] != m.contour[v - 1];
    if (starts) {
      if (v > 0 && m.contour[v] < m.contour[v - 1])
        throw Error("vertex " + num(v) + ": contour indices decrease (" + num(m.contour[v - 1]) +
                    " then " + num(m.contour[v]) + "): the vertices are not in contour order");
      if (v > 0 && m.layer[v] < m.layer[v - 1])
        throw Error("vertex " + num(v) + ": contour " + num(m.contour[v]) + " is in layer " +
                    num(m.layer[v]) + ", below the previous contour's layer " + num(m.layer[v - 1]));
      if (v > 0) s.contour_begin.push_back(v);
      ++s.layer_begin[m.layer[v] + 1];
    } else if (m.layer[v] != m.layer[v - 1]) {
      throw Error("vertex " + num(v) + ": contour " + num(m.contour[v]) + " spans layers " +
                  num(m.layer[v - 1]) + " and " + num(m.layer[v]));
    }
    local[v] = starts ? 0 : local[v - 1] + 1;
  }
  if (V > 0) s.contour_begin.push_back(V);
  for (size_t k = 0; k < L; ++k) s.layer_begin[k + 1] += s.layer_begin[k];
  const size_t C = s.contour_begin.size() - 1;

  // Edges: each consecutive pair of a contour exactly once, plus at most one closing edge.
  std::vector<uint8_t> linked(V, 0);  // vertex -> edge to the next vertex seen
  std::vector<uint8_t> closing(C, 0);
  std::vector<uint32_t> contour_of(V);
  for (size_t c = 0; c < C; ++c)
    for (uint64_t v = s.contour_begin[c]; v < s.contour_begin[c + 1]; ++v) contour_of[v] = uint32_t(c);
  for (size_t e = 0; e < m.edges.size(); e += 2) {
    uint32_t a = m.edges[e], b = m.edges[e + 1];
    if (a >= V || b >= V)
      throw Error("edge " + num(e / 2) + " names vertex " + num(a >= V ? a : b) + " of " + num(V));
    if (contour_of[a] != contour_of[b])
      throw Error("edge " + num(e / 2) + " joins vertices " + num(a) + " and " + num(b) +
                  " of different contours");
    if (local[a] > local[b]) std::swap(a, b);
    const size_t c = contour_of[a];
    const uint64_t n = s.contour_begin[c + 1] - s.contour_begin[c];
    if (local[b] == local[a] + 1 && !linked[a]) {
      linked[a] = 1;
    } else if (local[a] == 0 && local[b] == n - 1 && !closing[c]) {
      closing[c] = 1;
    } else {
      throw Error("edge " + num(e / 2) + " (vertices " + num(a) + ", " + num(b) +
                  ") is not a segment of contour " + num(c) + " between consecutive points");
    }
  }
  s.contour_open.resize(C);
  for (size_t c = 0; c < C; ++c) {
    for (uint64_t v = s.contour_begin[c]; v + 1 < s.contour_begin[c + 1]; ++v)
      if (!linked[v])
        throw Error("contour " + num(c) + " is broken: no edge between vertices " + num(v) +
                    " and " + num(v + 1));
    s.contour_open[c] = !closing[c];
  }
  s.xyz.assign(m.position.begin(), m.position.end());
  if (m.has_encoding()) {
    s.fingerprint = m.fingerprint;
    s.face.assign(m.face.begin(), m.face.end());
    s.edge.resize(V);
    s.t.resize(V);
    for (size_t v = 0; v < V; ++v)
      if (const char* why = decode_area_coordinates(&m.area[3 * v], s.edge[v], s.t[v]))
        throw Error("vertex " + num(v) + ": " + why);
  }
  validate_slices(s);
  return s;
}

uint64_t contour_mesh_hash(const ContourMesh& m) {
  XXH3_state_t* state = XXH3_createState();
  if (!state) throw Error("out of memory");
  XXH3_64bits_reset(state);
  auto add = [&](const void* data, size_t bytes) {
    XXH3_64bits_update(state, &bytes, sizeof bytes);
    if (bytes) XXH3_64bits_update(state, data, bytes);
  };
  auto array = [&](const auto& a) { add(a.data(), a.size() * sizeof a[0]); };
  add(&m.thickness, sizeof m.thickness);
  add(&m.z_start, sizeof m.z_start);
  add(&m.fingerprint.faces, sizeof m.fingerprint.faces);
  add(&m.fingerprint.hash, sizeof m.fingerprint.hash);
  array(m.layer_z);
  array(m.position);
  array(m.layer);
  array(m.contour);
  array(m.face);
  array(m.area);
  array(m.edges);
  const uint64_t h = XXH3_64bits_digest(state);
  XXH3_freeState(state);
  return h;
}

}  // namespace slicereuse
