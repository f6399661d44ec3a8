#pragma once
// The placements file: which members sit on which plate, and where (docs/formats.md, "Placements
// file"). JSON, written by the hosts after arranging (arrange_plates.h) and read back when a
// person gives the placements instead of having them computed.
//
// write_placements_file(path, plates): atomic (util/atomic_file.h), by nlohmann::json; numbers in
// the shortest form that reads back as the same double, so reading gives back exactly the doubles
// written. Throws Error for a name or output that is not UTF-8 text, before creating the file.
// read_placements_file(path): the plates as written; throws Error naming the file, the line of a
// syntax error, or the plate and member of a missing or mistyped field, a non-finite number, a
// member named twice, or a plate without members. Fields the reader does not know are ignored
// (a host may add its own figures).
// arrangement_of(plates, names, plate): the Arrangement (arrange_plates.h) of the members `names`
// that the file describes: of every plate (plate 0), or of plate `plate` only (from 1; then the
// Arrangement has that one plate, and names are its members); throws Error naming a plate the
// file does not have, a member the file places that is not among names, or a member of names it
// does not place.
#include <string>
#include <vector>

#include "slicereuse/plates/arrange_plates.h"

namespace slicereuse {

struct PlateRecord {
  std::vector<std::string> names;       // members, in placing order
  std::vector<Placement> placements;    // per member
  double area_used = 0;                 // 0..1, as arrange_plates reports it
  std::string output;                   // the plate's print file, or empty
};

struct PlacementsFile {
  double spacing_mm = 0;
  Platform platform;
  std::vector<PlateRecord> plates;
};

// The file's record of an arrangement of the members `names`, with each plate's output (or none).
PlacementsFile placements_of(const Arrangement& a, const std::vector<std::string>& names, double spacing_mm,
                             const Platform& platform, const std::vector<std::string>& outputs = {});

Arrangement arrangement_of(const PlacementsFile& file, const std::vector<std::string>& names, size_t plate = 0);

void write_placements_file(const std::string& path, const PlacementsFile& file);

PlacementsFile read_placements_file(const std::string& path);

}  // namespace slicereuse
