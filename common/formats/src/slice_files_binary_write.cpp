// Binary (.srb) writer (layout: slice_files_binary_layout.h). The arrays are written as they
// are in memory, one fwrite per section, so writing runs at disk speed.
#include <xxhash.h>

#include <algorithm>
#include <cstring>

#include "slice_files_binary_layout.h"
#include "slicereuse/util/atomic_file.h"

namespace slicereuse::detail {

void write_container(const std::string& path, uint32_t kind, const unsigned char fields[kKindFieldBytes],
                     const std::vector<SectionOut>& sections, const Progress& progress) {
  const uint64_t end = table_end(sections.size());
  std::vector<unsigned char> head(end + 8, 0);
  unsigned char* h = head.data();
  std::memcpy(h, kBinaryMagic, sizeof kBinaryMagic);
  put<uint32_t>(h + kVersionAt, kFormatVersion);
  put<uint32_t>(h + kKindAt, kind);
  std::memcpy(h + kThicknessAt, fields, kKindFieldBytes);
  put<uint32_t>(h + kSectionCountAt, uint32_t(sections.size()));

  uint64_t offset = head.size(), total = 0;
  for (size_t i = 0; i < sections.size(); ++i) {
    const SectionOut& sec = sections[i];
    unsigned char* e = h + kFixedHeaderBytes + kSectionEntryBytes * i;
    put<uint32_t>(e + kIdAt, sec.id);
    put<uint64_t>(e + kOffsetAt, offset);
    put<uint64_t>(e + kBytesAt, sec.bytes);
    put<uint64_t>(e + kChecksumAt, XXH3_64bits(sec.data, sec.bytes));
    offset = align8(offset + sec.bytes);
    total += sec.bytes;
  }
  put<uint64_t>(h + end, XXH3_64bits(h, end));

  AtomicFile file(path);
  file.write(head.data(), head.size());
  const char zeros[8] = {};
  uint64_t done = 0;
  for (const SectionOut& sec : sections) {
    const auto* data = static_cast<const unsigned char*>(sec.data);
    for (uint64_t at = 0; at < sec.bytes; at += kPieceBytes) {
      const uint64_t n = std::min(kPieceBytes, sec.bytes - at);
      file.write(data + at, n);
      done += n;
      report_progress(progress, total ? double(done) / double(total) : 1.0, "writing");
    }
    file.write(zeros, align8(sec.bytes) - sec.bytes);
  }
  file.commit();
}

void write_binary(const std::string& path, const Slices& s, FileKind kind,
                  const Progress& progress) {
  const uint64_t L = s.layers(), C = s.contours(), P = s.points();
  unsigned char fields[kKindFieldBytes] = {};
  // The fields begin at header offset kThicknessAt.
  auto f = [&fields](size_t header_offset) { return fields + (header_offset - kThicknessAt); };
  put<double>(f(kThicknessAt), s.thickness);
  put<double>(f(kZStartAt), s.z_start);
  put<uint64_t>(f(kLayersAt), L);
  put<uint64_t>(f(kContoursAt), C);
  put<uint64_t>(f(kPointsAt), P);
  if (kind == FileKind::Encoding) {
    put<uint64_t>(f(kFingerprintFacesAt), s.fingerprint.faces);
    put<uint64_t>(f(kFingerprintHashAt), s.fingerprint.hash);
  }
  std::vector<SectionOut> sections;
  for (uint32_t id : section_ids(kind)) sections.push_back({id, section_data(s, id), section_bytes(id, L, C, P)});
  write_container(path, uint32_t(kind), fields, sections, progress);
}

}  // namespace slicereuse::detail
