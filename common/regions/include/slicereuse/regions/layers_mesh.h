#pragma once
// layers_mesh: layered regions as a triangle mesh, to look at: layer k's region (Clipper
// polygons, kRegionScale units per mm) as a slab from z_start + k h to z_start + (k + 1) h, its
// walls one quad per loop edge and its faces the region's triangles (region_triangles.h), every
// face counter-clockwise seen from outside. Each slab is closed on its own (slabs touch, not
// merged), so the mesh's volume is the layers' areas times h.
#include <clipper.hpp>

#include <vector>

#include "slicereuse/mesh/mesh.h"

namespace slicereuse {

Mesh layers_mesh(const std::vector<ClipperLib::Paths>& layers, double z_start, double thickness);

}  // namespace slicereuse
