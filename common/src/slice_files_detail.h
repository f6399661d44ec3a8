#pragma once
// Internals shared by the slice file readers and writers (slice_files*.cpp); not part of the
// API. The public functions in slice_files.cpp validate, pick the format and call these.
// Every function here throws Error whose message starts with the file's path.
#include <cstdio>
#include <string>
#include <vector>

#include "slicereuse/buffer.h"
#include "slicereuse/progress.h"
#include "slicereuse/slices.h"

namespace slicereuse::detail {

enum class FileKind { Contours = 1, Encoding = 2 };

inline const char* kind_word(FileKind k) { return k == FileKind::Contours ? "contours" : "encoding"; }
inline const char* kind_noun(FileKind k) {
  return k == FileKind::Contours ? "a contour file" : "an encoding file";
}

// The 8 bytes that open every binary (.srb) file.
constexpr char kBinaryMagic[8] = {'\x89', 'S', 'R', 'B', '\r', '\n', '\x1a', '\n'};
constexpr unsigned kFormatVersion = 1;

// Binary (.srb) layout, see docs/formats.md: a fixed header, a table of section entries, a
// checksum over both, then the sections at 8-byte aligned offsets. Multi-byte fields are
// little-endian, which is the host order on every platform MeshLab runs on.
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, ".srb I/O assumes a little-endian host");
constexpr size_t kFixedHeaderBytes = 80;
constexpr size_t kSectionEntryBytes = 32;
enum SectionId : uint32_t {
  kLayerZ = 1, kLayerBegin = 2, kContourBegin = 3, kContourOpen = 4,
  kXyz = 5, kFace = 6, kEdge = 7, kT = 8
};
const char* section_name(uint32_t id);
// The sections of a file of `kind`, in file order.
std::vector<uint32_t> section_ids(FileKind kind);
// Byte size of section id for the given counts (counts must be at most 2^58, no overflow).
uint64_t section_bytes(uint32_t id, uint64_t layers, uint64_t contours, uint64_t points);
inline uint64_t align8(uint64_t n) { return (n + 7) & ~uint64_t(7); }

// Writes a binary container atomically: the fixed header with `kind` and the kind's own header
// bytes [16, 72) (`fields`), the section table with checksums, then the sections in order.
// Used by the slice files and the map files (map_files.cpp, kind 3).
constexpr size_t kKindFieldBytes = 56;
struct SectionOut {
  uint32_t id;
  const void* data;
  uint64_t bytes;
};
void write_container(const std::string& path, uint32_t kind, const unsigned char fields[kKindFieldBytes],
                     const std::vector<SectionOut>& sections, const Progress& progress);

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
