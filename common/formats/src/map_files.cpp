// Map files, text (.map) and binary (.srb kind 3); see docs/formats.md. The binary form shares
// the slice files' container: magic, version, section table with XXH3 checksums, 8-byte
// aligned sections, written and read with its checks by write_container and ContainerReader
// (slice_files_binary_layout.h).
#include "slicereuse/formats/map_files.h"

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <string_view>

#include "slice_files_binary_layout.h"
#include "slicereuse/formats/file_names.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/input_file.h"
#include "slicereuse/util/text_tokens.h"

namespace slicereuse {
namespace {

using detail::kBinaryMagic;
using detail::kFormatVersion;

// The map's own header fields (docs/formats.md, "Map files"), byte offsets in the container's
// fixed header.
enum MapField : size_t {
  kSourceVerticesAt = 16,     // uint64
  kTargetVerticesAt = 24,     // uint64
  kSourceFacesAt = 32,        // uint64, source fingerprint
  kSourceHashAt = 40,         // uint64
  kTargetFacesAt = 48,        // uint64, target fingerprint
  kTargetHashAt = 56,         // uint64
  kMapReservedAt = 64,        // uint64, 0
};
const std::vector<uint32_t> kSectionIds = {detail::kSourceFaces, detail::kMapFace, detail::kMapBary};
uint64_t section_bytes(uint32_t id, uint64_t source_faces, uint64_t source_vertices) {
  return id == detail::kSourceFaces ? 12 * source_faces
         : id == detail::kMapFace   ? 4 * source_vertices
                                    : 24 * source_vertices;
}
std::string num(uint64_t v) { return std::to_string(v); }

unsigned char* section_data(SurfaceMap& m, uint32_t id) {
  return id == detail::kSourceFaces ? reinterpret_cast<unsigned char*>(m.source_faces.data())
         : id == detail::kMapFace   ? reinterpret_cast<unsigned char*>(m.face.data())
                                    : reinterpret_cast<unsigned char*>(m.bary.data());
}
const unsigned char* section_data(const SurfaceMap& m, uint32_t id) {
  return section_data(const_cast<SurfaceMap&>(m), id);
}

void write_binary(const std::string& path, const SurfaceMap& m, const Progress& progress) {
  unsigned char fields[detail::kKindFieldBytes] = {};
  unsigned char* f = fields - detail::kThicknessAt;  // header offsets index into fields
  detail::put<uint64_t>(f + kSourceVerticesAt, m.source_vertices);
  detail::put<uint64_t>(f + kTargetVerticesAt, m.target_vertices);
  detail::put<uint64_t>(f + kSourceFacesAt, m.source.faces);
  detail::put<uint64_t>(f + kSourceHashAt, m.source.hash);
  detail::put<uint64_t>(f + kTargetFacesAt, m.target.faces);
  detail::put<uint64_t>(f + kTargetHashAt, m.target.hash);
  std::vector<detail::SectionOut> sections;
  for (uint32_t id : kSectionIds)
    sections.push_back({id, section_data(m, id), section_bytes(id, m.source.faces, m.source_vertices)});
  detail::write_container(path, detail::kMapFileKind, fields, sections, progress);
}

SurfaceMap read_binary(const std::string& path, FILE* f, uint64_t size, const Progress& progress) {
  detail::ContainerReader c(path, f, size, detail::kMapFileKind, kSectionIds);
  if (c.field<uint64_t>(kMapReservedAt) != 0) c.fail("reserved header field is not 0");
  SurfaceMap m;
  m.source_vertices = c.field<uint64_t>(kSourceVerticesAt);
  m.target_vertices = c.field<uint64_t>(kTargetVerticesAt);
  m.source = {c.field<uint64_t>(kSourceFacesAt), c.field<uint64_t>(kSourceHashAt)};
  m.target = {c.field<uint64_t>(kTargetFacesAt), c.field<uint64_t>(kTargetHashAt)};
  // Every source face and vertex takes bytes of the file: no allocation beyond its size.
  if (m.source.faces >= size || m.source_vertices >= size)
    c.fail("the header claims " + num(m.source.faces) + " source faces and " + num(m.source_vertices) +
           " source vertices, more than the file's " + num(size) + " bytes can hold");
  std::vector<uint64_t> bytes;
  for (uint32_t id : kSectionIds) bytes.push_back(section_bytes(id, m.source.faces, m.source_vertices));
  c.check_sections(bytes);
  m.source_faces.resize(3 * m.source.faces);
  m.face.resize(m.source_vertices);
  m.bary.resize(3 * m.source_vertices);
  std::vector<unsigned char*> dst;
  for (uint32_t id : kSectionIds) dst.push_back(section_data(m, id));
  c.read_sections(dst, progress);
  return m;
}

// Text: "# slicereuse map 1", "# source <vertices> <faces> <hash>", "# target <vertices>
// <faces> <hash>", then one line "f a b c" per source face and one line "v face b0 b1 b2" per
// source vertex.
void write_text(const std::string& path, const SurfaceMap& m, const Progress& progress) {
  AtomicFile file(path);
  char hs[17], ht[17];
  std::snprintf(hs, sizeof hs, "%016llx", static_cast<unsigned long long>(m.source.hash));
  std::snprintf(ht, sizeof ht, "%016llx", static_cast<unsigned long long>(m.target.hash));
  const std::string head = "# slicereuse map " + num(kFormatVersion) + "\n# source " + num(m.source_vertices) + " " +
                           num(m.source.faces) + " " + hs + "\n# target " + num(m.target_vertices) + " " +
                           num(m.target.faces) + " " + ht + "\n";
  file.write(head.data(), head.size());
  std::vector<char> buf;
  buf.reserve(size_t(1) << 20);
  auto flush = [&] {
    file.write(buf.data(), buf.size());
    buf.clear();
  };
  auto put_uint = [&](uint64_t v) {
    char t[24];
    buf.insert(buf.end(), t, std::to_chars(t, t + sizeof t, v).ptr);
  };
  auto put_real = [&](double v) {
    char t[32];
    buf.insert(buf.end(), t, std::to_chars(t, t + sizeof t, v).ptr);
  };
  for (size_t f = 0; f < m.source.faces; ++f) {
    buf.push_back('f');
    for (int j = 0; j < 3; ++j) buf.push_back(' '), put_uint(m.source_faces[3 * f + j]);
    buf.push_back('\n');
    if (buf.size() > (size_t(1) << 20)) flush();
  }
  for (size_t i = 0; i < m.source_vertices; ++i) {
    buf.push_back('v');
    buf.push_back(' ');
    put_uint(m.face[i]);
    for (int j = 0; j < 3; ++j) buf.push_back(' '), put_real(m.bary[3 * i + j]);
    buf.push_back('\n');
    if (buf.size() > (size_t(1) << 20)) {
      flush();
      report_progress(progress, double(i) / double(m.source_vertices), "writing");
    }
  }
  flush();
  file.commit();
}

// The map's text lines, blank ones skipped, read with the text formats' tokenizer.
struct TextReader {
  const std::string& path;
  detail::LineReader lines;
  detail::Line l{};

