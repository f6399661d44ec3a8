#include "slicereuse/plates/arrange_plates.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

#include "slicereuse/plates/footprint.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse {
namespace {

// A member's footprint at one rotation, as its plate test needs it: the footprint's marked runs
// per row (to mark the plate) and its dilation's runs per row (to test a position).
struct Runs {
  std::vector<uint32_t> row_begin;  // height + 1
  std::vector<int> lo, hi;          // run i covers columns [lo[i], hi[i]]
};

Runs runs_of(const Footprint& f) {
  Runs r;
  r.row_begin.push_back(0);
  for (int j = 0; j < f.height; ++j) {
    const uint8_t* row = f.cells.data() + size_t(j) * f.width;
    for (int i = 0; i < f.width;) {
      if (!row[i]) {
        ++i;
        continue;
      }
      int e = i;
      while (e + 1 < f.width && row[e + 1]) ++e;
      r.lo.push_back(i);
      r.hi.push_back(e);
      i = e + 1;
    }
    r.row_begin.push_back(uint32_t(r.lo.size()));
  }
  return r;
}

struct Pose {
  double theta_deg;
  Footprint footprint;  // its x0, y0 place it
  Runs marked, near;    // runs of the footprint and of its dilation (margin cells larger each side)
  int margin;
  size_t cells;
};

// A plate's grid: which cells members' footprints hold, and per row the last held column at or
// before each column (-1: none), so that a test finds a conflict and the next position that
// could clear it in one look-up per run.
struct PlateGrid {
  int width, height;
  std::vector<int> last_held;  // width * height
  size_t cells = 0;

  PlateGrid(int w, int h) : width(w), height(h), last_held(size_t(w) * size_t(h), -1) {}

  // The smallest x' >= x at which pose could sit in row y without conflict from the runs tested
  // so far: x itself when it is free. Rows are tested from *start_row on, wrapping around, and
  // *start_row is left at the row that conflicted: the next position usually conflicts there too.
  int first_free_from(const Pose& p, int x, int y, int* start_row) const {
    const int m = p.margin, rows = int(p.near.row_begin.size()) - 1;
    for (int n = 0; n < rows; ++n) {
      const int dj = (*start_row + n) % rows;
      const int row = y - m + dj;
      if (row < 0 || row >= height) continue;
      const int* held = last_held.data() + size_t(row) * width;
      for (uint32_t r = p.near.row_begin[size_t(dj)]; r < p.near.row_begin[size_t(dj) + 1]; ++r) {
        const int lo = std::max(0, x - m + p.near.lo[r]), hi = std::min(width - 1, x - m + p.near.hi[r]);
        if (lo > hi) continue;
        const int q = held[hi];
        if (q >= lo) {
          *start_row = dj;
          return q - (p.near.lo[r] - m) + 1;  // the run starts past q from there on
        }
      }
    }
    return x;
  }

  void hold(const Pose& p, int x, int y) {
    for (int j = 0; j + 1 < int(p.marked.row_begin.size()); ++j) {
      int* held = last_held.data() + size_t(y + j) * width;
      for (uint32_t r = p.marked.row_begin[size_t(j)]; r < p.marked.row_begin[size_t(j) + 1]; ++r)
        for (int i = x + p.marked.lo[r]; i <= x + p.marked.hi[r]; ++i) held[i] = i;
      for (int i = 1; i < width; ++i) held[i] = std::max(held[i], held[i - 1]);
    }
    cells += p.cells;
  }
};

struct Spot {
  int x = -1, y = -1;
  size_t pose = 0;
  bool found() const { return x >= 0; }
};

// The bottom-left-most free position of any pose on the grid: lowest top edge, then lowest
// right edge, then the first pose.
Spot best_spot(const PlateGrid& g, const std::vector<Pose>& poses) {
  Spot best;
  int best_top = INT32_MAX, best_right = INT32_MAX;
  for (size_t k = 0; k < poses.size(); ++k) {
    const Pose& p = poses[k];
    const int w = p.footprint.width, h = p.footprint.height;
    // A plate whose free cells are fewer than the footprint's has no room for it.
    if (size_t(g.width) * size_t(g.height) - g.cells < p.cells) continue;
    int start_row = 0;
    for (int y = 0; y + h <= g.height && y + h <= best_top; ++y) {
      int x = 0;
      while (x + w <= g.width) {
        const int next = g.first_free_from(p, x, y, &start_row);
        if (next == x) break;
        x = next;
      }
      if (x + w > g.width) continue;
      if (y + h < best_top || x + w < best_right) {
        best = {x, y, k};
        best_top = y + h;
        best_right = x + w;
      }
      break;  // higher rows only raise the top edge
    }
  }
  return best;
}

}  // namespace

