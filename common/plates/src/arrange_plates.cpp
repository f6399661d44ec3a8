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

void check_options(const std::vector<const Mesh*>& members, const std::vector<std::string>& names,
                   const ArrangeOptions& o) {
  if (names.size() != members.size())
    throw Error(format("arrangement: %zu names for %zu members", names.size(), members.size()));
  if (!(o.spacing_mm >= 0) || !std::isfinite(o.spacing_mm))
    throw Error(format("spacing %g mm is not a number >= 0", o.spacing_mm));
  if (!(o.cell_mm > 0) || !std::isfinite(o.cell_mm) || o.cell_mm > 10)
    throw Error(format("footprint cell size %g mm is not within (0, 10] mm", o.cell_mm));
  if (!(o.rotation_step_deg > 0) || !(o.rotation_step_deg <= 360))
    throw Error(format("rotation step %g degrees is not within (0, 360]", o.rotation_step_deg));
}

// A plate's grid of cells: the platform inside the spacing from its edges.
struct GridFrame {
  double usable_w, usable_h;  // mm
  int width, height;          // cells
  double x0, y0;              // the first cell's corner in model coordinates
};

GridFrame grid_frame(const Platform& platform, const ArrangeOptions& o) {
  GridFrame g;
  g.usable_w = platform.x1 - platform.x0 - 2 * o.spacing_mm;
  g.usable_h = platform.y1 - platform.y0 - 2 * o.spacing_mm;
  g.width = int(std::floor(g.usable_w / o.cell_mm)), g.height = int(std::floor(g.usable_h / o.cell_mm));
  if (!(g.usable_w > 0) || !(g.usable_h > 0) || g.width < 1 || g.height < 1)
    throw Error(format("the platform (%g x %g mm) leaves no room inside a spacing of %g mm from its edges",
                       platform.x1 - platform.x0, platform.y1 - platform.y0, o.spacing_mm));
  g.x0 = platform.x0 + o.spacing_mm, g.y0 = platform.y0 + o.spacing_mm;
  return g;
}

// The rotations tried, k * step for k = 0, 1, ... below 360 degrees.
std::vector<double> rotations(double step_deg) {
  std::vector<double> thetas;
  for (int k = 0; k * step_deg < 360 - 1e-9; ++k) thetas.push_back(k * step_deg);
  return thetas;
}

void check_meshes(const std::vector<const Mesh*>& members, const std::vector<std::string>& names) {
  for (size_t m = 0; m < members.size(); ++m) {
    try {
      validate_mesh(*members[m]);
    } catch (const Error& e) {
      throw Error("member '" + names[m] + "': " + e.what());
    }
  }
}

// Each member's footprint at 0 degrees (kept for its first pose) and its cells. Every member
// must fit an empty plate at some rotation, refused before anything is placed; members are
// looked at on all cores, and the first refused, in their order, is named.
struct Unturned {
  std::vector<Footprint> footprint;
  std::vector<size_t> cells;
};

Unturned unturned_footprints(const std::vector<const Mesh*>& members, const std::vector<std::string>& names,
                             const std::vector<double>& thetas, const Platform& platform, const GridFrame& grid,
                             const ArrangeOptions& o, const Progress& progress) {
  const size_t n = members.size();
  std::vector<uint8_t> fits(n, 0);
  Unturned out{std::vector<Footprint>(n), std::vector<size_t>(n)};
  parallel_blocks(
      n,
      [&](size_t m) {
        const std::vector<double> points = plan_points(*members[m]);
        for (double theta : thetas) {
          const FootprintExtent e = footprint_extent(points, theta, o.cell_mm);
          fits[m] |= e.width <= grid.width && e.height <= grid.height;
        }
        if (!fits[m]) return;
        out.footprint[m] = mesh_footprint(*members[m], points, 0, o.cell_mm);
        out.cells[m] = out.footprint[m].marked();
      },
      progress, "arranging");
  for (size_t m = 0; m < n; ++m)
    if (!fits[m]) {
      const FootprintExtent e = footprint_extent(plan_points(*members[m]), 0, o.cell_mm);
      throw Error(format("member '%s' (%.2f x %.2f mm seen from above) fits the platform at no rotation: the "
                         "platform is %.2f x %.2f mm, %.2f x %.2f mm inside the spacing of %g mm from its edges",
                         names[m].c_str(), e.size_x_mm, e.size_y_mm, platform.x1 - platform.x0,
                         platform.y1 - platform.y0, grid.usable_w, grid.usable_h, o.spacing_mm));
    }
  return out;
}

// Largest footprint first: large members find room on an empty plate, small ones fill gaps.
std::vector<size_t> largest_first(const std::vector<size_t>& cells) {
  std::vector<size_t> order(cells.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return cells[a] > cells[b]; });
  return order;
}

// How each rotation's footprint is made: a rotation a half or a quarter turn past one already
// made turns that footprint's cells instead of rasterizing the mesh again; every member's
// footprints are made in the same stages, each from the one before (stage 0: rasterized).
struct TurnSource {
  size_t from = SIZE_MAX;  // SIZE_MAX: rasterized
  bool half = false;
  size_t stage = 0;
};

struct TurnPlan {
  std::vector<TurnSource> source;                // per rotation
  std::vector<std::vector<size_t>> made_in_stage;  // rotations per stage
};