  [[noreturn]] void fail(const std::string& what) const { detail::fail_at_line(path, l.number, what); }
  bool next() {
    while (lines.next(l))
      if (!detail::at_end(l.b, l.e)) return true;
    return false;
  }
  std::string_view current() const { return std::string_view(l.b, size_t(l.e - l.b)); }
  template <class T, int Base = 10>
  T number(const char*& p, const char* what) const {
    T v{};
    if (!detail::parse_number<Base>(p, l.e, v)) fail(std::string("expected ") + what);
    return v;
  }
  void expect_end(const char* p) const {
    if (!detail::at_end(p, l.e)) fail("unexpected text at the end of the line");
  }
};

SurfaceMap read_text(const std::string& path, const std::vector<char>& data) {
  TextReader r{path, detail::LineReader(data.data(), data.data() + data.size())};
  const std::string first = "# slicereuse map " + num(kFormatVersion);
  if (!r.next() || r.l.number != 1 || r.current().substr(0, 16) != "# slicereuse map")
    throw Error("'" + path + "': not a slicereuse map file: it must start with '" + first + "' (text) or the binary magic");
  if (r.current() != first) r.fail("the first line must be '" + first + "' (other versions are not supported)");
  SurfaceMap m;
  for (const char* key : {"# source ", "# target "}) {
    if (!r.next() || r.current().substr(0, 9) != key) r.fail(std::string("expected '") + key + "<vertices> <faces> <hash>'");
    const char* at = r.l.b + 9;
    const bool source = key[2] == 's';
    (source ? m.source_vertices : m.target_vertices) = r.number<uint64_t>(at, "a vertex count");
    Fingerprint& fp = source ? m.source : m.target;
    fp.faces = r.number<uint64_t>(at, "a face count");
    fp.hash = r.number<uint64_t, 16>(at, "a 16-digit hexadecimal hash");
    r.expect_end(at);
  }
  // Each face and vertex line takes at least 8 bytes: counts beyond that are corrupt.
  if (m.source.faces > data.size() / 8 || m.source_vertices > data.size() / 8)
    r.fail("the header claims " + num(m.source.faces) + " source faces and " + num(m.source_vertices) +
           " vertices, more than the file can hold (truncated file?)");
  m.source_faces.resize(3 * m.source.faces);
  m.face.resize(m.source_vertices);
  m.bary.resize(3 * m.source_vertices);
  for (uint64_t f = 0; f < m.source.faces; ++f) {
    if (!r.next()) r.fail("the file ends after " + num(f) + " of " + num(m.source.faces) + " face lines (truncated file?)");
    if (r.current().substr(0, 2) != "f ") r.fail("expected a face line 'f <a> <b> <c>'");
    const char* at = r.l.b + 2;
    for (int j = 0; j < 3; ++j) m.source_faces[3 * f + j] = r.number<uint32_t>(at, "a vertex index");
    r.expect_end(at);
  }
  for (uint64_t i = 0; i < m.source_vertices; ++i) {
    if (!r.next()) r.fail("the file ends after " + num(i) + " of " + num(m.source_vertices) + " vertex lines (truncated file?)");
    if (r.current().substr(0, 2) != "v ") r.fail("expected a vertex line 'v <face> <b0> <b1> <b2>'");
    const char* at = r.l.b + 2;
    m.face[i] = r.number<uint32_t>(at, "a target face id");
    for (int j = 0; j < 3; ++j) m.bary[3 * i + j] = r.number<double>(at, "a number");
    r.expect_end(at);
  }
  if (r.next()) r.fail("unexpected line after the last vertex line");
  return m;
}

}  // namespace

void write_map_file(const std::string& path, const SurfaceMap& map, const Progress& progress) {
  try {
    validate_surface_map(map);
  } catch (const Error& e) {
    throw Error("cannot write the map file '" + path + "': " + e.what());
  }
  if (is_binary_file_name(path))
    write_binary(path, map, progress);
  else
    write_text(path, map, progress);
}

SurfaceMap read_map_file(const std::string& path, const Progress& progress) {
  const detail::InputFile f = detail::open_input_file(path, "the map file");
  const uint64_t size = f.size();
  char head[sizeof kBinaryMagic] = {};
  const size_t got = std::fread(head, 1, sizeof head, f.get());
  std::rewind(f.get());
  SurfaceMap m;
  if (got == sizeof head && std::memcmp(head, kBinaryMagic, sizeof head) == 0) {
    m = read_binary(path, f.get(), size, progress);
  } else {
    std::vector<char> data(size);
    if (size && std::fread(data.data(), 1, size, f.get()) != size)
      throw Error("cannot read '" + path + "': " + std::strerror(errno));
    m = read_text(path, data);
  }
  report_progress(progress, 1, "reading");
  try {
    validate_surface_map(m);
  } catch (const Error& e) {
    throw Error("'" + path + "': " + e.what());
  }
  return m;
}

}  // namespace slicereuse
