#include "slicereuse/supports/transfer_support_points.h"

#include <algorithm>
#include <cmath>

#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/mesh/vec3.h"
#include "slicereuse/supports/locate_support_points.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "support_areas.h"
#include "support_points_for_areas.h"

namespace slicereuse {
namespace {

// The source's points on member: the same faces, or through the map and onto member's surface.
SupportPoints carried(const SupportPoints& source, const Mesh& member, const Fingerprint& member_fp,
                      const SurfaceMap* map) {
  if (source.fingerprint == member_fp) {
    SupportPoints out = source;
    place_support_points(out, member);
    return out;
  }
  if (!map)
    throw Error("the support points are for a mesh of " + describe_fingerprint(source.fingerprint) +
                ", the member has " + describe_fingerprint(member_fp) + ", and no map between them was given");
  if (map->source != source.fingerprint)
    throw Error("the map is from a mesh of " + describe_fingerprint(map->source) +
                ", but the support points are for a mesh of " + describe_fingerprint(source.fingerprint));
  validate_surface_map(*map);
  check_map_target(*map, member);
  std::vector<double> xyz(3 * source.size(), 0);
  for (size_t i = 0; i < source.size(); ++i)
    for (int j = 0; j < 3; ++j) {
      double image[3];
      map_point(*map, member, map->source_faces[3 * size_t(source.face[i]) + j], image);
      for (int a = 0; a < 3; ++a) xyz[3 * i + a] += source.bary[3 * i + j] * image[a];
    }
  SupportPoints out = locate_support_points(member, xyz, source.kind);
  out.layer = source.layer;
  return out;
}

// The layer whose plane is the first at or above z (layers() when above the top one).
size_t layer_at_or_above(const Slices& s, double z) {
  return size_t(std::lower_bound(s.layer_z.begin(), s.layer_z.end(), z) - s.layer_z.begin());
}

// The layer on whose areas point i is certified (within radius of them, z in its span), trying
// its own layer first (the plate's planes are the source's), then the layer at or above its z,
// the one below and the one above that; n when none, or when its surface faces up there.
size_t certifying_layer(const SupportPoints& p, size_t i, const Slices& s, const std::vector<LayerAreas>& areas,
                        double radius) {
  const size_t n = s.layers();
  if (faces_up(p, i)) return n;
  const double x = p.xyz[3 * i], y = p.xyz[3 * i + 1], z = p.xyz[3 * i + 2];
  const size_t at = layer_at_or_above(s, z);
  for (const size_t k : {size_t(p.layer[i]), at, at - 1, at + 1}) {
    if (k >= n) continue;  // at - 1 wraps for at = 0
    const LayerSpan span = layer_span(s, k);
    if (z >= span.lo && z <= span.hi && distance_to_areas(areas[k], x, y) <= radius) return k;
  }
  return n;
}

}  // namespace

SupportPoints transfer_support_points(const SupportPoints& source, const Mesh& member, const Slices& member_slicing,
                                      const SupportPointOptions& options, SupportTransferStats* stats,
                                      const SurfaceMap* map, const Progress& progress) {
  validate_support_points(source);
  check_support_input(member, member_slicing, options);
  const Fingerprint member_fp = member_slicing.fingerprint;
  const SupportPoints on_member = carried(source, member, member_fp, map);
  const std::vector<LayerAreas> areas = support_areas(member_slicing, options, sub_progress(progress, 0, 0.4));

  SupportPoints kept, dropped;
  kept.fingerprint = dropped.fingerprint = member_fp;
  for (size_t i = 0; i < on_member.size(); ++i) {
    const size_t k = certifying_layer(on_member, i, member_slicing, areas, options.support_radius_mm());
    if (k == member_slicing.layers()) {
      dropped.push_back_from(on_member, i);
    } else {
      kept.push_back_from(on_member, i);
      kept.layer.back() = uint32_t(k);
    }
  }
  const SupportPoints added =
      support_points_for_areas(member, member_slicing, areas, options, &kept, sub_progress(progress, 0.4, 1));
  if (kept.size() + added.size() > options.max_points)
    throw Error(format("the part needs %zu support points, more than the limit of %zu", kept.size() + added.size(),
                       options.max_points));

  // An added point near a dropped one is that point moved: each pairs with at most one.
  size_t moved = 0;
  std::vector<bool> paired(dropped.size(), false);
  const double reach2 = options.minimal_distance_mm * options.minimal_distance_mm;
  for (size_t a = 0; a < added.size(); ++a) {
    size_t best = dropped.size();
    double best_d2 = reach2;
    for (size_t d = 0; d < dropped.size(); ++d) {
      const double d2 = squared_distance(&added.xyz[3 * a], &dropped.xyz[3 * d]);
      if (!paired[d] && d2 <= best_d2) best_d2 = d2, best = d;
    }
    if (best < dropped.size()) paired[best] = true, ++moved;
  }
  if (stats) {
    stats->transferred = source.size();
    stats->kept = kept.size();
    stats->moved = moved;
    stats->added = added.size() - moved;
    stats->dropped = dropped.size() - moved;
  }
  SupportPoints out = kept;
  for (size_t i = 0; i < added.size(); ++i) out.push_back_from(added, i);
  return out;
}

}  // namespace slicereuse
