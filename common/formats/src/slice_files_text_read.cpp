// Text reader (.ctr / .enc, see docs/formats.md). One sequential pass splits the file into
// lines and checks the header and layer structure; two parallel passes over the contour lines
// then count their points and parse them with std::from_chars straight into the arrays.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "area_coordinates.h"
#include "slice_files_detail.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/parallel_blocks.h"
#include "slicereuse/util/text_tokens.h"

namespace slicereuse::detail {
namespace {

// Contour lines are parsed in blocks of about this many bytes of text.
constexpr size_t kBlockBytes = size_t(1) << 20;

[[noreturn]] void fail(const std::string& path, uint64_t line, const std::string& what) {
  fail_at_line(path, line, what);
}
[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw Error("'" + path + "': " + what);
}

bool comment_or_blank(const Line& l) { return l.b == l.e || *l.b == '#' || at_end(l.b, l.e); }

struct Header {
  bool has_thickness = false, has_z_start = false, has_counts = false, has_fingerprint = false;
  uint64_t layers = 0, contours = 0, points = 0;
};

void parse_first_line(const std::string& path, const Line& l, FileKind kind) {
  const char* p = l.b;
  std::string_view w;
  const std::string expected = "# slicereuse " + std::string(kind_word(kind)) + " " +
                               std::to_string(kFormatVersion);
  if (p == l.e || *p != '#' || !next_word(++p, l.e, w) || w != "slicereuse")
    fail(path, 1, "not a slicereuse file: it must start with '" + expected +
                      "' (text) or the binary magic");
  if (!next_word(p, l.e, w)) fail(path, 1, "the first line names no kind, expected '" + expected + "'");
  if (w != kind_word(kind)) {
    const FileKind other = kind == FileKind::Contours ? FileKind::Encoding : FileKind::Contours;
    if (w == kind_word(other))
      fail(path, 1, "this is " + std::string(kind_noun(other)) + ", expected " + kind_noun(kind));
    fail(path, 1, "unknown file kind '" + std::string(w) + "'");
  }
  unsigned version = 0;
  if (!parse_number(p, l.e, version) || !at_end(p, l.e))
    fail(path, 1, "the first line must be '" + expected + "'");
  if (version != kFormatVersion)
    fail(path, 1, "format version " + std::to_string(version) +
                      " is not supported (this build reads version " +
                      std::to_string(kFormatVersion) + ")");
}

// One "# key ..." line; unknown keys are comments.
void parse_header_line(const std::string& path, const Line& l, Header& h, Slices& s) {
  const char* p = l.b + 1;
  const char* e = l.e;
  std::string_view key;
  if (!next_word(p, e, key)) return;
  auto bad = [&](const char* form) { fail(path, l.number, std::string("expected '# ") + form + "'"); };
  auto once = [&](bool& seen) {
    if (seen) fail(path, l.number, "repeated header line '# " + std::string(key) + "'");
    seen = true;
  };
  if (key == "thickness") {
    once(h.has_thickness);
    if (!parse_number(p, e, s.thickness) || !at_end(p, e)) bad("thickness <h>");
  } else if (key == "z_start") {
    once(h.has_z_start);
    if (!parse_number(p, e, s.z_start) || !at_end(p, e)) bad("z_start <z>");
  } else if (key == "layers") {
    once(h.has_counts);
    std::string_view w1, w2;
    if (!parse_number(p, e, h.layers) || !next_word(p, e, w1) || w1 != "contours" ||
        !parse_number(p, e, h.contours) || !next_word(p, e, w2) || w2 != "points" ||
        !parse_number(p, e, h.points) || !at_end(p, e))
      bad("layers <L> contours <C> points <P>");
  } else if (key == "fingerprint") {
    once(h.has_fingerprint);
    if (!parse_number(p, e, s.fingerprint.faces) || !parse_number<16>(p, e, s.fingerprint.hash) || !at_end(p, e))
      bad("fingerprint <faces> <16 hex digits>");
  }
}

// Parses "layer <k> <z> <n>"; returns n.
uint64_t parse_layer_line(const std::string& path, const Line& l, Slices& s) {
  const char* p = l.b;
  std::string_view w;
  uint64_t k = 0, n = 0;
  double z = 0;
  if (!next_word(p, l.e, w) || w != "layer")
    fail(path, l.number, "expected 'layer <k> <z> <n>', found " + quoted_token(l.b, l.e));
  if (!parse_number(p, l.e, k) || !parse_number(p, l.e, z) || !parse_number(p, l.e, n) || !at_end(p, l.e))
    fail(path, l.number, "expected 'layer <k> <z> <n>'");
  if (k != s.layers())
    fail(path, l.number, "layer " + std::to_string(k) + " where layer " +
                             std::to_string(s.layers()) + " was expected (layers count 0, 1, 2, ...)");
  if (!std::isfinite(z)) fail(path, l.number, "layer height is not finite");
  s.layer_z.push_back(z);
  return n;
}

// Runs f(c) for every contour line on all cores, in blocks of about kBlockBytes of text, with
// progress mapped into [from, to].
template <class F>
void for_contour_lines(const std::vector<Line>& lines, const Progress& progress, double from,
                       double to, F f) {
  std::vector<size_t> first{0};
  for (size_t c = 1; c < lines.size(); ++c)
    if (size_t(lines[c].b - lines[first.back()].b) >= kBlockBytes) first.push_back(c);
  first.push_back(lines.size());
  parallel_blocks(
      first.size() - 1,
      [&](size_t b) {
        for (size_t c = first[b]; c < first[b + 1]; ++c) f(c);
      },
      sub_progress(progress, from, to), "reading");
}

// Counts the points of a contour line and notes whether it starts with "open".
uint64_t count_points(const std::string& path, const Line& l, size_t per_point, uint8_t& open) {
  const char* p = skip_blanks(l.b, l.e);
  open = l.e - p >= 4 && std::memcmp(p, "open", 4) == 0 && (l.e - p == 4 || is_blank(p[4]));
  if (open) p += 4;
  uint64_t tokens = 0;
  bool in_token = false;
  for (; p < l.e; ++p) {
    const bool s = !is_blank(*p);
    tokens += s && !in_token;
    in_token = s;
  }
  if (tokens == 0) fail(path, l.number, "contour line has no points");
  if (tokens % per_point)
    fail(path, l.number, std::to_string(tokens) + " numbers, expected " +
                             (per_point == 3 ? "whole triples 'x y z'" : "whole quads 'f l1 l2 l3'"));
  return tokens / per_point;
}

// open: the line starts with "open" (count_points has checked the line's form).
void parse_contour_points(const std::string& path, const Line& l, bool open, double* xyz,
                          uint64_t n) {
  const char* p = skip_blanks(l.b, l.e) + (open ? 4 : 0);
  for (uint64_t i = 0; i < 3 * n; ++i) {
    const char* at = p;
    if (!parse_number(p, l.e, xyz[i]) || !std::isfinite(xyz[i]))
      fail(path, l.number, "point " + std::to_string(i / 3 + 1) + ": " + quoted_token(at, l.e) +
                               " is not a finite number");
  }
}

void parse_encoding_points(const std::string& path, const Line& l, bool open,
                           const Fingerprint& fp, uint32_t* face, uint8_t* edge, double* t,
                           uint64_t n) {
  const char* p = skip_blanks(l.b, l.e) + (open ? 4 : 0);
  for (uint64_t i = 0; i < n; ++i) {
    auto bad = [&](const std::string& what) {
      fail(path, l.number, "point " + std::to_string(i + 1) + ": " + what);
    };
    const char* at = p;
    uint64_t f = 0;
    if (!parse_number(p, l.e, f)) bad(quoted_token(at, l.e) + " is not a face id");
    if (f >= fp.faces || f > UINT32_MAX)
      bad("face " + std::to_string(f) + " does not exist: the mesh has " +
          std::to_string(fp.faces) + " faces");
    double lambda[3];
    for (double& v : lambda) {
      at = p;
      if (!parse_number(p, l.e, v) || !std::isfinite(v))
        bad(quoted_token(at, l.e) + " is not a finite number");
      if (v < 0) bad("negative area coordinate " + quoted_token(at, l.e));
    }
    uint8_t j = 0;
    double ti = 0;
    if (const char* why = decode_area_coordinates(lambda, j, ti)) bad(why);
    face[i] = uint32_t(f);
    edge[i] = j;
    t[i] = ti;
  }
}

}  // namespace

Slices read_text(const std::string& path, const Buffer<char>& data, FileKind kind,
                 const Progress& progress) {
  Slices s;
  LineReader reader(data.data(), data.data() + data.size());
  Line l;
  if (!reader.next(l)) fail(path, "empty file");
  parse_first_line(path, l, kind);

  Header h;
  bool body = false;
  while ((body = reader.next(l)) && comment_or_blank(l))
    if (l.b != l.e && *l.b == '#') parse_header_line(path, l, h, s);
  const char* missing = !h.has_thickness ? "# thickness <h>"
                        : !h.has_z_start ? "# z_start <z>"
                        : !h.has_counts  ? "# layers <L> contours <C> points <P>"
                        : kind == FileKind::Encoding && !h.has_fingerprint
                            ? "# fingerprint <faces> <hash>"
                            : nullptr;
  if (missing) fail(path, "the header lacks the line '" + std::string(missing) + "'");

  // Structure pass: layer lines and the lines of their contours.
  std::vector<Line> lines;
  lines.reserve(std::min<uint64_t>(h.contours, data.size() / 2));
  s.layer_begin.push_back(0);
  uint64_t pending = 0;  // contour lines still due in the current layer
  for (; body; body = reader.next(l)) {
    if (comment_or_blank(l)) continue;
    if (pending == 0) {
      pending = parse_layer_line(path, l, s);
      s.layer_begin.push_back(lines.size() + pending);
    } else {
      lines.push_back(l);
      --pending;
    }
  }
  if (pending)
    fail(path, "the file ends inside layer " + std::to_string(s.layers() - 1) + ", " +
                   std::to_string(pending) + " contour lines short (truncated file?)");
  if (s.layers() != h.layers || lines.size() != h.contours)
    fail(path, "the header announces " + std::to_string(h.layers) + " layers and " +
                   std::to_string(h.contours) + " contours, the file has " +
                   std::to_string(s.layers()) + " and " + std::to_string(lines.size()) +
                   " (truncated file?)");
  report_progress(progress, 0.1, "reading");

  const size_t C = lines.size();
  const size_t per_point = kind == FileKind::Contours ? 3 : 4;
  s.contour_open.resize(C);
  s.contour_begin.assign(C + 1, 0);
  for_contour_lines(lines, progress, 0.1, 0.3, [&](size_t c) {
    s.contour_begin[c + 1] = count_points(path, lines[c], per_point, s.contour_open[c]);
  });
  for (size_t c = 0; c < C; ++c) s.contour_begin[c + 1] += s.contour_begin[c];
  if (s.points() != h.points)
    fail(path, "the header announces " + std::to_string(h.points) + " points, the file has " +
                   std::to_string(s.points()));

  const size_t P = s.points();
  if (kind == FileKind::Contours) {
    s.xyz.resize(3 * P);
    for_contour_lines(lines, progress, 0.3, 1, [&](size_t c) {
      const uint64_t p0 = s.contour_begin[c];
      parse_contour_points(path, lines[c], s.contour_open[c], s.xyz.data() + 3 * p0,
                           s.contour_begin[c + 1] - p0);
    });
  } else {
    s.face.resize(P);
    s.edge.resize(P);
    s.t.resize(P);
    for_contour_lines(lines, progress, 0.3, 1, [&](size_t c) {
      const uint64_t p0 = s.contour_begin[c];
      parse_encoding_points(path, lines[c], s.contour_open[c], s.fingerprint, s.face.data() + p0,
                            s.edge.data() + p0, s.t.data() + p0, s.contour_begin[c + 1] - p0);
    });
  }
  try {
    validate_slices(s);
  } catch (const Error& e) {
    fail(path, e.what());
  }
  return s;
}

}  // namespace slicereuse::detail
