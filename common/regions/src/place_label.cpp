#include "slicereuse/regions/place_label.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "slicereuse/regions/clip_regions.h"
#include "slicereuse/regions/label_region.h"
#include "slicereuse/regions/layer_region.h"
#include "slicereuse/regions/turns_by_15_degrees.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/squared_distances.h"

namespace slicereuse {
namespace {

constexpr double kStepShare = 1.0 / 250, kMinStepMm = 0.1;
constexpr int kAngles = 12;            // by 15 degrees over half a turn (turns_by_15_degrees.h)
constexpr size_t kCentresTried = 16;   // per height and angle, farthest from the edges first
constexpr double kHeightStep = 0.9;    // each height tried is this share of the one before

// The face's inside on a grid of cells (centre of cell (i, j) at x0 + (i + 0.5) step, ...): by
// the crossings of each row's centre line with the loops (even-odd: loops do not cross), then
// each inside cell's distance to the nearest outside one (exact Euclidean transform of the
// grid, Felzenszwalb and Huttenlocher), in cells.
struct FaceGrid {
  double x0 = 0, y0 = 0, step = 0;
  int w = 0, h = 0;
  std::vector<uint8_t> inside;
  std::vector<double> clearance;  // in cells

  // Whether (x, y) mm may lie inside the face: its cell is inside, or next to one that is
  // (covers decides there); false only where the face is more than a cell away.
  int cell_state(double x, double y) const {  // 1 inside, 0 outside, -1 near the edge
    const int i = int(std::floor((x - x0) / step)), j = int(std::floor((y - y0) / step));
    if (i < 0 || i >= w || j < 0 || j >= h) return 0;
    if (inside[size_t(j) * size_t(w) + size_t(i)]) return 1;
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int a = i + di, b = j + dj;
        if (a >= 0 && a < w && b >= 0 && b < h && inside[size_t(b) * size_t(w) + size_t(a)]) return -1;
      }
    return 0;
  }

};

FaceGrid face_grid(const ClipperLib::Paths& face) {
  FaceGrid g;
  const ClipperLib::IntRect b = [&] {
    ClipperLib::Clipper c;
    c.AddPaths(face, ClipperLib::ptSubject, true);
    return c.GetBounds();
  }();
  const double bx0 = double(b.left) / kRegionScale, by0 = double(b.top) / kRegionScale;
  const double bx1 = double(b.right) / kRegionScale, by1 = double(b.bottom) / kRegionScale;
  g.step = std::max(kMinStepMm, kStepShare * std::max(bx1 - bx0, by1 - by0));
  g.x0 = bx0 - g.step;  // a ring of outside cells around the face
  g.y0 = by0 - g.step;
  g.w = int(std::ceil((bx1 - bx0) / g.step)) + 2;
  g.h = int(std::ceil((by1 - by0) / g.step)) + 2;
  g.inside.assign(size_t(g.w) * size_t(g.h), 0);
  std::vector<double> crossings;
  for (int j = 0; j < g.h; ++j) {
    const double y = g.y0 + (j + 0.5) * g.step;
    crossings.clear();
    for (const ClipperLib::Path& loop : face)
      for (size_t a = 0; a < loop.size(); ++a) {
        const ClipperLib::IntPoint& p = loop[a];
        const ClipperLib::IntPoint& q = loop[(a + 1) % loop.size()];
        const double py = double(p.Y) / kRegionScale, qy = double(q.Y) / kRegionScale;
        if ((py <= y) == (qy <= y)) continue;
        const double px = double(p.X) / kRegionScale, qx = double(q.X) / kRegionScale;
        crossings.push_back(px + (y - py) / (qy - py) * (qx - px));
      }
    std::sort(crossings.begin(), crossings.end());
    for (size_t c = 0; c + 1 < crossings.size(); c += 2) {
      const int i0 = std::max(0, int(std::ceil((crossings[c] - g.x0) / g.step - 0.5)));
      const int i1 = std::min(g.w - 1, int(std::floor((crossings[c + 1] - g.x0) / g.step - 0.5)));
      for (int i = i0; i <= i1; ++i) g.inside[size_t(j) * size_t(g.w) + size_t(i)] = 1;
    }
  }
  std::vector<uint8_t> outside(g.inside.size());
  for (size_t i = 0; i < outside.size(); ++i) outside[i] = !g.inside[i];
  g.clearance = squared_distances(outside, g.w, g.h);
  for (double& c : g.clearance) c = std::sqrt(c);
  return g;
}


ClipperLib::Paths placed_region(const ClipperLib::Paths& label, double x_mm, double y_mm, const std::array<double, 2>& cs) {
  const double c = cs[0], s = cs[1];
  ClipperLib::Paths out = label;
  for (ClipperLib::Path& path : out)
    for (ClipperLib::IntPoint& p : path) {
      const double x = double(p.X), y = double(p.Y);
      p.X = ClipperLib::cInt(std::llround(c * x - s * y)) + region_units(x_mm);
      p.Y = ClipperLib::cInt(std::llround(s * x + c * y)) + region_units(y_mm);
    }
  return out;
}

bool inside(const ClipperLib::Paths& label, const ClipperLib::Paths& fit) {
  return clip_regions(label, fit, ClipperLib::ctDifference).empty();
}

}  // namespace

