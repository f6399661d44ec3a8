#include "slicereuse/plates/footprint.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "slicereuse/plates/placement.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {
namespace {

void check_cell(double cell_mm) {
  if (!(cell_mm > 0) || !std::isfinite(cell_mm))
    throw Error(format("footprint cell size %g mm is not a positive number", cell_mm));
}

// The turned vertices' x and y (2 per vertex, every vertex: the triangles index them) and the
// extent of the turned plan points (the vertices that faces use), the same numbers turned alike.
struct Turned {
  std::vector<double> xy;
  double min_x = std::numeric_limits<double>::infinity(), min_y = min_x, max_x = -min_x, max_y = -min_x;
};

void take_extent(const std::vector<double>& plan_points, const Turn& turn, Turned& t) {
  for (size_t i = 0; i + 1 < plan_points.size(); i += 2) {
    double x, y;
    turn.apply(plan_points[i], plan_points[i + 1], x, y);
    t.min_x = std::min(t.min_x, x);
    t.max_x = std::max(t.max_x, x);
    t.min_y = std::min(t.min_y, y);
    t.max_y = std::max(t.max_y, y);
  }
}

void check_plan_points(const std::vector<double>& plan_points) {
  if (plan_points.empty()) throw Error("a footprint needs a mesh with faces");
}

Turned turned_vertices(const Mesh& mesh, const std::vector<double>& plan_points, double theta_deg) {
  check_plan_points(plan_points);
  const Turn turn = turn_of(theta_deg);
  Turned t;
  t.xy.resize(2 * mesh.vertices());
  for (size_t i = 0; i < mesh.vertices(); ++i) turn.apply(mesh.V[3 * i], mesh.V[3 * i + 1], t.xy[2 * i], t.xy[2 * i + 1]);
  take_extent(plan_points, turn, t);
  return t;
}

int cells_over(double from, double to, double cell) { return int(std::floor((to - from) / cell)) + 1; }

FootprintExtent extent_of(const Turned& t, double cell) {
  const double x0 = t.min_x - kFootprintSlack_mm, y0 = t.min_y - kFootprintSlack_mm;
  return {cells_over(x0, t.max_x + kFootprintSlack_mm, cell), cells_over(y0, t.max_y + kFootprintSlack_mm, cell),
          t.max_x - t.min_x, t.max_y - t.min_y};
}

}  // namespace

size_t Footprint::marked() const { return size_t(std::count(cells.begin(), cells.end(), uint8_t(1))); }

std::vector<double> plan_points(const Mesh& mesh) {
  std::vector<uint8_t> used(mesh.vertices(), 0);
  for (uint32_t v : mesh.F) used[v] = 1;
  std::vector<double> xy;
  for (size_t v = 0; v < mesh.vertices(); ++v)
    if (used[v]) xy.insert(xy.end(), {mesh.V[3 * v], mesh.V[3 * v + 1]});
  check_plan_points(xy);  // none without faces
  return xy;
}

FootprintExtent footprint_extent(const std::vector<double>& plan_points, double theta_deg, double cell_mm) {
  check_cell(cell_mm);
  check_plan_points(plan_points);
  Turned t;
  take_extent(plan_points, turn_of(theta_deg), t);
  return extent_of(t, cell_mm);
}

Footprint mesh_footprint(const Mesh& mesh, double theta_deg, double cell_mm) {
  return mesh_footprint(mesh, plan_points(mesh), theta_deg, cell_mm);
}

