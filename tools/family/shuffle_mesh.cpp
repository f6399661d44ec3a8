#include "shuffle_mesh.h"

#include <algorithm>
#include <numeric>
#include <random>

#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/util/error.h"

namespace slicereuse::test {
namespace {

// Fisher-Yates over mt19937_64, whose output the standard fixes (std::shuffle's is not).
std::vector<uint32_t> permutation(size_t n, std::mt19937_64& rng) {
  std::vector<uint32_t> p(n);
  std::iota(p.begin(), p.end(), 0u);
  for (size_t i = n; i > 1; --i) std::swap(p[i - 1], p[rng() % i]);
  return p;
}

}  // namespace

ShuffledMesh shuffle_mesh(const Mesh& mesh, uint64_t seed) {
  std::mt19937_64 rng(seed);
  const size_t nv = mesh.vertices(), nf = mesh.faces();
  ShuffledMesh s;
  s.new_index = permutation(nv, rng);
  s.new_face = permutation(nf, rng);
  s.corner_shift.resize(nf);
  s.mesh.V.resize(mesh.V.size());
  s.mesh.F.resize(mesh.F.size());
  for (size_t i = 0; i < nv; ++i)
    for (int d = 0; d < 3; ++d) s.mesh.V[3 * size_t(s.new_index[i]) + d] = mesh.V[3 * i + d];
  for (size_t f = 0; f < nf; ++f) {
    s.corner_shift[f] = uint8_t(rng() % 3);
    for (size_t j = 0; j < 3; ++j)
      s.mesh.F[3 * size_t(s.new_face[f]) + (j + s.corner_shift[f]) % 3] = s.new_index[mesh.F[3 * f + j]];
  }
  return s;
}

SurfaceMap map_onto_shuffled(const Mesh& source, const ShuffledMesh& shuffled) {
  const size_t nv = source.vertices(), nf = source.faces();
  if (shuffled.new_index.size() != nv || shuffled.new_face.size() != nf)
    throw Error("map_onto_shuffled: the source is not the shuffled mesh's family");
  SurfaceMap m;
  m.face.resize(nv);
  m.bary.assign(3 * nv, 0);
  for (size_t f = 0; f < nf; ++f)
    for (size_t j = 0; j < 3; ++j) {
      const uint32_t v = source.F[3 * f + j];
      m.face[v] = shuffled.new_face[f];
      std::fill_n(&m.bary[3 * size_t(v)], 3, 0.0);
      m.bary[3 * size_t(v) + (j + shuffled.corner_shift[f]) % 3] = 1;
    }
  m.source = mesh_fingerprint(source);
  m.target = mesh_fingerprint(shuffled.mesh);
  m.source_vertices = nv;
  m.target_vertices = nv;
  m.source_faces = source.F;
  return m;
}

}  // namespace slicereuse::test
