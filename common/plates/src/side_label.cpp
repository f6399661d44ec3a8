#include "slicereuse/plates/side_label.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "slicereuse/plates/base_label.h"
#include "slicereuse/plates/placement.h"
#include "slicereuse/regions/clip_regions.h"
#include "slicereuse/regions/clip_to_box.h"
#include "slicereuse/regions/label_region.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse {
namespace {

using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

constexpr double kFlatShare = 0.5;   // of the depth: how far a face's points may lie from its plane
constexpr double kHeightStep = 0.9;  // each height tried is this share of the one before (as place_label)
constexpr double kOutsideMm = 1;     // how far the cut's bands start outside the face's plane

// The turn (about z) taking the side's outward direction, in the member's own frame, to -y.
double side_deg(LabelSide side) {
  switch (side) {
    case LabelSide::Back: return 180;
    case LabelSide::Left: return 90;
    case LabelSide::Right: return -90;
    default: return 0;
  }
}

Paths turned(const Paths& region, const Turn& t) {
  Paths out = region;
  for (Path& path : out)
    for (IntPoint& p : path) {
      double x, y;
      t.apply(double(p.X), double(p.Y), x, y);
      p = {cInt(std::llround(x)), cInt(std::llround(y))};
    }
  return out;
}

Path rect(cInt x0, cInt y0, cInt x1, cInt y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

// A region's box (its points': no Clipper, which would build its edges first); empty: none.
ClipperLib::IntRect bounds(const Paths& region) {
  ClipperLib::IntRect b{std::numeric_limits<cInt>::max(), std::numeric_limits<cInt>::max(),
                        std::numeric_limits<cInt>::min(), std::numeric_limits<cInt>::min()};
  for (const Path& path : region)
    for (const IntPoint& p : path)
      b = {std::min(b.left, p.X), std::min(b.top, p.Y), std::max(b.right, p.X), std::max(b.bottom, p.Y)};
  return b;
}

// A layer's face over the strip a <= u <= b of the side's frame (the side facing -w, w being y):
// whether every u has the part, the least and the greatest over u of the part's least w there
// (its outermost point at u), and up to which w the part fills the strip from that greatest on,
// looking no farther than `reach` beyond the least.
struct LayerFace {
  bool covered = false;
  cInt outermost = 0;
  double innermost = 0, solid = 0;
};

// What of a region lies over a <= u <= b and at most w_max.
Paths over(const Paths& region, cInt a, cInt b, cInt w_max) {
  if (region.empty()) return {};
  const ClipperLib::IntRect all = bounds(region);
  return clip_to_box(region, {a, all.top - 1, b, std::min(all.bottom + 1, w_max)});
}

// The least w of a region over a <= u <= b (rounded down), none when it has nothing there: the
// least lies on its boundary (it is bounded), at a vertex over the strip or where an edge
// crosses the strip's sides. The top of what a clip to the strip would give, with no clip (a
// layer's hundreds of points cut to a strip at each of its layers were most of a label's search).
std::optional<cInt> least_w_over(const Paths& region, cInt a, cInt b) {
  std::optional<double> least;
  const auto take = [&](double w) { least = least ? std::min(*least, w) : w; };
  for (const Path& path : region)
    for (size_t i = 0; i < path.size(); ++i) {
      const IntPoint& p = path[i];
      const IntPoint& q = path[(i + 1) % path.size()];
      if (p.X >= a && p.X <= b) take(double(p.Y));
      for (const cInt side : {a, b})
        if ((p.X < side && q.X > side) || (p.X > side && q.X < side))
          take(double(p.Y) + double(q.Y - p.Y) * (double(side - p.X) / double(q.X - p.X)));
    }
  if (!least) return std::nullopt;
  return cInt(std::floor(*least));
}

LayerFace layer_face(const Paths& region, cInt a, cInt b, cInt reach) {
  LayerFace f;
  const std::optional<cInt> outermost = least_w_over(region, a, b);
  if (!outermost) return f;
  f.outermost = *outermost;
  const cInt cap = f.outermost + reach;
  const Paths near = clip_to_box(region, {a, f.outermost - 1, b, cap});
  // Between consecutive vertices' u, the part's least w at u is on one edge (the polygons do not
  // cross): the lowest crossing the slab's middle. Its greatest is at a slab's end.
  std::vector<cInt> breaks{a, b};
  for (const Path& path : near)
    for (const IntPoint& p : path)
      if (p.X > a && p.X < b) breaks.push_back(p.X);
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  const size_t slabs = breaks.size() - 1;
  std::vector<double> middle(slabs, INFINITY), ends(slabs, 0);
  for (const Path& path : near)
    for (size_t i = 0; i < path.size(); ++i) {
      IntPoint l = path[i], r = path[(i + 1) % path.size()];
      if (l.X == r.X) continue;
      if (l.X > r.X) std::swap(l, r);
      const auto w_at = [&](cInt u) {
        return double(l.Y) + (double(u) - double(l.X)) * double(r.Y - l.Y) / double(r.X - l.X);
      };
      const size_t s1 = size_t(std::lower_bound(breaks.begin(), breaks.end(), r.X) - breaks.begin());
      for (size_t s = size_t(std::lower_bound(breaks.begin(), breaks.end(), l.X) - breaks.begin()); s < s1; ++s) {
        const double m = 0.5 * (w_at(breaks[s]) + w_at(breaks[s + 1]));
        if (m < middle[s]) {
          middle[s] = m;
          ends[s] = std::max(w_at(breaks[s]), w_at(breaks[s + 1]));
        }
      }
    }
  f.innermost = -INFINITY;
  for (size_t s = 0; s < slabs; ++s) {
    if (middle[s] == INFINITY) return f;  // a u without the part
    f.innermost = std::max(f.innermost, ends[s]);
  }
  f.covered = true;
  // The strip from the innermost point to the cap, less the part: where the part first fails.
  const cInt from = cInt(std::ceil(f.innermost));
  const Paths gaps = from < cap ? clip_regions({rect(a, from, b, cap)}, near, ClipperLib::ctDifference) : Paths{};
  f.solid = gaps.empty() ? double(std::max(from, cap)) : double(bounds(gaps).top);
  return f;
}

// The u-intervals of the horizontal line at height z (both in Clipper units of the side's frame,
// u from a to b) inside the letters, cut by Clipper, touching ones joined.
std::vector<std::pair<cInt, cInt>> section(const Paths& letters, cInt z, cInt a, cInt b) {
  ClipperLib::Clipper c;
  c.AddPath({{a, z}, {b, z}}, ClipperLib::ptSubject, false);
  c.AddPaths(letters, ClipperLib::ptClip, true);
  ClipperLib::PolyTree tree;
  c.Execute(ClipperLib::ctIntersection, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  Paths open;
  ClipperLib::OpenPathsFromPolyTree(tree, open);
  std::vector<std::pair<cInt, cInt>> pieces, joined;
  for (const Path& piece : open) {
    if (piece.empty()) continue;
    cInt lo = piece[0].X, hi = piece[0].X;
    for (const IntPoint& p : piece) {
      lo = std::min(lo, p.X);
      hi = std::max(hi, p.X);
    }
    if (hi > lo) pieces.push_back({lo, hi});
  }
  std::sort(pieces.begin(), pieces.end());
  for (const auto& piece : pieces) {
    if (!joined.empty() && piece.first <= joined.back().second)
      joined.back().second = std::max(joined.back().second, piece.second);
    else
      joined.push_back(piece);
  }
  return joined;
}

}  // namespace

const char* side_name(LabelSide side) {
  switch (side) {
    case LabelSide::Front: return "front";
    case LabelSide::Back: return "back";
    case LabelSide::Left: return "left";
    case LabelSide::Right: return "right";
    default: return "base";
  }
}

SideLabel place_side_label(const Slices& layers, double thickness_mm, double turn_deg, const std::string& text,
                           const std::string& name, const LabelOptions& o) {
  return place_side_label(layers_paths(layers), layers.layer_z, thickness_mm, turn_deg, text, name, o);
}

SideLabel place_side_label(std::vector<Paths> regions, const std::vector<double>& layer_z, double thickness_mm,
                           double turn_deg, const std::string& text, const std::string& name, const LabelOptions& o) {
  label_box_mm(text, o.height_mm);  // checks the text and the height
  SideLabel s;
  const Turn to_side = turn_of(side_deg(o.side) - turn_deg), to_plate = turn_of(turn_deg - side_deg(o.side));
  const size_t L = regions.size();
  // Every layer in the side's frame, and the member's extent in u.
  parallel_blocks(L, [&](size_t k) { regions[k] = turned(regions[k], to_side); }, {}, "labels");
  cInt u_lo = std::numeric_limits<cInt>::max(), u_hi = std::numeric_limits<cInt>::min();
  for (size_t k = 0; k < L; ++k) {
    if (regions[k].empty()) continue;
    const ClipperLib::IntRect b = bounds(regions[k]);
    u_lo = std::min(u_lo, b.left);
    u_hi = std::max(u_hi, b.right);
  }
  const std::array<double, 2> least = label_box_mm(text, o.min_height_mm);
  const double tol_mm = kFlatShare * o.depth_mm;
  s.why = format("the label '%s' fits nowhere on the %s side of %s: even %.3g mm high it is %.3g mm long, and no %.3g "
                 "mm of its height has a face %.3g mm wide (%g mm either side of the label) with every point within "
                 "%.3g mm of a plane and %.3g mm of solid part behind the innermost",
                 text.c_str(), side_name(o.side), name.c_str(), o.min_height_mm, least[0], o.min_height_mm,
                 least[0] + 2 * o.margin_mm, o.margin_mm, tol_mm, o.depth_mm + kLabelRoofMm);
  if (u_lo > u_hi) return s;
  const cInt u_centre = (u_lo + u_hi) / 2;
  const cInt margin = region_units(o.margin_mm), tol = region_units(tol_mm), depth = region_units(o.depth_mm);
  const cInt roof = region_units(kLabelRoofMm), reach = tol + depth + roof;
  std::vector<double> heights;
  for (double h = o.height_mm; h > o.min_height_mm; h *= kHeightStep) heights.push_back(h);
  heights.push_back(o.min_height_mm);
  // Half the strip a box h high looks at: its width and the margins.
  const auto half_strip = [&](double h) { return region_units(0.5 * label_box_mm(text, h)[0]) + margin; };
  // All that matters from here on: the widest strip, up to the reach beyond the outermost point
  // over the narrowest (a wider strip's outermost lies no farther in); none there, no box fits.
  const cInt widest = half_strip(std::max(heights.front(), heights.back()));
  const cInt narrowest = half_strip(std::min(heights.front(), heights.back()));
  parallel_blocks(
      L,
      [&](size_t k) {
        Paths& r = regions[k];
        const std::optional<cInt> top = least_w_over(r, u_centre - narrowest, u_centre + narrowest);
        r = top ? over(r, u_centre - widest, u_centre + widest, *top + reach) : Paths{};
      },
      {}, "labels");
  const double bottom = layer_z[0] - 0.5 * thickness_mm;
  // Whether the box from layer j, `spanned` layers high, over the strip a <= u <= b has a face
  // (faces: the layers' faces over that strip, made as needed), and the face's plane.
  const auto face_of = [&](std::vector<std::optional<LayerFace>>& faces, cInt a, cInt b, size_t j, size_t spanned,
                           cInt& plane) {
    double innermost = -INFINITY, solid = INFINITY;
    plane = std::numeric_limits<cInt>::max();
    for (size_t k = j; k < j + spanned; ++k) {
      if (!faces[k]) faces[k] = layer_face(regions[k], a, b, reach);
      const LayerFace& f = *faces[k];
      if (!f.covered) return false;
      plane = std::min(plane, f.outermost);
      innermost = std::max(innermost, f.innermost);
      solid = std::min(solid, f.solid);
    }
    return innermost <= double(plane + tol) && solid >= innermost + double(depth + roof);
  };
  // A box without a face over the narrowest strip gets none over its own: a wider strip's
  // outermost point lies no farther in and its innermost no nearer, so it is no flatter, and the
  // letters over the narrow strip need the part solid behind it all the same. Most boxes fail
  // there, on faces made once for every height (a 200k-face arch where none fits: 3x faster).
  std::vector<std::optional<LayerFace>> narrow(L);
  for (const double h : heights) {
    // The box's layers: those whose plane it spans, from its bottom on layer j's.
    const size_t spanned = size_t(std::floor(h / thickness_mm - 0.5 + 1e-9)) + 1;
    const double lowest = std::ceil(o.margin_mm / thickness_mm - 1e-9);
    const double highest = std::floor((double(L) * thickness_mm - o.margin_mm - h) / thickness_mm + 1e-9);
    if (h < 0.5 * thickness_mm || highest < lowest) continue;
    std::vector<size_t> bottoms;
    for (size_t j = size_t(lowest); j <= size_t(highest) && j + spanned <= L; ++j) bottoms.push_back(j);
    // Nearest the member's middle height first, the lower of two as near.
    const auto off_middle = [&](size_t j) { return std::fabs(2.0 * double(j) + h / thickness_mm - double(L)); };
    std::stable_sort(bottoms.begin(), bottoms.end(), [&](size_t x, size_t y) { return off_middle(x) < off_middle(y); });
    const cInt a = u_centre - half_strip(h), b = u_centre + half_strip(h);
    std::vector<std::optional<LayerFace>> faces(L);
    for (const size_t j : bottoms) {
      cInt plane;
      if (!face_of(narrow, u_centre - narrowest, u_centre + narrowest, j, spanned, plane) ||
          !face_of(faces, a, b, j, spanned, plane))
        continue;
      // Placed: the letters upright on the face, u to the right, z up, centred on the box.
      const double z_centre = bottom + double(j) * thickness_mm + 0.5 * h;
      Paths letters = label_region(text, h, false);
      for (Path& loop : letters) {
        std::vector<std::array<double, 3>> outline;
        for (IntPoint& p : loop) {
          p.X += u_centre;
          p.Y += region_units(z_centre);
          std::array<double, 3> q{0, 0, double(p.Y) / kRegionScale};
          to_plate.apply(double(p.X) / kRegionScale, double(plane) / kRegionScale, q[0], q[1]);
          outline.push_back(q);
        }
        s.outline.push_back(std::move(outline));
      }
      s.first = j;
      for (size_t k = j; k < j + spanned; ++k) {
        Paths bands;
        for (const auto& [u0, u1] : section(letters, region_units(layer_z[k]), a, b))
          bands.push_back(rect(u0, plane - region_units(kOutsideMm), u1, plane + tol + depth));
        s.cuts.push_back(turned(bands, to_plate));
      }
      s.height_mm = h;
      to_plate.apply(double(u_centre) / kRegionScale, double(plane) / kRegionScale, s.x_mm, s.y_mm);
      s.z_mm = z_centre;
      s.why.clear();
      return s;
    }
  }
  return s;
}

}  // namespace slicereuse
