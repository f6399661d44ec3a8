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

#include "slicereuse/slicing/slices.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

enum class FileFormat { Text = 0, Binary = 1 };

void write_contour_file(const std::string& path, const Slices& s, FileFormat format,
                        const Progress& progress = {});
void write_encoding_file(const std::string& path, const Slices& s, FileFormat format,
                         const Progress& progress = {});

Slices read_contour_file(const std::string& path, const Progress& progress = {});
Slices read_encoding_file(const std::string& path, const Progress& progress = {});

// What identifies a slice file's content: its size and a checksum of the content. For a binary
// file the checksum is the one stored over its header and section table, which holds every
// section's checksum (only the header is read); a text file has none stored and is hashed
// whole (XXH3). No file times: a file rewritten within the clock's resolution keeps its
// modification time, and one rewritten with the same bytes is the same content. Throws Error
// if it cannot be read.
struct FileIdentity {
  uint64_t size = 0;
  uint64_t checksum = 0;
  bool operator==(const FileIdentity& o) const { return size == o.size && checksum == o.checksum; }
};
FileIdentity slice_file_identity(const std::string& path);

}  // namespace slicereuse