Footprint mesh_footprint(const Mesh& mesh, const std::vector<double>& plan_points, double theta_deg, double cell_mm) {
  check_cell(cell_mm);
  const Turned t = turned_vertices(mesh, plan_points, theta_deg);
  const FootprintExtent e = extent_of(t, cell_mm);
  Footprint f;
  f.cell = cell_mm;
  f.x0 = t.min_x - kFootprintSlack_mm;
  f.y0 = t.min_y - kFootprintSlack_mm;
  f.width = e.width;
  f.height = e.height;
  f.cells.assign(size_t(f.width) * size_t(f.height), 0);
  const double slack = kFootprintSlack_mm;
  // The cell of a coordinate: by the reciprocal, whose rounding (some 1e-14 of a cell) is far
  // inside the slack; truncation is the floor here, since below 0 both clamp to 0.
  const double per_mm = 1 / cell_mm;
  auto column = [&](double x) { return std::clamp(int((x - f.x0) * per_mm), 0, f.width - 1); };
  auto row = [&](double y) { return std::clamp(int((y - f.y0) * per_mm), 0, f.height - 1); };
  // Each vertex's cells with the slack either side, once: a triangle's box in cells is then the
  // least and greatest of its corners' (column and row are monotone), with no arithmetic per
  // corner, and a vertex is a corner of about six triangles.
  struct CellBox {
    int i0, i1, j0, j1;
  };
  std::vector<CellBox> box(mesh.vertices());
  for (size_t v = 0; v < box.size(); ++v) {
    const double x = t.xy[2 * v], y = t.xy[2 * v + 1];
    box[v] = {column(x - slack), column(x + slack), row(y - slack), row(y + slack)};
  }
  for (size_t tri = 0; tri < mesh.faces(); ++tri) {
    const CellBox& a = box[mesh.F[3 * tri]];
    const CellBox& b = box[mesh.F[3 * tri + 1]];
    const CellBox& c = box[mesh.F[3 * tri + 2]];
    const int i0 = std::min({a.i0, b.i0, c.i0}), i1 = std::max({a.i1, b.i1, c.i1});
    const int j0 = std::min({a.j0, b.j0, c.j0}), j1 = std::max({a.j1, b.j1, c.j1});
    if (j1 - j0 <= 1 && i1 - i0 <= 1) {
      // Within 2 x 2 cells (most triangles of a fine mesh): the cells of its bounding box, at
      // most one cell more than it touches, instead of clipping it to each row.
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) f.cells[size_t(j) * f.width + i] = 1;
      continue;
    }
    double px[3], py[3];
    for (int k = 0; k < 3; ++k) {
      px[k] = t.xy[2 * mesh.F[3 * tri + k]];
      py[k] = t.xy[2 * mesh.F[3 * tri + k] + 1];
    }
    for (int j = j0; j <= j1; ++j) {
      // The triangle's x extent within the row's band: its corners inside the band and its
      // edges' crossings of the band's two lines (the band clip of a convex polygon).
      const double band_lo = f.y0 + j * cell_mm - slack, band_hi = f.y0 + (j + 1) * cell_mm + slack;
      double lo_x = std::numeric_limits<double>::infinity(), hi_x = -lo_x;
      auto take = [&](double x) {
        lo_x = std::min(lo_x, x);
        hi_x = std::max(hi_x, x);
      };
      for (int c = 0; c < 3; ++c) {
        if (py[c] >= band_lo && py[c] <= band_hi) take(px[c]);
        const int d = (c + 1) % 3;
        if (py[c] == py[d]) continue;
        for (double line : {band_lo, band_hi}) {
          const double u = (line - py[c]) / (py[d] - py[c]);
          if (u > 0 && u < 1) take(px[c] + u * (px[d] - px[c]));
        }
      }
      if (!(lo_x <= hi_x)) continue;
      const int i0 = column(lo_x - slack), i1 = column(hi_x + slack);
      std::fill(f.cells.begin() + long(j) * f.width + i0, f.cells.begin() + long(j) * f.width + i1 + 1, 1);
    }
  }
  return f;
}

Footprint half_turn_footprint(const Footprint& f) {
  Footprint h = f;
  h.x0 = -(f.x0 + f.width * f.cell);
  h.y0 = -(f.y0 + f.height * f.cell);
  std::reverse(h.cells.begin(), h.cells.end());  // (i, j) -> (width-1-i, height-1-j)
  return h;
}

Footprint quarter_turn_footprint(const Footprint& f) {
  Footprint q;
  q.cell = f.cell;
  q.margin = f.margin;
  q.width = f.height;
  q.height = f.width;
  q.x0 = -(f.y0 + f.height * f.cell);
  q.y0 = f.x0;
  q.cells.assign(f.cells.size(), 0);
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i)
      q.cells[size_t(i) * q.width + size_t(f.height - 1 - j)] = f.cells[size_t(j) * f.width + i];
  return q;
}

Footprint dilate_footprint(const Footprint& f, double spacing_mm) {
  if (!(spacing_mm >= 0) || !std::isfinite(spacing_mm))
    throw Error(format("spacing %g mm is not a number >= 0", spacing_mm));
  // Two cells di, dj apart have boxes max(0, |di| - 1) and max(0, |dj| - 1) cells apart.
  auto gap = [&](int d) { return std::max(0, std::abs(d) - 1) * f.cell; };
  auto near = [&](int di, int dj) {
    return (di == 0 && dj == 0) || gap(di) * gap(di) + gap(dj) * gap(dj) < spacing_mm * spacing_mm;
  };
  int m = 0;
  while (near(m + 1, 0)) ++m;
  // reach[dj]: how far along a row cells dj rows away are near.
  std::vector<int> reach(size_t(m) + 1);
  for (int dj = 0; dj <= m; ++dj) {
    int r = -1;
    while (near(r + 1, dj)) ++r;
    reach[size_t(dj)] = r;
  }
  Footprint d;
  d.cell = f.cell;
  d.margin = m;
  d.x0 = f.x0 - m * f.cell;
  d.y0 = f.y0 - m * f.cell;
  d.width = f.width + 2 * m;
  d.height = f.height + 2 * m;
  d.cells.assign(size_t(d.width) * size_t(d.height), 0);
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i) {
      // A marked cell whose four neighbours are marked adds nothing (with m >= 1): an offset
      // near it is as near one of them, one cell closer. Most of a footprint's cells are such.
      if (!f.cells[size_t(j) * f.width + i] ||
          (m > 0 && i > 0 && i + 1 < f.width && f.cells[size_t(j) * f.width + i - 1] && f.cells[size_t(j) * f.width + i + 1] &&
           j > 0 && j + 1 < f.height && f.cells[size_t(j - 1) * f.width + i] && f.cells[size_t(j + 1) * f.width + i]))
        continue;
      for (int dj = -m; dj <= m; ++dj) {
        const int r = reach[size_t(std::abs(dj))];
        if (r < 0) continue;
        uint8_t* row = d.cells.data() + size_t(j + m + dj) * d.width;
        std::fill(row + (i + m - r), row + (i + m + r + 1), 1);
      }
    }
  return d;
}

}  // namespace slicereuse
