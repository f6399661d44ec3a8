#pragma once
// The binary (.srb) file layout (docs/formats.md, "Binary format"), shared by the reader
// (slice_files_binary_read.cpp), the writer (slice_files_binary_write.cpp), the format
// detection (slice_files.cpp) and the map files (map_files.cpp); internal, not part of the API.
//   A fixed header of kFixedHeaderBytes, a table of one kSectionEntryBytes entry per section,
//   an XXH3-64 checksum over both, then the sections at 8-byte aligned offsets.
//   write_container / ContainerReader: the container for every kind (contour, encoding and map
//   files), so its checks exist once.
//   section_ids(kind): the sections of a file kind, in file order;
//   section_bytes(id, L, C, P): a section's size for L layers, C contours, P points;
//   section_data(s, id): the Slices array a section holds (the one id -> array mapping).
// Multi-byte fields are little-endian, which is the host order on every platform MeshLab runs on.
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "slice_files_detail.h"
#include "slicereuse/slicing/slices.h"
#include "slicereuse/util/progress.h"

namespace slicereuse::detail {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, ".srb I/O assumes a little-endian host");

// The 8 bytes that open every binary file.
constexpr char kBinaryMagic[8] = {'\x89', 'S', 'R', 'B', '\r', '\n', '\x1a', '\n'};

// Large sections are read and written in pieces so progress (and cancellation) stays responsive.
constexpr uint64_t kPieceBytes = uint64_t(64) << 20;

template <class T>
void put(unsigned char* at, T v) {
  std::memcpy(at, &v, sizeof v);
}
template <class T>
T get(const unsigned char* at) {
  T v;
  std::memcpy(&v, at, sizeof v);
  return v;
}

// Fixed header: byte offsets of its fields.
constexpr size_t kFixedHeaderBytes = 80;
enum HeaderField : size_t {
  kVersionAt = 8,             // uint32
  kKindAt = 12,               // uint32, FileKind
  kThicknessAt = 16,          // double
  kZStartAt = 24,             // double
  kLayersAt = 32,             // uint64
  kContoursAt = 40,           // uint64
  kPointsAt = 48,             // uint64
  kFingerprintFacesAt = 56,   // uint64, encoding files (0 in contour files)
  kFingerprintHashAt = 64,    // uint64, encoding files (0 in contour files)
  kSectionCountAt = 72,       // uint32
  kReservedAt = 76,           // uint32, 0
};

// Section table entry: byte offsets of its fields.
constexpr size_t kSectionEntryBytes = 32;
enum EntryField : size_t {
  kIdAt = 0,        // uint32
  kPaddingAt = 4,   // uint32, 0
  kOffsetAt = 8,    // uint64, from the start of the file
  kBytesAt = 16,    // uint64
  kChecksumAt = 24  // uint64, XXH3-64 of the section's bytes
};

// Bytes [0, table_end(n)) are the fixed header and a table of n sections; the header checksum
// follows them.
inline uint64_t table_end(uint64_t sections) { return kFixedHeaderBytes + kSectionEntryBytes * sections; }

// The kinds a container holds (field kKindAt): the slice files' FileKind (1, 2) and map files.
constexpr uint32_t kMapFileKind = 3;
// "a contour file", "an encoding file", "a map file"; nullptr for an unknown kind.
const char* container_kind_noun(uint32_t kind);

enum SectionId : uint32_t {
  kLayerZ = 1, kLayerBegin = 2, kContourBegin = 3, kContourOpen = 4,
  kXyz = 5, kFace = 6, kEdge = 7, kT = 8,
  kSourceFaces = 9, kMapFace = 10, kMapBary = 11  // map files
};
const char* section_name(uint32_t id);
std::vector<uint32_t> section_ids(FileKind kind);
// Counts must be at most 2^58 (no overflow).
uint64_t section_bytes(uint32_t id, uint64_t layers, uint64_t contours, uint64_t points);
// The arrays must already have their sizes (section_bytes); nullptr for an unknown id.
unsigned char* section_data(Slices& s, uint32_t id);
inline const unsigned char* section_data(const Slices& s, uint32_t id) {
  return section_data(const_cast<Slices&>(s), id);
}
inline uint64_t align8(uint64_t n) { return (n + 7) & ~uint64_t(7); }

// Writes a binary container atomically: the fixed header with `kind` and the kind's own header
// bytes [kThicknessAt, kSectionCountAt) (`fields`), the section table with checksums, then the
// sections in order. Used by the slice files (kinds 1, 2) and the map files (map_files.cpp, 3).
constexpr size_t kKindFieldBytes = kSectionCountAt - kThicknessAt;
struct SectionOut {
  uint32_t id;
  const void* data;
  uint64_t bytes;
};
void write_container(const std::string& path, uint32_t kind, const unsigned char fields[kKindFieldBytes],
                     const std::vector<SectionOut>& sections, const Progress& progress);

// Reads a binary container, the reverse of write_container, with every check the container
// itself defines, in this order:
//   ContainerReader c(path, f, size, kind, ids);  // the file holds a header: magic, version,
//       kind (names the kind found), section count (ids.size()), header checksum, reserved field
//   ... the kind's own fields (c.field<T>(at)), its counts checked against the file size ...
//   c.check_sections(bytes);  // the table: ids in order, canonical offsets, sizes bytes[i],
//       within the file, nothing after the last section; before anything is allocated
//   c.read_sections(dst, progress);  // zero padding, each section into dst[i], its checksum
// f is open at offset 0; errors are Error("'path': what").
class ContainerReader {
 public:
  ContainerReader(const std::string& path, FILE* f, uint64_t size, uint32_t kind, std::vector<uint32_t> ids);
  template <class T>
  T field(size_t at) const {
    return get<T>(head_.data() + at);
  }
  void check_sections(const std::vector<uint64_t>& bytes) const;
  void read_sections(const std::vector<unsigned char*>& dst, const Progress& progress);
  [[noreturn]] void fail(const std::string& what) const;

 private:
  void read(void* dst, uint64_t n, const std::string& what);
  const unsigned char* entry(size_t i) const { return head_.data() + kFixedHeaderBytes + kSectionEntryBytes * i; }

  const std::string& path_;
  FILE* f_;
  uint64_t size_;
  std::vector<uint32_t> ids_;
  std::vector<unsigned char> head_;  // header, table and header checksum
};

}  // namespace slicereuse::detail
