#pragma once
// Placement: where a member sits on a build plate. The member is turned by theta_deg degrees
// about the z axis (counter-clockwise seen from +z, about the model origin), then moved by
// (tx_mm, ty_mm) in x-y; z is untouched, so every vertex keeps its height and the member its
// layers.
//
// place_mesh: the member with its placement applied to its vertices (faces unchanged). The
// placement is applied to the vertices, never to contour points after slicing: a vertex's z,
// hence which edges cross which planes and at which parameter t, does not change, so a
// transfer onto the placed vertices gives exactly the points direct slicing of the placed
// member gives (the same arithmetic on the same numbers).
// turn_xy: the rotation alone, (x, y) -> (c x - s y, s x + c y); the one place its arithmetic is
// written, so footprints (footprint.h) and placed meshes agree. Multiples of 90 degrees turn
// exactly (cos and sin exactly 0 or +-1).
#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

struct Placement {
  double theta_deg = 0;
  double tx_mm = 0;
  double ty_mm = 0;
};

struct Turn {
  double c = 1, s = 0;
  void apply(double x, double y, double& ox, double& oy) const {
    ox = c * x - s * y;
    oy = s * x + c * y;
  }
};

Turn turn_of(double theta_deg);

Mesh place_mesh(const Mesh& mesh, const Placement& placement);

}  // namespace slicereuse
