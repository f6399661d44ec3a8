#pragma once
// Map files: a SurfaceMap (surface_map.h) on disk, as text (.map) or binary (.srb, the
// container of the slice files with kind 3), specified byte by byte in docs/formats.md.
//
// write_map_file validates the map, then writes atomically (AtomicFile): binary when the path
// ends in ".srb" (any case, is_binary_file_name in file_names.h), text otherwise. read_map_file detects the format from the file's
// first bytes, checks every count against the file size before allocating and every binary
// section against its XXH3 checksum, validates the result (validate_surface_map), and throws
// Error naming the file, the line or section and the problem.
#include <string>

#include "slicereuse/crossparam/surface_map.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

void write_map_file(const std::string& path, const SurfaceMap& map, const Progress& progress = {});
SurfaceMap read_map_file(const std::string& path, const Progress& progress = {});

}  // namespace slicereuse