LabelPlacement place_label(const ClipperLib::Paths& face, const std::string& text, double height_mm,
                           double min_height_mm, double margin_mm, bool mirrored) {
  label_box_mm(text, height_mm);  // checks the text and the height
  if (!(std::isfinite(min_height_mm) && min_height_mm > 0 && min_height_mm <= height_mm))
    throw Error(format("a label's least height is %g mm; it must be positive and at most its height, %g mm",
                       min_height_mm, height_mm));
  if (!(std::isfinite(margin_mm) && margin_mm >= 0))
    throw Error(format("a label's margin is %g mm; it must be a finite, non-negative number", margin_mm));
  LabelPlacement best;
  ClipperLib::Paths fit;
  {
    ClipperLib::ClipperOffset offset(2, double(region_units(0.002)));
    offset.AddPaths(face, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    offset.Execute(fit, -double(region_units(margin_mm)));
  }
  if (fit.empty()) return best;
  const FaceGrid g = face_grid(fit);
  std::vector<size_t> centres;
  for (size_t c = 0; c < g.inside.size(); ++c)
    if (g.inside[c]) centres.push_back(c);
  // Farthest from the edges first; of those as far, nearest the middle of the face's box (a
  // label centred in a rectangle, not at one end of its middle line); then in grid order.
  const auto off_middle = [&](size_t c) {
    const double di = double(c % size_t(g.w)) - 0.5 * (g.w - 1), dj = double(c / size_t(g.w)) - 0.5 * (g.h - 1);
    return di * di + dj * dj;
  };
  std::stable_sort(centres.begin(), centres.end(), [&](size_t a, size_t b) {
    if (g.clearance[a] != g.clearance[b]) return g.clearance[a] > g.clearance[b];
    return off_middle(a) < off_middle(b);
  });
  std::vector<double> heights;
  for (double h = height_mm; h > min_height_mm; h *= kHeightStep) heights.push_back(h);
  heights.push_back(min_height_mm);
  for (const double h : heights) {
    const std::array<double, 2> box = label_box_mm(text, h);
    const double half_height_cells = 0.5 * box[1] / g.step;
    const ClipperLib::Paths label = label_region(text, h, mirrored);
    for (int k = 0; k < kAngles; ++k) {
      const double angle = 15.0 * ((k + 1) / 2) * (k % 2 ? 1 : -1);  // 0, 15, -15, 30, ..., -75, 90
      const std::array<double, 2> cs = turn_by_15_degrees(int(std::lround(angle / 15)));
      const double c = cs[0], s = cs[1];
      size_t tried = 0;
      for (size_t centre : centres) {
        // Sorted: no centre after this one fits either (a cell's clearance is within a cell).
        if (g.clearance[centre] < half_height_cells - 1) break;
        const double x = g.x0 + (double(centre % size_t(g.w)) + 0.5) * g.step;
        const double y = g.y0 + (double(centre / size_t(g.w)) + 0.5) * g.step;
        // The box's corners first, on the grid (near the edge, exactly): most centres fail there.
        bool corners = true;
        for (const double u : {-0.5, 0.5})
          for (const double v : {-0.5, 0.5}) {
            if (!corners) break;
            const double cx = x + c * u * box[0] - s * v * box[1], cy = y + s * u * box[0] + c * v * box[1];
            const int state = g.cell_state(cx, cy);
            corners = state == 1 || (state == -1 && region_covers(fit, {region_units(cx), region_units(cy)}));
          }
        if (!corners) continue;
        // The whole box, not only the strokes: a hole of the face (a drain hole) between the
        // letters would break the label up.
        ClipperLib::Path box_loop;
        for (const auto& [u, v] : {std::pair{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}})
          box_loop.push_back({region_units(x + c * u * box[0] - s * v * box[1]),
                              region_units(y + s * u * box[0] + c * v * box[1])});
        if (inside({box_loop}, fit)) {
          best = {true, x, y, angle, h, placed_region(label, x, y, cs)};
          return best;
        }
        if (++tried == kCentresTried) break;
      }
    }
  }
  return best;
}

}  // namespace slicereuse
