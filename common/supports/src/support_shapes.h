#pragma once
// support_shapes: the closed shells the support structure is made of, appended to one mesh.
// Every shell is a loft between two convex polygons given counter-clockwise seen from +z, with
// the same number of corners (corner i of one above corner i of the other): side quads and
// fanned caps, faces counter-clockwise seen from outside, so each shell is closed and
// outward-oriented on its own (shells may overlap; the masks' nonzero rule fills their union).
#include <array>
#include <vector>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

// Corners of every cone and cylinder. The masks' pixel is 0.05 mm: a 16-gon inscribed in a
// circle of radius 0.5 mm (a pillar) lies within 0.5 * (1 - cos(pi/16)) < 0.01 mm of it.
constexpr int kSupportSides = 16;

using Outline = std::vector<std::array<double, 2>>;

// The regular kSupportSides-gon inscribed in the circle of radius r around (x, y), corner 0 at
// angle 0, counter-clockwise.
Outline circle_outline(double x, double y, double r);

// The kSupportSides-gon inscribed in the horizontal section of the cylinder of radius r around an
// axis through (x, y) along (dx, dy, dz), dz != 0: an ellipse, r across the axis and r |d| / |dz|
// along it (corner 0 ahead along (dx, dy)), counter-clockwise; a circle for a vertical axis.
Outline section_outline(double x, double y, double r, double dx, double dy, double dz);

// Appends the loft from bottom at z_bottom to top at z_top (z_bottom < z_top, equal sizes >= 3).
void append_loft(Mesh& mesh, const Outline& bottom, double z_bottom, const Outline& top, double z_top);

// A vertical cone frustum (or cylinder) around (x, y): radius r_bottom at z_bottom, r_top at z_top.
void append_frustum(Mesh& mesh, double x, double y, double z_bottom, double r_bottom, double z_top, double r_top);

}  // namespace slicereuse
