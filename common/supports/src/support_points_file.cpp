#include "slicereuse/supports/support_points_file.h"

#include <cstdio>
#include <string_view>
#include <vector>

#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"
#include "slicereuse/util/input_file.h"
#include "slicereuse/util/text_tokens.h"

namespace slicereuse {
namespace {

constexpr std::string_view kMagic = "slicereuse support points 1";
// A point line holds 12 numbers of at least one byte and a blank each: a count larger than the
// bytes left allows is refused before anything is allocated for it.
constexpr size_t kMinLineBytes = 24;

// "<key> <number>" on its own line.
uint64_t header_number(detail::LineReader& lines, const std::string& name, std::string_view key, const char* what) {
  detail::Line l;
  if (!lines.next(l)) throw Error("'" + name + "': the file ends in its header; expected '" + std::string(key) + " " + what + "'");
  const char* p = l.b;
  std::string_view word;
  uint64_t v = 0;
  if (!detail::next_word(p, l.e, word) || word != key)
    detail::fail_at_line(name, l.number, "expected '" + std::string(key) + " " + what + "', found " + detail::quoted_token(l.b, l.e));
  if (!detail::parse_number(p, l.e, v))
    detail::fail_at_line(name, l.number, std::string(what) + " expected, found " + detail::quoted_token(p, l.e));
  if (!detail::at_end(p, l.e)) detail::fail_at_line(name, l.number, "unexpected text " + detail::quoted_token(p, l.e));
  return v;
}

}  // namespace

void write_support_points(const std::string& path, const SupportPoints& points) {
  validate_support_points(points);
  AtomicFile f(path);
  std::string out = format("%s\nmesh %llu %016llx\npoints %zu\n", std::string(kMagic).c_str(),
                           (unsigned long long)points.fingerprint.faces, (unsigned long long)points.fingerprint.hash,
                           points.size());
  char line[512];
  for (size_t i = 0; i < points.size(); ++i) {
    const double* b = &points.bary[3 * i];
    const double* x = &points.xyz[3 * i];
    const double* n = &points.normal[3 * i];
    const int len = std::snprintf(line, sizeof line, "%u %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %u %u\n",
                                  points.face[i], b[0], b[1], b[2], x[0], x[1], x[2], n[0], n[1], n[2],
                                  unsigned(points.kind[i]), points.layer[i]);
    out.append(line, size_t(len));
    if (out.size() > (1u << 20)) {
      f.write(out.data(), out.size());
      out.clear();
    }
  }
  f.write(out.data(), out.size());
  f.commit();
}

SupportPoints parse_support_points(const char* data, size_t size, const std::string& name) {
  const char* e = data + size;
  detail::LineReader lines(data, e);
  detail::Line l;
  if (!lines.next(l) || std::string_view(l.b, size_t(l.e - l.b)) != kMagic)
    throw Error("'" + name + "' is not a support-points file: its first line is not '" + std::string(kMagic) + "'");
  SupportPoints pts;
  {
    if (!lines.next(l)) throw Error("'" + name + "': the file ends in its header; expected 'mesh <faces> <hash>'");
    const char* p = l.b;
    std::string_view word;
    if (!detail::next_word(p, l.e, word) || word != "mesh" || !detail::parse_number(p, l.e, pts.fingerprint.faces) ||
        !detail::parse_number<16>(p, l.e, pts.fingerprint.hash) || !detail::at_end(p, l.e))
      detail::fail_at_line(name, l.number,
                           "expected 'mesh <faces> <16-digit hexadecimal hash>', found " + detail::quoted(l.b, l.e, [](char) { return false; }));
  }
  const uint64_t count = header_number(lines, name, "points", "<count>");
  if (count > size / kMinLineBytes)
    throw Error(format("'%s' says it has %llu points, but its %zu bytes cannot hold that many", name.c_str(),
                       (unsigned long long)count, size));
  const size_t n = size_t(count);
  pts.face.resize(n);
  pts.bary.resize(3 * n);
  pts.xyz.resize(3 * n);
  pts.normal.resize(3 * n);
  pts.kind.resize(n);
  pts.layer.resize(n);
  for (size_t i = 0; i < n; ++i) {
    if (!lines.next(l))
      throw Error(format("'%s' is truncated: it says %zu points and ends after %zu", name.c_str(), n, i));
    const char* p = l.b;
    unsigned kind = 0;
    bool ok = detail::parse_number(p, l.e, pts.face[i]);
    for (int j = 0; ok && j < 3; ++j) ok = detail::parse_number(p, l.e, pts.bary[3 * i + j]);
    for (int j = 0; ok && j < 3; ++j) ok = detail::parse_number(p, l.e, pts.xyz[3 * i + j]);
    for (int j = 0; ok && j < 3; ++j) ok = detail::parse_number(p, l.e, pts.normal[3 * i + j]);
    ok = ok && detail::parse_number(p, l.e, kind) && detail::parse_number(p, l.e, pts.layer[i]) && detail::at_end(p, l.e);
    if (!ok)
      detail::fail_at_line(name, l.number,
                           "expected '<face> <3 area coordinates> <x y z> <normal> <kind> <layer>', found " +
                               detail::quoted(l.b, l.e, [](char) { return false; }));
    if (kind > 1) detail::fail_at_line(name, l.number, format("kind %u; 0 (island) and 1 (overhang) exist", kind));
    pts.kind[i] = uint8_t(kind);
  }
  while (lines.next(l))
    if (!detail::at_end(l.b, l.e))
      detail::fail_at_line(name, l.number, format("text after the %zu points the header announces", n));
  try {
    validate_support_points(pts);
  } catch (const Error& err) {
    throw Error("'" + name + "': " + err.what());
  }
  return pts;
}

SupportPoints read_support_points(const std::string& path) {
  detail::InputFile in = detail::open_input_file(path, "the support-points file");
  std::vector<char> bytes(size_t(in.size()));
  if (!bytes.empty() && std::fread(bytes.data(), 1, bytes.size(), in.get()) != bytes.size())
    throw Error("cannot read the support-points file '" + path + "'");
  return parse_support_points(bytes.data(), bytes.size(), path);
}

}  // namespace slicereuse
