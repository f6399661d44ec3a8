// Binary (.srb) reader (layout: slice_files_binary_layout.h). Every count and section entry is checked against the file size before
// anything is allocated, so a hostile header cannot make us allocate more than the file holds;
// then each section is read straight into its array and checked against its checksum.
#include <xxhash.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "slice_files_binary_layout.h"
#include "slicereuse/util/error.h"

namespace slicereuse::detail {
namespace {

std::string num(uint64_t v) { return std::to_string(v); }

struct Entry {
  uint32_t id;
  uint64_t offset, bytes, checksum;
};

}  // namespace

Slices read_binary(const std::string& path, FILE* f, uint64_t size, FileKind kind,
                   const Progress& progress) {
  auto fail = [&](const std::string& what) -> void { throw Error("'" + path + "': " + what); };
  auto read = [&](void* dst, uint64_t n, const char* what) {
    if (n && std::fread(dst, 1, n, f) != n)
      fail(std::string("cannot read ") + what + ": " +
           (std::ferror(f) ? std::strerror(errno) : "unexpected end of file"));
  };

  if (size < kFixedHeaderBytes)
    fail("truncated file: " + num(size) + " bytes, the binary header alone takes " +
         num(kFixedHeaderBytes));
  std::vector<unsigned char> head(kFixedHeaderBytes);
  read(head.data(), head.size(), "the header");
  if (std::memcmp(head.data(), kBinaryMagic, sizeof kBinaryMagic) != 0)
    fail("not a slicereuse binary file (bad magic number)");
  const uint32_t version = get<uint32_t>(head.data() + kVersionAt);
  if (version != kFormatVersion)
    fail("format version " + num(version) + " is not supported (this build reads version " +
         num(kFormatVersion) + ")");
  const uint32_t file_kind = get<uint32_t>(head.data() + kKindAt);
  if (file_kind != uint32_t(FileKind::Contours) && file_kind != uint32_t(FileKind::Encoding))
    fail("unknown file kind " + num(file_kind) + " (1 = contours, 2 = encoding)");
  if (file_kind != uint32_t(kind))
    fail("this is " + std::string(kind_noun(FileKind(file_kind))) + ", expected " +
         kind_noun(kind));

  const std::vector<uint32_t> ids = section_ids(kind);
  const uint32_t n_sections = get<uint32_t>(head.data() + kSectionCountAt);
  if (n_sections != ids.size())
    fail("the header lists " + num(n_sections) + " sections, " + kind_noun(kind) + " has " +
         num(ids.size()));
  const size_t table_end = kFixedHeaderBytes + kSectionEntryBytes * ids.size();
  const uint64_t header_bytes = table_end + 8;
  if (size < header_bytes)
    fail("truncated file: " + num(size) + " bytes, the header and section table take " +
         num(header_bytes));
  head.resize(header_bytes);
  read(head.data() + kFixedHeaderBytes, header_bytes - kFixedHeaderBytes, "the section table");
  if (XXH3_64bits(head.data(), table_end) != get<uint64_t>(head.data() + table_end))
    fail("header checksum mismatch: the header or section table is corrupted");
  if (get<uint32_t>(head.data() + kReservedAt) != 0) fail("reserved header field is not 0");

  Slices s;
  s.thickness = get<double>(head.data() + kThicknessAt);
  s.z_start = get<double>(head.data() + kZStartAt);
  const uint64_t L = get<uint64_t>(head.data() + kLayersAt), C = get<uint64_t>(head.data() + kContoursAt),
                 P = get<uint64_t>(head.data() + kPointsAt);
  if (kind == FileKind::Encoding)
    s.fingerprint = {get<uint64_t>(head.data() + kFingerprintFacesAt), get<uint64_t>(head.data() + kFingerprintHashAt)};
  // Each layer, contour and point takes at least one byte of the file: this bounds every
  // allocation below by the file size, and keeps the size arithmetic far from overflow.
  if (L >= size || C >= size || P >= size)
    fail("the header claims " + num(L) + " layers, " + num(C) + " contours and " + num(P) +
         " points, more than the file's " + num(size) + " bytes can hold");

  std::vector<Entry> table(ids.size());
  uint64_t end = header_bytes;
  for (size_t i = 0; i < ids.size(); ++i) {
    const unsigned char* e = head.data() + kFixedHeaderBytes + kSectionEntryBytes * i;
    Entry& t = table[i];
    t = {get<uint32_t>(e + kIdAt), get<uint64_t>(e + kOffsetAt), get<uint64_t>(e + kBytesAt),
         get<uint64_t>(e + kChecksumAt)};
    const std::string name = "section " + num(i) + " (" + section_name(ids[i]) + ")";
    if (t.id != ids[i] || get<uint32_t>(e + kPaddingAt) != 0)
      fail(name + " has id " + num(t.id) + ", expected " + num(ids[i]));
    if (t.offset != align8(end))
      fail(name + " starts at byte " + num(t.offset) + ", expected " + num(align8(end)));
    const uint64_t expected = section_bytes(t.id, L, C, P);
    if (t.bytes != expected)
      fail(name + " has " + num(t.bytes) + " bytes, the header's counts need " + num(expected));
    if (t.offset > size || t.bytes > size - t.offset)
      fail(name + " ends at byte " + num(t.offset + t.bytes) + ", beyond the end of the file (" +
           num(size) + " bytes): truncated file");
    end = t.offset + t.bytes;
  }
  if (end != size) fail(num(size - end) + " unexpected bytes after the last section");

  s.layer_z.resize(L);
  s.layer_begin.resize(L + 1);
  s.contour_begin.resize(C + 1);
  s.contour_open.resize(C);
  if (kind == FileKind::Contours) {
    s.xyz.resize(3 * P);
  } else {
    s.face.resize(P);
    s.edge.resize(P);
    s.t.resize(P);
  }
  uint64_t at = header_bytes, done = 0;
  const uint64_t total = size - header_bytes;
  for (const Entry& t : table) {
    const std::string name = std::string("section ") + section_name(t.id);
    unsigned char padding[8] = {};
    read(padding, t.offset - at, "the padding");
    if (std::any_of(padding, padding + 8, [](unsigned char b) { return b != 0; }))
      fail("nonzero padding before " + name + ": the file is corrupted");
    unsigned char* dst = section_data(s, t.id);
    for (uint64_t piece = 0; piece < t.bytes; piece += kPieceBytes) {
      const uint64_t n = std::min(kPieceBytes, t.bytes - piece);
      read(dst + piece, n, name.c_str());
      done += n;
      report_progress(progress, double(done) / double(total), "reading");
    }
    if (XXH3_64bits(dst, t.bytes) != t.checksum)
      fail(name + ": checksum mismatch, the file is corrupted");
    at = t.offset + t.bytes;
  }
  try {
    validate_slices(s);
  } catch (const Error& e) {
    fail(e.what());
  }
  return s;
}

}  // namespace slicereuse::detail
