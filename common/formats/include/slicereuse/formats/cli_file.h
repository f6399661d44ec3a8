#pragma once
// CLI (Common Layer Interface, version 2.0) contour files for additive-manufacturing software,
// ASCII or binary (long format). docs/formats.md ("CLI") gives the layout and every choice made
// where the CLI specification leaves room.
//
// write_cli_file: in: validated Slices with xyz (z of a point is its layer's z in CLI; points'
// own z are not written). Out: the file, written atomically; units are millimetres
// ($$UNITS/1). Closed contours are polylines that repeat their first point at the end, with
// direction 1 (counter-clockwise, external) when their signed area is positive, else 0
// (clockwise, internal); open contours have direction 2. ASCII prints each double in its
// shortest round-trip form (an exact round trip); binary stores float32 (rounded to nearest).
//
// read_cli_file: in: a CLI file, ASCII or binary (long or short format), from any program.
// Out: Slices with xyz in millimetres (coordinates times $$UNITS), z of every point = its
// layer's z, contour_open = (direction 2), closed polylines without their repeated last point,
// thickness = the mean layer spacing (1 when there are fewer than 2 layers) and z_start = first
// layer's z - thickness/2. Hatches are skipped (they are infill, not contours). Throws Error
// naming the file, the byte offset or line, and the problem (truncated, counts the file cannot
// hold, NaN/Inf, an unknown command, layers not ascending, $$LAYERS disagreeing). Counts are
// checked against the bytes actually present before anything is allocated for them.
#include <string>

#include "slicereuse/slicing/slices.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

enum class CliEncoding { Ascii = 0, Binary = 1 };

void write_cli_file(const std::string& path, const Slices& s, CliEncoding encoding,
                    const Progress& progress = {});

Slices read_cli_file(const std::string& path, const Progress& progress = {});

}  // namespace slicereuse
