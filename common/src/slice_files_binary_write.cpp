// Binary (.srb) writer (layout: slice_files_binary_layout.h). The arrays are written as they
// are in memory, one fwrite per section, so writing runs at disk speed.
#include <xxhash.h>

#include <algorithm>
#include <cstring>

#include "slice_files_binary_layout.h"
#include "slicereuse/atomic_file.h"

namespace slicereuse::detail {

void write_binary(const std::string& path, const Slices& s, FileKind kind,
                  const Progress& progress) {
  const std::vector<uint32_t> ids = section_ids(kind);
  const uint64_t L = s.layers(), C = s.contours(), P = s.points();
  const size_t table_end = kFixedHeaderBytes + kSectionEntryBytes * ids.size();
  std::vector<unsigned char> head(table_end + 8, 0);
  unsigned char* h = head.data();
  std::memcpy(h, kBinaryMagic, sizeof kBinaryMagic);
  put<uint32_t>(h + kVersionAt, kFormatVersion);
  put<uint32_t>(h + kKindAt, uint32_t(kind));
  put<double>(h + kThicknessAt, s.thickness);
  put<double>(h + kZStartAt, s.z_start);
  put<uint64_t>(h + kLayersAt, L);
  put<uint64_t>(h + kContoursAt, C);
  put<uint64_t>(h + kPointsAt, P);
  if (kind == FileKind::Encoding) {
    put<uint64_t>(h + kFingerprintFacesAt, s.fingerprint.faces);
    put<uint64_t>(h + kFingerprintHashAt, s.fingerprint.hash);
  }
  put<uint32_t>(h + kSectionCountAt, uint32_t(ids.size()));

  uint64_t offset = head.size(), total = 0;
  for (size_t i = 0; i < ids.size(); ++i) {
    const uint64_t bytes = section_bytes(ids[i], L, C, P);
    unsigned char* e = h + kFixedHeaderBytes + kSectionEntryBytes * i;
    put<uint32_t>(e + kIdAt, ids[i]);
    put<uint64_t>(e + kOffsetAt, offset);
    put<uint64_t>(e + kBytesAt, bytes);
    put<uint64_t>(e + kChecksumAt, XXH3_64bits(section_data(s, ids[i]), bytes));
    offset = align8(offset + bytes);
    total += bytes;
  }
  put<uint64_t>(h + table_end, XXH3_64bits(h, table_end));

  AtomicFile file(path);
  file.write(head.data(), head.size());
  const char zeros[8] = {};
  uint64_t done = 0;
  for (uint32_t id : ids) {
    const unsigned char* data = section_data(s, id);
    const uint64_t bytes = section_bytes(id, L, C, P);
    for (uint64_t at = 0; at < bytes; at += kPieceBytes) {
      const uint64_t n = std::min(kPieceBytes, bytes - at);
      file.write(data + at, n);
      done += n;
      report_progress(progress, total ? double(done) / double(total) : 1.0, "writing");
    }
    file.write(zeros, align8(bytes) - bytes);
  }
  file.commit();
}

}  // namespace slicereuse::detail
