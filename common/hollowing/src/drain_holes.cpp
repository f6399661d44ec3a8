#include "slicereuse/hollowing/drain_holes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "slicereuse/regions/clip_regions.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/regions/region_pieces.h"
#include "slicereuse/regions/turns_by_15_degrees.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {
namespace {

// The centroid of a piece (outer loop less its holes), in Clipper units.
std::array<double, 2> centroid(const ClipperLib::Paths& piece) {
  double area = 0, cx = 0, cy = 0;
  for (const ClipperLib::Path& loop : piece)
    for (size_t i = 0; i < loop.size(); ++i) {
      const ClipperLib::IntPoint& p = loop[i];
      const ClipperLib::IntPoint& q = loop[(i + 1) % loop.size()];
      const double cross = double(p.X) * double(q.Y) - double(q.X) * double(p.Y);
      area += cross;
      cx += (double(p.X) + double(q.X)) * cross;
      cy += (double(p.Y) + double(q.Y)) * cross;
    }
  return {cx / (3 * area), cy / (3 * area)};
}

// The piece shrunk by r (Clipper units): where a hole's centre keeps the hole inside it.
ClipperLib::Paths room_in(const ClipperLib::Paths& piece, double r) {
  ClipperLib::ClipperOffset offset;
  offset.AddPaths(piece, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
  ClipperLib::Paths room;
  offset.Execute(room, -r);
  return room;
}

// Where the first hole under the piece goes.
ClipperLib::IntPoint hole_centre(const ClipperLib::Paths& piece, const ClipperLib::Paths& room) {
  const std::array<double, 2> c = centroid(piece);
  const ClipperLib::IntPoint middle{ClipperLib::cInt(std::llround(c[0])), ClipperLib::cInt(std::llround(c[1]))};
  if (room.empty() || region_covers(room, middle)) return middle;
  // The vertex of the shrunk piece nearest the centroid: the hole lies inside the piece there.
  ClipperLib::IntPoint best = room[0][0];
  double nearest = INFINITY;
  for (const ClipperLib::Path& loop : room)
    for (const ClipperLib::IntPoint& p : loop) {
      const double dx = double(p.X) - c[0], dy = double(p.Y) - c[1];
      if (dx * dx + dy * dy < nearest) nearest = dx * dx + dy * dy, best = p;
    }
  return best;
}

// The corner of room farthest from every centre chosen (its least distance to them greatest), and
// that distance squared; 0 when room has no corner off them.
std::pair<ClipperLib::IntPoint, double> farthest_corner(const ClipperLib::Paths& room,
                                                        const std::vector<ClipperLib::IntPoint>& chosen) {
  std::pair<ClipperLib::IntPoint, double> best{{0, 0}, 0};
  for (const ClipperLib::Path& loop : room)
    for (const ClipperLib::IntPoint& p : loop) {
      double nearest = INFINITY;
      for (const ClipperLib::IntPoint& c : chosen) {
        const double dx = double(p.X - c.X), dy = double(p.Y - c.Y);
        nearest = std::min(nearest, dx * dx + dy * dy);
      }
      if (nearest > best.second) best = {p, nearest};
    }
  return best;
}

// The 24-gon of radius r (Clipper units) around c.
ClipperLib::Path disc(const ClipperLib::IntPoint& c, double r) {
  ClipperLib::Path d;
  for (int i = 0; i < 24; ++i) {
    const std::array<double, 2> t = turn_by_15_degrees(i);
    d.push_back({c.X + ClipperLib::cInt(std::llround(r * t[0])), c.Y + ClipperLib::cInt(std::llround(r * t[1]))});
  }
  return d;
}

void check_diameter(double diameter_mm) {
  if (!(std::isfinite(diameter_mm) && diameter_mm > 0))
    throw Error(format("a drain hole's diameter is %g mm; it must be a positive number", diameter_mm));
}

using Vec3 = std::array<double, 3>;

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Vec3 unit(const Vec3& a) {
  const double n = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return {a[0] / n, a[1] / n, a[2] / n};
}

// The section of the convex prism whose two caps are `caps` (24 corners each, corner i of one
// over corner i of the other) by the plane at z: the points where its edges cross the plane, in
// order around their middle (the section of a convex solid is convex); empty when fewer than 3.
ClipperLib::Path prism_section(const std::array<std::array<Vec3, 24>, 2>& caps, double z) {
  ClipperLib::Path pts;
  const auto edge = [&](const Vec3& p, const Vec3& q) {
    if (p[2] == z) pts.push_back({region_units(p[0]), region_units(p[1])});
    if ((p[2] - z) * (q[2] - z) < 0) {
      const double t = (z - p[2]) / (q[2] - p[2]);
      pts.push_back({region_units(p[0] + t * (q[0] - p[0])), region_units(p[1] + t * (q[1] - p[1]))});
    }
  };
  for (size_t i = 0; i < 24; ++i) {
    edge(caps[0][i], caps[0][(i + 1) % 24]);
    edge(caps[1][i], caps[1][(i + 1) % 24]);
    edge(caps[0][i], caps[1][i]);
  }
  if (pts.size() < 3) return {};
  __int128 sx = 0, sy = 0;
  for (const ClipperLib::IntPoint& p : pts) sx += p.X, sy += p.Y;
  const ClipperLib::cInt mx = ClipperLib::cInt(sx / __int128(pts.size()));
  const ClipperLib::cInt my = ClipperLib::cInt(sy / __int128(pts.size()));
  // Counter-clockwise around the middle, exactly: by half-plane, then by the cross product.
  const auto upper = [&](const ClipperLib::IntPoint& p) { return p.Y > my || (p.Y == my && p.X >= mx); };
  std::sort(pts.begin(), pts.end(), [&](const ClipperLib::IntPoint& a, const ClipperLib::IntPoint& b) {
    if (upper(a) != upper(b)) return upper(a);
    return __int128(a.X - mx) * __int128(b.Y - my) - __int128(a.Y - my) * __int128(b.X - mx) > 0;
  });
  pts.erase(std::unique(pts.begin(), pts.end(),
                        [](const ClipperLib::IntPoint& a, const ClipperLib::IntPoint& b) { return a.X == b.X && a.Y == b.Y; }),
            pts.end());
  if (pts.size() < 3 || ClipperLib::Area(pts) <= 0) return {};
  return pts;
}

}  // namespace

std::vector<DrainHole> add_drain_holes(std::vector<ClipperLib::Paths>& cavity, double diameter_mm, size_t count) {
  check_diameter(diameter_mm);
  if (count == 0) throw Error("0 drain holes per cavity: at least 1, or a drain hole diameter of 0 for none");
  const double r = 0.5 * double(region_units(diameter_mm));
  std::vector<DrainHole> holes;
  std::vector<ClipperLib::Path> discs;
  for (size_t k = 0; k < cavity.size(); ++k) {
    if (cavity[k].empty()) continue;
    // Most layers are one piece with a corner inside the layer below's cavity, or holding one of
    // its corners: it overlaps, and needs no splitting into pieces (which Clipper makes strictly
    // simple, slowly).
    if (k > 0 && std::count_if(cavity[k].begin(), cavity[k].end(), [](const ClipperLib::Path& loop) {
                   return ClipperLib::Orientation(loop);
                 }) == 1) {
      bool overlaps = false;
      for (const ClipperLib::Path& loop : cavity[k])
        overlaps = overlaps || region_covers_strictly(cavity[k - 1], loop[0]);
      for (const ClipperLib::Path& loop : cavity[k - 1])
        overlaps = overlaps || region_covers_strictly(cavity[k], loop[0]);
      if (overlaps) continue;
    }
    for (const ClipperLib::Paths& piece : region_pieces(cavity[k])) {
      if (k > 0 && !clip_regions(piece, cavity[k - 1], ClipperLib::ctIntersection).empty()) continue;
      const ClipperLib::Paths room = room_in(piece, r);
      std::vector<ClipperLib::IntPoint> centres{hole_centre(piece, room)};
      while (centres.size() < count) {
        const auto [corner, d2] = farthest_corner(room, centres);
        if (d2 == 0) break;  // no room for another hole apart from these
        centres.push_back(corner);
      }
      for (const ClipperLib::IntPoint& c : centres) {
        holes.push_back({0, k, double(c.X) / kRegionScale, double(c.Y) / kRegionScale});
        discs.push_back(disc(c, r));
      }
    }
  }
  // Each hole into the layers under its cavity (after all are found: a hole is no cavity's start),
  // all of a layer's holes in one union.
  for (size_t k = 0; k < cavity.size(); ++k) {
    ClipperLib::Paths under;
    for (size_t h = 0; h < holes.size(); ++h)
      if (k < holes[h].layer) under.push_back(discs[h]);
    if (!under.empty()) cavity[k] = clip_regions(cavity[k], under, ClipperLib::ctUnion);
  }
  return holes;
}

void check_drain_holes_fit(const std::vector<DrainHole>& holes, double diameter_mm, const Slices& part) {
  const double r = 0.5 * double(region_units(diameter_mm));
  std::vector<ClipperLib::Paths> regions;  // made as far up as the holes reach
  const auto region = [&](size_t k) -> const ClipperLib::Paths& {
    while (regions.size() <= k) regions.push_back(layer_region(LayerView(part, regions.size())));
    return regions[k];
  };
  // Under a millionth of a square millimetre is the discs' rounding to Clipper's grid.
  constexpr double kRoundingMm2 = 1e-6;
  for (const DrainHole& h : holes) {
    if (!h.automatic || h.layer == h.first || h.layer > part.layers()) continue;
    const ClipperLib::Paths d{disc({region_units(h.x_mm), region_units(h.y_mm)}, r)};
    // Right under the cavity the part rings the hole; further down, what of the hole lies outside
    // the part must stay outside on every layer below (its mouth on a base that curves up, as a
    // sphere's does), else it opens sideways through a wall.
    ClipperLib::Paths above;
    for (size_t k = h.layer; k-- > h.first;) {
      ClipperLib::Paths outside = clip_regions(d, region(k), ClipperLib::ctDifference);
      const double sideways = region_area_mm2(
          k + 1 == h.layer ? outside : clip_regions(above, outside, ClipperLib::ctDifference));
      if (sideways > kRoundingMm2) {
        const bool under = k + 1 == h.layer;  // else the layer above is where it leaves the part
        throw Error(format("a drain hole of %g mm at (%.2f, %.2f) mm would cut through the part's side on layer %zu "
                           "(z %.3f mm): %.3g mm2 of it lies outside the part there, %s; make drain_hole_mm smaller",
                           diameter_mm, h.x_mm, h.y_mm, under ? k : k + 1, part.layer_z[under ? k : k + 1], sideways,
                           under ? "right under its cavity" : "over part of the layer below"));
      }
      above = std::move(outside);
    }
  }
}

std::array<std::array<double, 3>, 2> drain_hole_axis(const DrainHole& h, double z_start, double thickness,
                                                     double depth_mm) {
  if (h.automatic)
    return {{{h.x_mm, h.y_mm, z_start - kHoleStickOutMm}, {h.x_mm, h.y_mm, z_start + double(h.layer) * thickness}}};
  std::array<std::array<double, 3>, 2> ends;
  const double mouth[3] = {h.x_mm, h.y_mm, h.z_mm};
  for (size_t j = 0; j < 3; ++j) {
    ends[0][j] = mouth[j] + kHoleStickOutMm * h.axis[j];
    ends[1][j] = mouth[j] - depth_mm * h.axis[j];
  }
  return ends;
}

void find_drain_hole_mouths(const Mesh& mesh, double z_start, double thickness, std::vector<DrainHole>& holes) {
  for (DrainHole& h : holes) {
    const double below = z_start + double(h.layer) * thickness;
    h.z_mm = z_start;
    for (size_t f = 0; f < mesh.faces(); ++f) {
      const double* p[3];
      for (int j = 0; j < 3; ++j) p[j] = &mesh.V[3 * size_t(mesh.F[3 * f + size_t(j)])];
      // The axis's point in the face's projection onto x-y: its area coordinates there.
      const double d = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]);
      if (d == 0) continue;
      const double b1 = ((h.x_mm - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (h.y_mm - p[0][1])) / d;
      const double b2 = ((p[1][0] - p[0][0]) * (h.y_mm - p[0][1]) - (h.x_mm - p[0][0]) * (p[1][1] - p[0][1])) / d;
      if (b1 < 0 || b2 < 0 || b1 + b2 > 1) continue;
      const double z = p[0][2] + b1 * (p[1][2] - p[0][2]) + b2 * (p[2][2] - p[0][2]);
      if (z < below && z > h.z_mm) h.z_mm = z;
    }
  }
}

