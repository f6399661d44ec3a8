#pragma once
// Reading and writing the method's two files: the contour file (points) and the encoding file
// (face + area coordinates per point), each as text (.ctr / .enc) or binary (.srb).
// docs/formats.md specifies both formats byte by byte.
//
// Writers are atomic (AtomicFile, atomic_file.h) and throw Error naming the path on failure.
// Readers detect the format from the file's first bytes, validate every count against the file
// size and every section checksum, and throw Error naming the file, the line or section and the
// problem. A reader fills the structure of Slices (layers, contours) plus xyz (contour file) or
// the encoding and fingerprint (encoding file).
#include <string>

#include "slicereuse/progress.h"
#include "slicereuse/slices.h"

namespace slicereuse {

enum class FileFormat { Text = 0, Binary = 1 };

void write_contour_file(const std::string& path, const Slices& s, FileFormat format,
                        const Progress& progress = {});
void write_encoding_file(const std::string& path, const Slices& s, FileFormat format,
                         const Progress& progress = {});

Slices read_contour_file(const std::string& path, const Progress& progress = {});
Slices read_encoding_file(const std::string& path, const Progress& progress = {});

}  // namespace slicereuse
