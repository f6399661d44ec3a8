#include "support_points_for_areas.h"

#include <algorithm>
#include <cmath>

#include "cover_layer.h"
#include "part_columns.h"
#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/mesh/vec3.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/parallel_blocks.h"
#include "support_force.h"

namespace slicereuse {
namespace {

struct LayerPoints {
  std::vector<uint32_t> face;
  std::vector<double> bary;
  std::vector<uint8_t> kind;
};

// Whether mesh's face f faces up (faces_up, support_points.h).
bool face_faces_up(const Mesh& m, uint32_t f) {
  const uint32_t* c = &m.F[3 * size_t(f)];
  const Vec3 n = cross(sub(&m.V[3 * size_t(c[1])], &m.V[3 * size_t(c[0])]), sub(&m.V[3 * size_t(c[2])], &m.V[3 * size_t(c[0])]));
  return normal_faces_up(n[2] / norm(n));
}

// The contour point of layer k nearest to (x, y) on a face that does not face up (of all, when
// every one does), as face and area coordinates.
void nearest_contour_point(const Mesh& m, const Slices& s, size_t k, double x, double y, uint32_t& face,
                           double bary[3]) {
  size_t best = s.contour_begin[s.layer_begin[k]];
  double best_d2 = INFINITY;
  bool best_up = true;
  for (size_t p = best; p < s.contour_begin[s.layer_begin[k + 1]]; ++p) {
    const double d2 = (s.xyz[3 * p] - x) * (s.xyz[3 * p] - x) + (s.xyz[3 * p + 1] - y) * (s.xyz[3 * p + 1] - y);
    const bool up = face_faces_up(m, s.face[p]);
    if ((best_up && !up) || (up == best_up && d2 < best_d2)) best_d2 = d2, best = p, best_up = up;
  }
  face = s.face[best];
  const int j = s.edge[best];
  bary[j] = 1 - s.t[best];
  bary[(j + 1) % 3] = s.t[best];
  bary[(j + 2) % 3] = 0;
}

// Where a vertical ray from below at (x, y) meets a downward-facing face first: the lowest hit
// between the planes of layers k-1 and k (inner), else the lowest in the layer's span; ties go
// to the lower face id.
bool ray_hit(const PartColumns& down, double x, double y, const LayerSpan& span, const LayerSpan& inner,
             uint32_t& face, double bary[3]) {
  bool found = false, found_inner = false;
  double best_z = 0;
  down.for_each_hit(x, y, [&](uint32_t f, const double* l, double z) {
    if (z < span.lo || z > span.hi) return;
    const bool in_inner = z > inner.lo && z <= inner.hi;
    if (found && (found_inner > in_inner || (found_inner == in_inner && !(z < best_z)))) return;
    found = true, found_inner = in_inner, best_z = z, face = f;
    for (int j = 0; j < 3; ++j) bary[j] = l[j];
  });
  return found;
}

}  // namespace

SupportPoints support_points_for_areas(const Mesh& mesh, const Slices& slicing, const std::vector<LayerAreas>& areas,
                                       const SupportPointOptions& options, const SupportPoints* existing,
                                       const Progress& progress) {
  const size_t n = slicing.layers();
  const Fingerprint fp = mesh_fingerprint(mesh);
  std::vector<std::vector<std::array<double, 2>>> taken(n);
  if (existing) {
    if (existing->fingerprint != fp)
      throw Error("the existing support points are for a mesh of " + describe_fingerprint(existing->fingerprint) +
                  ", this one has " + describe_fingerprint(fp));
    for (size_t i = 0; i < existing->size(); ++i)
      if (existing->layer[i] < n) taken[existing->layer[i]].push_back({existing->xyz[3 * i], existing->xyz[3 * i + 1]});
  }
  // The cover runs up the layers (a layer's overhangs may be held by points below); then each
  // layer's points go onto the mesh on all cores.
  std::vector<std::vector<PlanePoint>> plane(n);
  const CoverReach reach{options.point_reach_mm(), options.support_radius_mm()};
  HeldSurface held(std::max(reach.head, reach.support));
  const Progress cover_progress = sub_progress(progress, 0, 0.5);
  // Each part's support force (support_force.h), layer on layer: its points' and what it inherits.
  const double point_force = options.held_area_mm2();
  std::vector<double> force_below;
  for (size_t k = 0; k < n; ++k) {
    const double z = slicing.layer_z[k];
    const LayerAreas& a = areas[k];
    plane[k] = cover_layer(a, taken[k], held, z, reach);
    std::vector<double> force = inherited_force(a, force_below);
    std::vector<std::array<double, 2>> layer = taken[k];
    for (const PlanePoint& p : plane[k]) layer.push_back({p.x, p.y});
    for (const std::array<double, 2>& p : layer) {
      const size_t i = part_at(a.parts, p[0], p[1]);
      if (i < force.size()) force[i] += point_force;
    }
    // Each part's slopes and their area.
    std::vector<std::vector<const ClipperLib::Paths*>> slopes(a.parts.size());
    std::vector<double> slope_mm2(a.parts.size(), 0);
    for (size_t j = 0; j < a.slopes.size(); ++j) {
      const size_t i = a.slope_part[j];
      if (i < a.parts.size()) slopes[i].push_back(&a.slopes[j]), slope_mm2[i] += region_area_mm2(a.slopes[j]);
    }
    for (size_t i = 0; i < a.parts.size(); ++i) {
      const size_t needed = slope_points_needed(slope_mm2[i], a.part_mm2[i], force[i], point_force);
      if (needed == 0) continue;
      const std::vector<PlanePoint> added = hold_slopes(slopes[i], layer, held, z, reach, needed);
      for (const PlanePoint& p : added) layer.push_back({p.x, p.y}), plane[k].push_back(p);
      force[i] += double(added.size()) * point_force;
    }
    force_below = std::move(force);
    for (const std::array<double, 2>& p : layer) held.add(p[0], p[1], z);
    if (k % 64 == 0 || k + 1 == n) report_progress(cover_progress, double(k + 1) / double(n), "support points");
  }
  // The rays meet faces below the highest layer with points only (none without points).
  double z_below = -INFINITY;
  for (size_t k = 0; k < n; ++k)
    if (!plane[k].empty()) z_below = layer_span(slicing, k).hi;
  const PartColumns down(mesh, true, z_below);
  std::vector<LayerPoints> layers(n);
  parallel_blocks(
      n,
      [&](size_t k) {
        const LayerSpan span = layer_span(slicing, k);
        const LayerSpan inner{k ? slicing.layer_z[k - 1] : span.lo, slicing.layer_z[k]};
        LayerPoints& out = layers[k];
        for (const PlanePoint& p : plane[k]) {
          uint32_t face;
          double bary[3];
          if (!ray_hit(down, p.x, p.y, span, inner, face, bary)) nearest_contour_point(mesh, slicing, k, p.x, p.y, face, bary);
          out.face.push_back(face);
          out.bary.insert(out.bary.end(), bary, bary + 3);
          out.kind.push_back(p.kind);
        }
      },
      sub_progress(progress, 0.5, 1), "support points");
  size_t total = 0;
  for (const LayerPoints& l : layers) total += l.face.size();
  if (total > options.max_points)
    throw Error(format("the part needs %zu support points, more than the limit of %zu", total, options.max_points));
  SupportPoints points;
  points.fingerprint = fp;
  for (size_t k = 0; k < n; ++k) {
    const LayerPoints& l = layers[k];
    points.face.insert(points.face.end(), l.face.begin(), l.face.end());
    points.bary.insert(points.bary.end(), l.bary.begin(), l.bary.end());
    points.kind.insert(points.kind.end(), l.kind.begin(), l.kind.end());
    points.layer.insert(points.layer.end(), l.face.size(), uint32_t(k));
  }
  place_support_points(points, mesh);
  return points;
}

}  // namespace slicereuse
