// Binary (.srb) reader (layout: slice_files_binary_layout.h): the container, for every kind, and
// the slice files on it. Every count and section entry is checked against the file size before
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

}  // namespace

ContainerReader::ContainerReader(const std::string& path, FILE* f, uint64_t size, uint32_t kind,
                                 std::vector<uint32_t> ids)
    : path_(path), f_(f), size_(size), ids_(std::move(ids)) {
  if (size < kFixedHeaderBytes)
    fail("truncated file: " + num(size) + " bytes, the binary header alone takes " + num(kFixedHeaderBytes));
  head_.resize(kFixedHeaderBytes);
  read(head_.data(), head_.size(), "the header");
  if (std::memcmp(head_.data(), kBinaryMagic, sizeof kBinaryMagic) != 0)
    fail("not a slicereuse binary file (bad magic number)");
  const uint32_t version = field<uint32_t>(kVersionAt);
  if (version != kFormatVersion)
    fail("format version " + num(version) + " is not supported (this build reads version " + num(kFormatVersion) +
         ")");
  const uint32_t file_kind = field<uint32_t>(kKindAt);
  const char* found = container_kind_noun(file_kind);
  if (!found) fail("unknown file kind " + num(file_kind) + " (1 = contours, 2 = encoding, 3 = map)");
  if (file_kind != kind) fail("this is " + std::string(found) + ", expected " + container_kind_noun(kind));

  const uint32_t n_sections = field<uint32_t>(kSectionCountAt);
  if (n_sections != ids_.size())
    fail("the header lists " + num(n_sections) + " sections, " + container_kind_noun(kind) + " has " +
         num(ids_.size()));
  const uint64_t end = table_end(ids_.size()), header_bytes = end + 8;
  if (size < header_bytes)
    fail("truncated file: " + num(size) + " bytes, the header and section table take " + num(header_bytes));
  head_.resize(header_bytes);
  read(head_.data() + kFixedHeaderBytes, header_bytes - kFixedHeaderBytes, "the section table");
  if (XXH3_64bits(head_.data(), end) != field<uint64_t>(end))
    fail("header checksum mismatch: the header or section table is corrupted");
  if (field<uint32_t>(kReservedAt) != 0) fail("reserved header field is not 0");
}

void ContainerReader::check_sections(const std::vector<uint64_t>& bytes) const {
  uint64_t end = head_.size();
  for (size_t i = 0; i < ids_.size(); ++i) {
    const unsigned char* e = entry(i);
    const uint32_t id = get<uint32_t>(e + kIdAt);
    const uint64_t offset = get<uint64_t>(e + kOffsetAt), n = get<uint64_t>(e + kBytesAt);
    const std::string name = "section " + num(i) + " (" + section_name(ids_[i]) + ")";
    if (id != ids_[i] || get<uint32_t>(e + kPaddingAt) != 0)
      fail(name + " has id " + num(id) + ", expected " + num(ids_[i]));
    if (offset != align8(end)) fail(name + " starts at byte " + num(offset) + ", expected " + num(align8(end)));
    if (n != bytes[i]) fail(name + " has " + num(n) + " bytes, the header's counts need " + num(bytes[i]));
    if (offset > size_ || n > size_ - offset)
      fail(name + " ends at byte " + num(offset + n) + ", beyond the end of the file (" + num(size_) +
           " bytes): truncated file");
    end = offset + n;
  }
  if (end != size_) fail(num(size_ - end) + " unexpected bytes after the last section");
}

void ContainerReader::read_sections(const std::vector<unsigned char*>& dst, const Progress& progress) {
  uint64_t at = head_.size(), done = 0;
  const uint64_t total = size_ - head_.size();
  for (size_t i = 0; i < ids_.size(); ++i) {
    const unsigned char* e = entry(i);
    const uint64_t offset = get<uint64_t>(e + kOffsetAt), bytes = get<uint64_t>(e + kBytesAt);
    const std::string name = std::string("section ") + section_name(ids_[i]);
    unsigned char padding[8] = {};
    read(padding, offset - at, "the padding");
    if (std::any_of(padding, padding + 8, [](unsigned char b) { return b != 0; }))
      fail("nonzero padding before " + name + ": the file is corrupted");
    for (uint64_t piece = 0; piece < bytes; piece += kPieceBytes) {
      const uint64_t n = std::min(kPieceBytes, bytes - piece);
      read(dst[i] + piece, n, name);
      done += n;
      report_progress(progress, double(done) / double(total), "reading");
    }
    if (XXH3_64bits(dst[i], bytes) != get<uint64_t>(e + kChecksumAt))
      fail(name + ": checksum mismatch, the file is corrupted");
    at = offset + bytes;
  }
}

void ContainerReader::fail(const std::string& what) const { throw Error("'" + path_ + "': " + what); }

void ContainerReader::read(void* dst, uint64_t n, const std::string& what) {
  if (n && std::fread(dst, 1, n, f_) != n)
    fail("cannot read " + what + ": " + (std::ferror(f_) ? std::strerror(errno) : "unexpected end of file"));
}

Slices read_binary(const std::string& path, FILE* f, uint64_t size, FileKind kind,
                   const Progress& progress) {
  const std::vector<uint32_t> ids = section_ids(kind);
  ContainerReader c(path, f, size, uint32_t(kind), ids);
  Slices s;
  s.thickness = c.field<double>(kThicknessAt);
  s.z_start = c.field<double>(kZStartAt);
  const uint64_t L = c.field<uint64_t>(kLayersAt), C = c.field<uint64_t>(kContoursAt),
                 P = c.field<uint64_t>(kPointsAt);
  if (kind == FileKind::Encoding)
    s.fingerprint = {c.field<uint64_t>(kFingerprintFacesAt), c.field<uint64_t>(kFingerprintHashAt)};
  // Each layer, contour and point takes at least one byte of the file: this bounds every
  // allocation below by the file size, and keeps the size arithmetic far from overflow.
  if (L >= size || C >= size || P >= size)
    c.fail("the header claims " + num(L) + " layers, " + num(C) + " contours and " + num(P) +
           " points, more than the file's " + num(size) + " bytes can hold");
  std::vector<uint64_t> bytes;
  for (uint32_t id : ids) bytes.push_back(section_bytes(id, L, C, P));
  c.check_sections(bytes);

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
  std::vector<unsigned char*> dst;
  for (uint32_t id : ids) dst.push_back(section_data(s, id));
  c.read_sections(dst, progress);
  try {
    validate_slices(s);
  } catch (const Error& e) {
    c.fail(e.what());
  }
  return s;
}

}  // namespace slicereuse::detail
