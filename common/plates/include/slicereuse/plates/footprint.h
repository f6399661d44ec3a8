#pragma once
// Footprint: where a member touches the build plate seen from above, as cells of a square grid.
//
// mesh_footprint(mesh, theta_deg, cell_mm): the mesh turned by theta_deg about z (turn_of,
// placement.h), its triangles projected onto x-y, and every grid cell that a projected triangle
// touches marked: conservative, so every point of the projection lies in a marked cell (the
// outline of the union of the triangles, holes and concave bays kept, not a bounding box). A
// triangle within 2 x 2 cells marks its bounding box's cells (at most one cell more than it
// touches; most triangles of a fine mesh, which then cost no clipping).
// Cell (i, j) covers [x0 + i cell, x0 + (i+1) cell] x [y0 + j cell, y0 + (j+1) cell], row-major
// in cells[j * width + i]; (x0, y0) lies kFootprintSlack_mm below the turned mesh's smallest x
// and y (at least that: half_turn_footprint, quarter_turn_footprint), and the slack is also
// added around every triangle, so that the placed mesh (turned and moved, whose coordinates
// round differently by some 1e-13 mm) stays inside the cells too.
// half_turn_footprint(f): the footprint of the same mesh turned 180 degrees further, without
// rasterizing it again: the cells point-reflected, on the reflected grid (its (x0, y0) is the
// reflection of f's far corner, so it lies at or below the turned mesh's smallest x and y by at
// least the slack). Turned again by turn_of(theta + 180), the mesh's coordinates differ from the
// reflected ones by rounding only (some 1e-16 of the coordinates), well inside the slack.
// quarter_turn_footprint(f): likewise 90 degrees further (counter-clockwise, as turn_of): a
// point (x, y) goes to (-y, x), so cell (i, j) becomes cell (height-1-j, i) of a grid height
// cells wide, whose (x0, y0) = (-(f's top edge), f.x0) lies at or below the turned mesh's
// smallest x and y by at least the slack.
// plan_points(mesh): the x and y of the vertices the mesh's faces use (2 numbers per vertex,
// each vertex once; an unused vertex is not on the plate), over which a turned mesh's extent is
// taken: made once per member, for its footprints and extents at every turn.
// footprint_extent: the grid's width and height in cells alone, from the plan points (what
// mesh_footprint would give), for the fit checks that need no cells.
// dilate_footprint(f, spacing_mm): the cells whose box comes closer than spacing_mm to a box of a
// marked cell (box distance from the cell offsets, exact), on a grid grown by `margin` cells on
// every side (x0 and y0 moved accordingly). A cell of another footprint on the same grid that
// is not marked in the dilation is therefore >= spacing_mm away from every marked cell, and so
// are the triangles inside them.
// Throws Error for a mesh without faces or a cell size that is not positive and finite.
#include <cstdint>
#include <vector>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

constexpr double kFootprintSlack_mm = 1e-6;

struct Footprint {
  double x0 = 0, y0 = 0, cell = 0;
  int width = 0, height = 0;
  int margin = 0;               // cells added on each side by dilate_footprint, else 0
  std::vector<uint8_t> cells;   // width * height, 1 = marked
  size_t marked() const;
};

struct FootprintExtent {
  int width = 0, height = 0;
  double size_x_mm = 0, size_y_mm = 0;  // the turned mesh's extent
};

std::vector<double> plan_points(const Mesh& mesh);

FootprintExtent footprint_extent(const std::vector<double>& plan_points, double theta_deg, double cell_mm);

// plan_points: those of the mesh (plan_points(mesh) when not given).
Footprint mesh_footprint(const Mesh& mesh, double theta_deg, double cell_mm);
Footprint mesh_footprint(const Mesh& mesh, const std::vector<double>& plan_points, double theta_deg, double cell_mm);

Footprint half_turn_footprint(const Footprint& f);

Footprint quarter_turn_footprint(const Footprint& f);

Footprint dilate_footprint(const Footprint& f, double spacing_mm);

}  // namespace slicereuse
