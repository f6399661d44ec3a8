#pragma once
// file_names: the two naming rules of slicereuse's files (docs/formats.md, "File names").
// Readers never look at a name (they go by the file's first bytes); these rules are for writers
// that have no format parameter and for finding the encoding that goes with a contour file.
//
// is_binary_file_name: whether a path names a binary (.srb) file: it ends in ".srb", in any case
// ("m0.srb", "M0.SRB"); contour, encoding and map files alike. Every other name is text.
// encoding_file_beside: the encoding file that goes with the contour file at contour_path: the
// path without its extension (from the last '.' after the last '/'), then "_enc.srb" for a
// binary encoding or ".enc" for a text one; without a format, the one contour_path's name says.
// "out/m0.srb" -> "out/m0_enc.srb", "out/m0.ctr" -> "out/m0.enc".
#include <string>

#include "slicereuse/formats/slice_files.h"

namespace slicereuse {

bool is_binary_file_name(const std::string& path);

std::string encoding_file_beside(const std::string& contour_path, FileFormat format);
std::string encoding_file_beside(const std::string& contour_path);

}  // namespace slicereuse
