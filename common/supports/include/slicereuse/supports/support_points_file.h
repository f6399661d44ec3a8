#pragma once
// The support-points file (.srp, docs/formats.md "Support-points file"): a text file a user can
// read and a script can write, one point per line in the encoding's own terms (face id and area
// coordinates) plus position, normal, kind and layer, under a header naming the mesh's
// fingerprint:
//   slicereuse support points 1
//   mesh <faces> <hash, 16 hex digits>
//   points <P>
//   <face> <b0> <b1> <b2> <x> <y> <z> <nx> <ny> <nz> <kind> <layer>     (P lines)
// Numbers are written with 17 significant digits, so a file read back gives the same doubles.
// write_support_points: atomic (nothing under the final name on failure); throws Error.
// read_support_points / parse_support_points: the points, validated (validate_support_points),
// or Error naming the file, line and what is wrong (a missing header, a count that disagrees
// with the lines, a number that does not parse, a face id beyond the mesh's faces).
#include <cstddef>
#include <string>

#include "slicereuse/supports/support_points.h"

namespace slicereuse {

void write_support_points(const std::string& path, const SupportPoints& points);
SupportPoints read_support_points(const std::string& path);
SupportPoints parse_support_points(const char* data, size_t size, const std::string& name);

}  // namespace slicereuse
