// Binary (.srb) layout helpers and writer. The arrays are written as they are in memory, one
// fwrite per section, so writing runs at disk speed.
#include <xxhash.h>

#include <algorithm>
#include <cstring>

#include "slice_files_detail.h"
#include "slicereuse/atomic_file.h"

namespace slicereuse::detail {

const char* section_name(uint32_t id) {
  switch (id) {
    case kLayerZ: return "layer_z";
    case kLayerBegin: return "layer_begin";
    case kContourBegin: return "contour_begin";
    case kContourOpen: return "contour_open";
    case kXyz: return "xyz";
    case kFace: return "face";
    case kEdge: return "edge";
    case kT: return "t";
    default: return "unknown";
  }
}

std::vector<uint32_t> section_ids(FileKind kind) {
  if (kind == FileKind::Contours) return {kLayerZ, kLayerBegin, kContourBegin, kContourOpen, kXyz};
  return {kLayerZ, kLayerBegin, kContourBegin, kContourOpen, kFace, kEdge, kT};
}

uint64_t section_bytes(uint32_t id, uint64_t layers, uint64_t contours, uint64_t points) {
  switch (id) {
    case kLayerZ: return 8 * layers;
    case kLayerBegin: return 8 * (layers + 1);
    case kContourBegin: return 8 * (contours + 1);
    case kContourOpen: return contours;
    case kXyz: return 24 * points;
    case kFace: return 4 * points;
    case kEdge: return points;
    case kT: return 8 * points;
    default: return 0;
  }
}

namespace {

// Large sections are written in pieces so progress (and cancellation) stays responsive.
constexpr uint64_t kPieceBytes = uint64_t(64) << 20;

template <class T>
void put(std::vector<unsigned char>& h, size_t at, T v) {
  std::memcpy(h.data() + at, &v, sizeof v);
}

const void* section_data(const Slices& s, uint32_t id) {
  switch (id) {
    case kLayerZ: return s.layer_z.data();
    case kLayerBegin: return s.layer_begin.data();
    case kContourBegin: return s.contour_begin.data();
    case kContourOpen: return s.contour_open.data();
    case kXyz: return s.xyz.data();
    case kFace: return s.face.data();
    case kEdge: return s.edge.data();
    case kT: return s.t.data();
    default: return nullptr;
  }
}

}  // namespace

void write_container(const std::string& path, uint32_t kind, const unsigned char fields[kKindFieldBytes],
                     const std::vector<SectionOut>& sections, const Progress& progress) {
  const size_t table_end = kFixedHeaderBytes + kSectionEntryBytes * sections.size();
  std::vector<unsigned char> head(table_end + 8, 0);
  std::memcpy(head.data(), kBinaryMagic, sizeof kBinaryMagic);
  put<uint32_t>(head, 8, kFormatVersion);
  put<uint32_t>(head, 12, kind);
  std::memcpy(head.data() + 16, fields, kKindFieldBytes);
  put<uint32_t>(head, 72, uint32_t(sections.size()));

  uint64_t offset = head.size(), total = 0;
  for (size_t i = 0; i < sections.size(); ++i) {
    const SectionOut& sec = sections[i];
    const size_t at = kFixedHeaderBytes + kSectionEntryBytes * i;
    put<uint32_t>(head, at, sec.id);
    put<uint64_t>(head, at + 8, offset);
    put<uint64_t>(head, at + 16, sec.bytes);
    put<uint64_t>(head, at + 24, XXH3_64bits(sec.data, sec.bytes));
    offset = align8(offset + sec.bytes);
    total += sec.bytes;
  }
  put<uint64_t>(head, table_end, XXH3_64bits(head.data(), table_end));

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
  std::vector<unsigned char> fields(kKindFieldBytes, 0);  // header bytes 16..72
  put<double>(fields, 0, s.thickness);
  put<double>(fields, 8, s.z_start);
  put<uint64_t>(fields, 16, L);
  put<uint64_t>(fields, 24, C);
  put<uint64_t>(fields, 32, P);
  if (kind == FileKind::Encoding) {
    put<uint64_t>(fields, 40, s.fingerprint.faces);
    put<uint64_t>(fields, 48, s.fingerprint.hash);
  }
  std::vector<SectionOut> sections;
  for (uint32_t id : section_ids(kind)) sections.push_back({id, section_data(s, id), section_bytes(id, L, C, P)});
  write_container(path, uint32_t(kind), fields.data(), sections, progress);
}

}  // namespace slicereuse::detail
