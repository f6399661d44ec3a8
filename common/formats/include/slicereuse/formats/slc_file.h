#pragma once
// SLC (3D Systems' SLiCe format, -SLCVER 2.0) contour export; docs/formats.md ("SLC") gives the
// layout byte by byte and the choices made where the specification leaves room.
//
// In: validated Slices with xyz (millimetres). Out: the file, written atomically, and how many
// open contours were left out: SLC has closed boundaries only. Each closed contour becomes one
// boundary, in the stored point order (outer loops counter-clockwise, holes clockwise, as SLC
// requires and slicereuse slices already are), with its first point repeated at the end, x and
// y as float32. Layer k is stored at the bottom of its slab, layer_z[k] - thickness/2.
// Throws Error naming the path (and the layer) on a coordinate too large for float32, on more
// points than SLC can count, or when the file cannot be written.
#include <cstddef>
#include <string>

#include "slicereuse/slicing/slices.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

struct SlcExportStats {
  size_t boundaries = 0;            // closed contours written
  size_t skipped_open_contours = 0; // open contours left out
};

SlcExportStats write_slc_file(const std::string& path, const Slices& s,
                              const Progress& progress = {});

}  // namespace slicereuse
