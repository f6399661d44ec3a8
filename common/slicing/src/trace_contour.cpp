#include "slicereuse/slicing/trace_contour.h"

#include "slicereuse/mesh/edge_links.h"
#include "slicereuse/slicing/edge_point.h"

namespace slicereuse {

uint32_t exit_edge(const Mesh& mesh, uint32_t f, double zk) {
  const uint32_t* c = &mesh.F[3 * size_t(f)];
  const bool below[3] = {mesh.V[3 * size_t(c[0]) + 2] < zk, mesh.V[3 * size_t(c[1]) + 2] < zk,
                         mesh.V[3 * size_t(c[2]) + 2] < zk};
  for (uint32_t j = 0; j < 3; ++j)
    if (below[j] && !below[(j + 1) % 3]) return j;
  return kNoEdge;
}

bool trace_contour(const Mesh& mesh, const std::vector<uint32_t>& links, double zk, uint32_t seed,
                   uint32_t stamp_value, uint32_t* stamp, ContourSink& sink) {
  const double* V = mesh.V.data();
  const uint32_t* F = mesh.F.data();
  const size_t first = sink.cursor;
  uint32_t f = seed, j = exit_edge(mesh, seed, zk);
  if (j == kNoEdge) return false;
  for (;;) {
    if (stamp[f] == stamp_value || sink.cursor == sink.end) return false;
    stamp[f] = stamp_value;
    const uint32_t* c = F + 3 * size_t(f);
    const EdgePoint p = edge_point(V + 3 * size_t(c[j]), V + 3 * size_t(c[(j + 1) % 3]), zk);
    const size_t i = sink.cursor++;
    sink.xyz[3 * i] = p.x;
    sink.xyz[3 * i + 1] = p.y;
    sink.xyz[3 * i + 2] = zk;
    if (sink.face) {
      sink.face[i] = f;
      sink.edge[i] = uint8_t(j);
      sink.t[i] = p.t;
    }
    const uint32_t link = links[3 * size_t(f) + j];
    if (link == kUnlinked) return false;
    f = link >> 2;
    if (f == seed) break;
    // f is entered by its edge sg, from corner sg (at or above) to sg+1 (below), as the slicer
    // walks: the third corner alone decides the exit.
    const uint32_t sg = link & 3, third = (sg + 2) % 3;
    j = V[3 * size_t(F[3 * size_t(f) + third]) + 2] >= zk ? (sg + 1) % 3 : third;
  }
  sink.lengths.push_back(sink.cursor - first);
  return true;
}

}  // namespace slicereuse
