#include "slicereuse/trace_contour.h"

#include "slicereuse/edge_links.h"
#include "slicereuse/edge_point.h"

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
                   uint32_t stamp_value, uint32_t* stamp, size_t max_points, TracedContours& out) {
  const size_t first_point = out.points();
  uint32_t f = seed;
  for (;;) {
    const uint32_t j = exit_edge(mesh, f, zk);
    if (j == kNoEdge || stamp[f] == stamp_value || out.points() >= max_points) return false;
    stamp[f] = stamp_value;
    const uint32_t* c = &mesh.F[3 * size_t(f)];
    const EdgePoint p = edge_point(&mesh.V[3 * size_t(c[j])], &mesh.V[3 * size_t(c[(j + 1) % 3])], zk);
    out.xyz.insert(out.xyz.end(), {p.x, p.y, zk});
    out.face.push_back(f);
    out.edge.push_back(uint8_t(j));
    out.t.push_back(p.t);
    const uint32_t link = links[3 * size_t(f) + j];
    if (link == kUnlinked) return false;
    f = link >> 2;
    if (f == seed) break;
  }
  out.lengths.push_back(out.points() - first_point);
  return true;
}

}  // namespace slicereuse