std::vector<DrainHole> add_drain_holes_at(std::vector<ClipperLib::Paths>& cavity, const std::vector<double>& layer_z,
                                          const std::vector<double>& mouths, const std::vector<double>& axes,
                                          double diameter_mm, double depth_mm) {
  check_diameter(diameter_mm);
  if (layer_z.size() != cavity.size() || mouths.size() != axes.size() || mouths.size() % 3)
    throw Error(format("internal error: drain holes for %zu layers of cavity and %zu planes, %zu mouth and %zu axis "
                       "coordinates",
                       cavity.size(), layer_z.size(), mouths.size(), axes.size()));
  const double r = 0.5 * diameter_mm;
  std::vector<DrainHole> holes;
  std::vector<std::vector<std::pair<size_t, ClipperLib::Path>>> sections;
  for (size_t h = 0; h < mouths.size() / 3; ++h) {
    const Vec3 m{mouths[3 * h], mouths[3 * h + 1], mouths[3 * h + 2]};
    const Vec3 given{axes[3 * h], axes[3 * h + 1], axes[3 * h + 2]};
    const double length = std::sqrt(given[0] * given[0] + given[1] * given[1] + given[2] * given[2]);
    if (!(std::isfinite(length) && length > 0 && std::isfinite(m[0] + m[1] + m[2])))
      throw Error(format("drain hole %zu at (%g, %g, %g) mm has no direction: its normal is (%g, %g, %g)", h + 1, m[0],
                         m[1], m[2], given[0], given[1], given[2]));
    const Vec3 a = unit(given);
    // Across the axis: u and v, square to it and to each other.
    const size_t least = std::abs(a[0]) <= std::abs(a[1]) && std::abs(a[0]) <= std::abs(a[2]) ? 0
                         : std::abs(a[1]) <= std::abs(a[2])                                 ? 1
                                                                                             : 2;
    Vec3 e{0, 0, 0};
    e[least] = 1;
    const Vec3 u = unit(cross(a, e)), v = cross(a, u);
    std::array<std::array<Vec3, 24>, 2> caps;
    for (size_t i = 0; i < 24; ++i) {
      const std::array<double, 2> t = turn_by_15_degrees(int(i));
      for (size_t j = 0; j < 3; ++j) {
        const double round = r * (t[0] * u[j] + t[1] * v[j]);
        caps[0][i][j] = m[j] + kHoleStickOutMm * a[j] + round;
        caps[1][i][j] = m[j] - depth_mm * a[j] + round;
      }
    }
    DrainHole hole{SIZE_MAX, 0, m[0], m[1], m[2], a, false};
    std::vector<std::pair<size_t, ClipperLib::Path>> cut;
    bool reaches = false;
    for (size_t k = 0; k < cavity.size(); ++k) {
      ClipperLib::Path section = prism_section(caps, layer_z[k]);
      if (section.empty()) continue;
      hole.first = std::min(hole.first, k);
      hole.layer = k + 1;
      reaches = reaches || !clip_regions(cavity[k], {section}, ClipperLib::ctIntersection).empty();
      cut.emplace_back(k, std::move(section));
    }
    if (!reaches)
      throw Error(format("drain hole %zu at (%.2f, %.2f, %.2f) mm reaches no cavity: drilled %g mm in along its normal "
                         "(%.2f, %.2f, %.2f), it ends in the wall; place it over the cavity (Hollow Mesh shows it)",
                         h + 1, m[0] + 0.0, m[1] + 0.0, m[2] + 0.0, depth_mm, a[0] + 0.0, a[1] + 0.0, a[2] + 0.0));
    holes.push_back(hole);
    sections.push_back(std::move(cut));
  }
  std::vector<ClipperLib::Paths> cuts(cavity.size());
  for (const auto& cut : sections)
    for (const auto& [k, section] : cut) cuts[k].push_back(section);
  for (size_t k = 0; k < cavity.size(); ++k)
    if (!cuts[k].empty()) cavity[k] = clip_regions(cavity[k], cuts[k], ClipperLib::ctUnion);
  return holes;
}

}  // namespace slicereuse
