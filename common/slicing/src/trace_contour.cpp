#include "slicereuse/slicing/trace_contour.h"

#include "slicereuse/mesh/edge_links.h"
#include "slicereuse/slicing/contour_step.h"

namespace slicereuse {

bool trace_contour(const Mesh& mesh, const std::vector<uint32_t>& links, double zk, uint32_t seed,
                   uint32_t stamp_value, uint32_t* stamp, ContourSink& sink) {
  const double* V = mesh.V.data();
  const uint32_t* F = mesh.F.data();
  const size_t first = sink.cursor;
  uint32_t f = seed, j = section_edges(V, F, seed, zk).exit;
  if (j == kNoEdge) return false;
  for (;;) {
    if (stamp[f] == stamp_value || sink.cursor == sink.end) return false;
    stamp[f] = stamp_value;
    const EdgePoint p = exit_point(V, F, f, j, zk);
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
    j = next_exit_edge(V, F, f, link & 3, zk);
  }
  sink.lengths.push_back(sink.cursor - first);
  return true;
}

}  // namespace slicereuse