Platform printer_platform(const PrinterProfile& p) {
  validate_printer_profile(p);
  const double half_w = p.width_px * p.pixel_size_x_um / 2000, half_h = p.height_px * p.pixel_size_y_um / 2000;
  return {-half_w - p.offset_x_mm, -half_h - p.offset_y_mm, half_w - p.offset_x_mm, half_h - p.offset_y_mm};
}

Arrangement arrange_plates(const std::vector<const Mesh*>& members, const std::vector<std::string>& names,
                           const Platform& platform, const ArrangeOptions& o, const Progress& progress) {
  if (names.size() != members.size())
    throw Error(format("arrangement: %zu names for %zu members", names.size(), members.size()));
  if (!(o.spacing_mm >= 0) || !std::isfinite(o.spacing_mm))
    throw Error(format("spacing %g mm is not a number >= 0", o.spacing_mm));
  if (!(o.cell_mm > 0) || !std::isfinite(o.cell_mm) || o.cell_mm > 10)
    throw Error(format("footprint cell size %g mm is not within (0, 10] mm", o.cell_mm));
  if (!(o.rotation_step_deg > 0) || !(o.rotation_step_deg <= 360))
    throw Error(format("rotation step %g degrees is not within (0, 360]", o.rotation_step_deg));
  const double usable_w = platform.x1 - platform.x0 - 2 * o.spacing_mm;
  const double usable_h = platform.y1 - platform.y0 - 2 * o.spacing_mm;
  const int grid_w = int(std::floor(usable_w / o.cell_mm)), grid_h = int(std::floor(usable_h / o.cell_mm));
  if (!(usable_w > 0) || !(usable_h > 0) || grid_w < 1 || grid_h < 1)
    throw Error(format("the platform (%g x %g mm) leaves no room inside a spacing of %g mm from its edges",
                       platform.x1 - platform.x0, platform.y1 - platform.y0, o.spacing_mm));
  const double gx = platform.x0 + o.spacing_mm, gy = platform.y0 + o.spacing_mm;
  std::vector<double> thetas;
  for (int k = 0; k * o.rotation_step_deg < 360 - 1e-9; ++k) thetas.push_back(k * o.rotation_step_deg);

  // Every member must be a mesh and fit an empty plate at some rotation; refused before
  // anything is placed. Members are looked at on all cores; the first refused, in their order,
  // is named.
  const size_t n = members.size();
  for (size_t m = 0; m < n; ++m) {
    try {
      validate_mesh(*members[m]);
    } catch (const Error& e) {
      throw Error("member '" + names[m] + "': " + e.what());
    }
  }
  std::vector<uint8_t> fits(n, 0);
  std::vector<Footprint> unturned(n);  // each member's footprint at 0 degrees, kept for its first pose
  std::vector<size_t> area(n);         // its cells
  const Progress checking = sub_progress(progress, 0, 0.1);
  parallel_blocks(
      n,
      [&](size_t m) {
        const std::vector<double> points = plan_points(*members[m]);
        for (double theta : thetas) {
          const FootprintExtent e = footprint_extent(points, theta, o.cell_mm);
          fits[m] |= e.width <= grid_w && e.height <= grid_h;
        }
        if (!fits[m]) return;
        unturned[m] = mesh_footprint(*members[m], points, 0, o.cell_mm);
        area[m] = unturned[m].marked();
      },
      checking, "arranging");
  for (size_t m = 0; m < n; ++m)
    if (!fits[m]) {
      const FootprintExtent e = footprint_extent(plan_points(*members[m]), 0, o.cell_mm);
      throw Error(format("member '%s' (%.2f x %.2f mm seen from above) fits the platform at no rotation: the "
                         "platform is %.2f x %.2f mm, %.2f x %.2f mm inside the spacing of %g mm from its edges",
                         names[m].c_str(), e.size_x_mm, e.size_y_mm, platform.x1 - platform.x0,
                         platform.y1 - platform.y0, usable_w, usable_h, o.spacing_mm));
    }

  // Largest footprint first: large members find room on an empty plate, small ones fill gaps.
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return area[a] > area[b]; });

  // A rotation a half or a quarter turn past one already made turns that footprint's cells
  // instead of rasterizing the mesh again; every member's footprints are made in the same
  // stages, each from the one before (stage 0: rasterized).
  struct Source {
    size_t from = SIZE_MAX;  // SIZE_MAX: rasterized
    bool half = false;
    size_t stage = 0;
  };
  std::vector<Source> source(thetas.size());
  std::vector<std::vector<size_t>> made_in_stage(1);
  for (size_t k = 0; k < thetas.size(); ++k) {
    for (size_t r = 0; r < k && source[k].from == SIZE_MAX; ++r)
      for (const bool half : {true, false})
        if (source[k].from == SIZE_MAX && thetas[k] == thetas[r] + (half ? 180 : 90))
          source[k] = {r, half, source[r].stage + 1};
    if (source[k].stage == made_in_stage.size()) made_in_stage.emplace_back();
    made_in_stage[source[k].stage].push_back(k);
  }

  Arrangement out;
  out.placement.resize(n);
  out.plate.resize(n);
  std::vector<PlateGrid> plates;
  for (size_t done = 0; done < n; ++done) {
    const size_t m = order[done];
    std::vector<Pose> poses(thetas.size());
    auto pose = [&](size_t k) {
      Pose& p = poses[k];
      p.theta_deg = thetas[k];
      const Footprint near = dilate_footprint(p.footprint, o.spacing_mm);
      p.marked = runs_of(p.footprint);
      p.near = runs_of(near);
      p.margin = near.margin;
      p.cells = p.footprint.marked();
    };
    const Progress member_progress =
        sub_progress(progress, 0.1 + 0.9 * double(done) / double(n), 0.1 + 0.9 * double(done + 1) / double(n));
    const std::vector<double> points = plan_points(*members[m]);
    for (size_t stage = 0; stage < made_in_stage.size(); ++stage) {
      const std::vector<size_t>& made = made_in_stage[stage];
      parallel_blocks(
          made.size(),
          [&](size_t i) {
            const size_t k = made[i];
            const Source& from = source[k];
            poses[k].footprint = thetas[k] == 0         ? std::move(unturned[m])
                                 : from.from == SIZE_MAX ? mesh_footprint(*members[m], points, thetas[k], o.cell_mm)
                                 : from.half             ? half_turn_footprint(poses[from.from].footprint)
                                                         : quarter_turn_footprint(poses[from.from].footprint);
            pose(k);
          },
          sub_progress(member_progress, double(stage) / double(made_in_stage.size()),
                       double(stage + 1) / double(made_in_stage.size())),
          "arranging");
    }
    // Poses that cannot fit an empty plate are no candidates anywhere.
    poses.erase(std::remove_if(poses.begin(), poses.end(),
                               [&](const Pose& p) { return p.footprint.width > grid_w || p.footprint.height > grid_h; }),
                poses.end());
    Spot spot;
    size_t k = 0;
    for (; k < plates.size(); ++k)
      if ((spot = best_spot(plates[k], poses)).found()) break;
    if (!spot.found()) {
      plates.emplace_back(grid_w, grid_h);
      out.members.emplace_back();
      spot = best_spot(plates[k], poses);
      if (!spot.found()) throw Error(format("member '%s' found no place on an empty plate", names[m].c_str()));
    }
    const Pose& p = poses[spot.pose];
    plates[k].hold(p, spot.x, spot.y);
    out.placement[m] = {p.theta_deg, gx + spot.x * o.cell_mm - p.footprint.x0, gy + spot.y * o.cell_mm - p.footprint.y0};
    out.plate[m] = k;
    out.members[k].push_back(m);
  }
  const double platform_area = (platform.x1 - platform.x0) * (platform.y1 - platform.y0);
  for (const PlateGrid& g : plates) out.area_used.push_back(double(g.cells) * o.cell_mm * o.cell_mm / platform_area);
  return out;
}

}  // namespace slicereuse
