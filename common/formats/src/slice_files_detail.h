#pragma once
// Internals shared by the slice file readers and writers (slice_files*.cpp); not part of the
// API. The public functions in slice_files.cpp validate, pick the format and call these.
// Every function here throws Error whose message starts with the file's path.
#include <cstdio>
#include <string>
#include <vector>

#include "slicereuse/slicing/slices.h"
#include "slicereuse/util/buffer.h"
#include "slicereuse/util/progress.h"

namespace slicereuse::detail {

enum class FileKind { Contours = 1, Encoding = 2 };

inline const char* kind_word(FileKind k) { return k == FileKind::Contours ? "contours" : "encoding"; }
inline const char* kind_noun(FileKind k) {
  return k == FileKind::Contours ? "a contour file" : "an encoding file";
}

// Both formats carry this version (text: "# slicereuse <kind> <version>"; binary: header).
constexpr unsigned kFormatVersion = 1;

// s has been validated and carries the data of `kind`.
void write_text(const std::string& path, const Slices& s, FileKind kind, const Progress& progress);
void write_binary(const std::string& path, const Slices& s, FileKind kind,
                  const Progress& progress);

// data holds the whole file.
Slices read_text(const std::string& path, const Buffer<char>& data, FileKind kind,
                 const Progress& progress);
// f is open at offset 0; size is the file's size in bytes.
Slices read_binary(const std::string& path, FILE* f, uint64_t size, FileKind kind,
                   const Progress& progress);

}  // namespace slicereuse::detail