TurnPlan turn_plan(const std::vector<double>& thetas) {
  TurnPlan plan{std::vector<TurnSource>(thetas.size()), std::vector<std::vector<size_t>>(1)};
  std::vector<TurnSource>& source = plan.source;
  for (size_t k = 0; k < thetas.size(); ++k) {
    for (size_t r = 0; r < k && source[k].from == SIZE_MAX; ++r)
      for (const bool half : {true, false})
        if (source[k].from == SIZE_MAX && thetas[k] == thetas[r] + (half ? 180 : 90))
          source[k] = {r, half, source[r].stage + 1};
    if (source[k].stage == plan.made_in_stage.size()) plan.made_in_stage.emplace_back();
    plan.made_in_stage[source[k].stage].push_back(k);
  }
  return plan;
}

// A member's poses at every rotation that fits an empty plate (the others are no candidates
// anywhere), made stage by stage as the plan says.
std::vector<Pose> member_poses(const Mesh& member, Footprint unturned, const std::vector<double>& thetas,
                               const TurnPlan& plan, const GridFrame& grid, const ArrangeOptions& o,
                               const Progress& progress) {
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
  const std::vector<double> points = plan_points(member);
  const size_t stages = plan.made_in_stage.size();
  for (size_t stage = 0; stage < stages; ++stage) {
    const std::vector<size_t>& made = plan.made_in_stage[stage];
    parallel_blocks(
        made.size(),
        [&](size_t i) {
          const size_t k = made[i];
          const TurnSource& from = plan.source[k];
          poses[k].footprint = thetas[k] == 0         ? std::move(unturned)
                               : from.from == SIZE_MAX ? mesh_footprint(member, points, thetas[k], o.cell_mm)
                               : from.half             ? half_turn_footprint(poses[from.from].footprint)
                                                       : quarter_turn_footprint(poses[from.from].footprint);
          pose(k);
        },
        sub_progress(progress, double(stage) / double(stages), double(stage + 1) / double(stages)), "arranging");
  }
  auto too_large = [&](const Pose& p) { return p.footprint.width > grid.width || p.footprint.height > grid.height; };
  poses.erase(std::remove_if(poses.begin(), poses.end(), too_large), poses.end());
  return poses;
}

// Where a member goes: the first plate with room for one of its poses, else a new plate;
// `plate` receives the plate's index, and the plate holds the member's cells.
Spot place_member(std::vector<PlateGrid>& plates, const std::vector<Pose>& poses, const GridFrame& grid,
                  const std::string& name, size_t& plate) {
  Spot spot;
  size_t k = 0;
  for (; k < plates.size(); ++k)
    if ((spot = best_spot(plates[k], poses)).found()) break;
  if (!spot.found()) {
    plates.emplace_back(grid.width, grid.height);
    spot = best_spot(plates[k], poses);
    if (!spot.found()) throw Error(format("member '%s' found no place on an empty plate", name.c_str()));
  }
  plates[k].hold(poses[spot.pose], spot.x, spot.y);
  plate = k;
  return spot;
}

}  // namespace

Platform printer_platform(const PrinterProfile& p) {
  validate_printer_profile(p);
  const double half_w = p.width_px * p.pixel_size_x_um / 2000, half_h = p.height_px * p.pixel_size_y_um / 2000;
  return {-half_w - p.offset_x_mm, -half_h - p.offset_y_mm, half_w - p.offset_x_mm, half_h - p.offset_y_mm};
}

Arrangement arrange_plates(const std::vector<const Mesh*>& members, const std::vector<std::string>& names,
                           const Platform& platform, const ArrangeOptions& o, const Progress& progress) {
  check_options(members, names, o);
  const GridFrame grid = grid_frame(platform, o);
  const std::vector<double> thetas = rotations(o.rotation_step_deg);
  check_meshes(members, names);
  Unturned unturned = unturned_footprints(members, names, thetas, platform, grid, o, sub_progress(progress, 0, 0.1));
  const std::vector<size_t> order = largest_first(unturned.cells);
  const TurnPlan plan = turn_plan(thetas);

  const size_t n = members.size();
  Arrangement out;
  out.placement.resize(n);
  out.plate.resize(n);
  std::vector<PlateGrid> plates;
  for (size_t done = 0; done < n; ++done) {
    const size_t m = order[done];
    const Progress member_progress =
        sub_progress(progress, 0.1 + 0.9 * double(done) / double(n), 0.1 + 0.9 * double(done + 1) / double(n));
    const std::vector<Pose> poses =
        member_poses(*members[m], std::move(unturned.footprint[m]), thetas, plan, grid, o, member_progress);
    size_t k = 0;
    const Spot spot = place_member(plates, poses, grid, names[m], k);
    if (k == out.members.size()) out.members.emplace_back();
    const Pose& p = poses[spot.pose];
    out.placement[m] = {p.theta_deg, grid.x0 + spot.x * o.cell_mm - p.footprint.x0,
                        grid.y0 + spot.y * o.cell_mm - p.footprint.y0};
    out.plate[m] = k;
    out.members[k].push_back(m);
  }
  const double platform_area = (platform.x1 - platform.x0) * (platform.y1 - platform.y0);
  for (const PlateGrid& g : plates) out.area_used.push_back(double(g.cells) * o.cell_mm * o.cell_mm / platform_area);
  return out;
}

}  // namespace slicereuse
