// CLI reader (cli_file.h, docs/formats.md "CLI"). The whole file is read into memory, then
// walked twice by the same parser: the first walk validates the structure and counts layers,
// polylines and points (every count is checked against the bytes present, so a lying count
// fails before anything is allocated for it); the second walk fills arrays of exactly that size.
#include <sys/stat.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>

#include "slicereuse/formats/cli_file.h"
#include "slicereuse/util/buffer.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/input_file.h"
#include "slicereuse/util/text_tokens.h"

namespace slicereuse {
namespace {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "CLI binary I/O assumes a little-endian host");

enum Command : uint16_t {
  kLayerLong = 127, kLayerShort = 128, kPolylineShort = 129, kPolylineLong = 130,
  kHatchesShort = 131, kHatchesLong = 132
};
constexpr std::string_view kHeaderStart = "$$HEADERSTART", kHeaderEnd = "$$HEADEREND";

std::string real(double v) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

// Where in the file an error is: a line for text, a byte offset for binary data.
struct Where {
  bool line;
  uint64_t n;
  std::string text() const { return (line ? "line " : "byte ") + std::to_string(n); }
};

class Reader {
 public:
  Reader(const std::string& path, const char* b) : path_(path), b_(b), line_pos_(b) {}
  [[noreturn]] void fail(const std::string& what) const {
    throw Error("CLI file '" + path_ + "': " + what);
  }
  [[noreturn]] void fail(const Where& w, const std::string& what) const {
    fail(w.text() + ": " + what);
  }
  Where line_at(const char* p) {
    // Lines are counted incrementally: the parser only moves forward within one walk.
    if (p < line_pos_) line_pos_ = b_, line_ = 1;
    for (; line_pos_ < p; ++line_pos_) line_ += *line_pos_ == '\n';
    return {true, line_};
  }
  Where byte_at(const char* p) const { return {false, uint64_t(p - b_)}; }
  const std::string& path() const { return path_; }

 private:
  const std::string& path_;
  const char* b_;
  const char* line_pos_;
  uint64_t line_ = 1;
};

// A command's parameters run to the next "$$", over line ends: blanks are also '\r' and '\n'.
constexpr bool kAcrossLines = true;
using detail::is_blank;
using detail::skip_blanks;

// The text at p, to the end of its line, for messages.
std::string quote(const char* p, const char* e) {
  return detail::quoted(p, e, [](char c) { return c == '\n' || c == '\r'; });
}

// One comma-separated field of an ASCII command: blanks, an optional '+', the number, blanks,
// then a comma or the end of the parameters.
template <class T>
bool field(const char*& p, const char* e, T& v) {
  p = skip_blanks<kAcrossLines>(p, e);
  if (p < e && *p == '+') ++p;
  if (!detail::from_chars_number(p, e, v)) return false;
  p = skip_blanks<kAcrossLines>(p, e);
  if (p < e) {
    if (*p != ',') return false;
    ++p;
  }
  return true;
}

const char* find(const char* p, const char* e, std::string_view what) {
  if (p >= e) return nullptr;
  const void* at = memmem(p, size_t(e - p), what.data(), what.size());
  return at ? static_cast<const char*>(at) : nullptr;
}

// The next "$$" at or after p, or e.
const char* next_command(const char* p, const char* e) {
  const char* q = find(p, e, "$$");
  return q ? q : e;
}

struct Header {
  bool ascii = false, binary = false;
  bool has_units = false;
  double units = 1;
  bool has_layers = false;
  uint64_t layers = 0;
  const char* geometry = nullptr;  // first byte after $$HEADEREND
};

Header parse_header(Reader& r, const char* b, const char* e) {
  Header h;
  const char* p = skip_blanks<kAcrossLines>(b, e);
  if (size_t(e - p) < kHeaderStart.size() || std::string_view(p, kHeaderStart.size()) != kHeaderStart)
    r.fail("not a CLI file: it does not start with $$HEADERSTART");
  const char* end = find(p, e, kHeaderEnd);
  if (!end) r.fail("the header has no $$HEADEREND: the file is truncated or not a CLI file");
  h.geometry = end + kHeaderEnd.size();
  p += kHeaderStart.size();
  while ((p = next_command(p, end)) < end) {
    const char* name = p + 2;
    const char* q = name;
    while (q < end && *q != '/' && !is_blank<kAcrossLines>(*q) && *q != '$') ++q;
    const std::string_view cmd(name, size_t(q - name));
    const char* params = q < end && *q == '/' ? q + 1 : q;
    const char* params_end = next_command(params, end);
    const Where at = r.line_at(p);
    auto number = [&](auto& v, const char* form) {
      const char* s = params;
      if (!field(s, params_end, v) || skip_blanks<kAcrossLines>(s, params_end) != params_end)
        r.fail(at, "expected " + std::string(form) + ", found " + quote(p, end));
    };
    if (cmd == "ASCII") {
      h.ascii = true;
    } else if (cmd == "BINARY") {
      h.binary = true;
    } else if (cmd == "UNITS") {
      if (h.has_units) r.fail(at, "repeated $$UNITS");
      h.has_units = true;
      number(h.units, "$$UNITS/<millimetres per unit>");
      if (!std::isfinite(h.units) || h.units <= 0)
        r.fail(at, "$$UNITS/" + real(h.units) + " is not a positive number");
    } else if (cmd == "LAYERS") {
      if (h.has_layers) r.fail(at, "repeated $$LAYERS");
      h.has_layers = true;
      number(h.layers, "$$LAYERS/<number of layers>");
    } else if (cmd == "HEADERSTART") {
      r.fail(at, "repeated $$HEADERSTART");
    }
    // $$VERSION, $$DATE, $$DIMENSION, $$LABEL, $$ALIGN, $$USERDATA and vendor extensions carry
    // nothing the contours need.
    p = params_end;
  }
  if (h.ascii == h.binary)
    r.fail(h.ascii ? "the header says both $$ASCII and $$BINARY"
                   : "the header says neither $$ASCII nor $$BINARY");
  if (!h.has_units) r.fail("the header has no $$UNITS");
  return h;
}

// Receives the geometry of one walk. Pass 1 (fill == false) counts; pass 2 fills s.
struct Sink {
  Reader& r;
  double units;
  bool fill = false;
  uint64_t layers = 0, contours = 0, points = 0;  // points: before dropping repeated ends
  Slices* s = nullptr;
  uint64_t p = 0;  // points written (pass 2)
  double last_z = 0;

  void layer(const Where& at, double z) {
    z *= units;
    if (!std::isfinite(z)) r.fail(at, "layer " + std::to_string(layers) + ": z is not a finite number");
    if (layers > 0 && !(z > last_z))
      r.fail(at, "layer " + std::to_string(layers) + " at z = " + real(z) +
                     " is not above the previous layer (z = " + real(last_z) + ")");
    last_z = z;
    if (fill) {
      s->layer_z[layers] = z;
      s->layer_begin[layers] = contours;
    }
    ++layers;
  }
  // next(x, y) reads the polyline's next point (raw file units); called only when filling.
  template <class Next>
  void polyline(const Where& at, int64_t dir, int64_t n, Next&& next) {
    if (layers == 0) r.fail(at, "a polyline before the first layer");
    if (dir < 0 || dir > 2)
      r.fail(at, "polyline direction " + std::to_string(dir) + " is not 0, 1 or 2");
    if (n < 1) r.fail(at, "a polyline with " + std::to_string(n) + " points");
    if (fill) {
      const uint64_t first = p;
      const std::string where = "layer " + std::to_string(layers - 1) + ", polyline " +
                                std::to_string(contours - s->layer_begin[layers - 1]);
      for (int64_t i = 0; i < n; ++i) {
        double x = 0, y = 0;
        next(x, y);
        x *= units;
        y *= units;
        if (!std::isfinite(x) || !std::isfinite(y))
          r.fail(at, where + ", point " + std::to_string(i) + ": a coordinate is not a finite number");
        double* q = &s->xyz[3 * p];
        q[0] = x;
        q[1] = y;
        q[2] = last_z;
        ++p;
      }
      // A closed polyline repeats its first point at the end; the loop closes implicitly here.
      const double* a = &s->xyz[3 * first];
      const double* z = &s->xyz[3 * (p - 1)];
      if (dir != 2 && p - first >= 2 && a[0] == z[0] && a[1] == z[1]) --p;
      s->contour_open[contours] = dir == 2;
      s->contour_begin[contours + 1] = p;
    }
    ++contours;
    points += uint64_t(n);
  }
};

void walk_ascii(Reader& r, const char* b, const char* e, Sink& sink, const Progress& progress) {
  const char* p = skip_blanks<kAcrossLines>(b, e);
  constexpr std::string_view start = "$$GEOMETRYSTART";
  if (size_t(e - p) < start.size() || std::string_view(p, start.size()) != start)
    r.fail(r.line_at(p), "expected $$GEOMETRYSTART after the header, found " + quote(p, e));
  p += start.size();
  uint64_t next_report = 64 << 20;
  for (;;) {
    p = skip_blanks<kAcrossLines>(p, e);
    if (p == e) r.fail("the file ends before $$GEOMETRYEND: it is truncated");
    const Where at = r.line_at(p);
    if (e - p < 2 || p[0] != '$' || p[1] != '$') r.fail(at, "unexpected text " + quote(p, e));
    const char* name = p + 2;
    const char* q = name;
    while (q < e && *q != '/' && !is_blank<kAcrossLines>(*q) && *q != '$') ++q;
    const std::string_view cmd(name, size_t(q - name));
    const char* params = q < e && *q == '/' ? q + 1 : q;
    const char* params_end = next_command(params, e);
    const char* f = params;
    auto bad = [&](const char* form) { r.fail(at, std::string("expected ") + form + ", found " + quote(p, e)); };
    if (cmd == "GEOMETRYEND") return;
    if (cmd == "LAYER") {
      double z = 0;
      if (!field(f, params_end, z) || f != params_end) bad("$$LAYER/<z>");
      sink.layer(at, z);
    } else if (cmd == "POLYLINE") {
      int64_t id = 0, dir = 0, n = 0;
      if (!field(f, params_end, id) || !field(f, params_end, dir) || !field(f, params_end, n))
        bad("$$POLYLINE/<id>,<dir>,<n>,<x1>,<y1>,...");
      // Every point takes two fields: count the commas before trusting n.
      uint64_t commas = 0;
      for (const char* c = f; c < params_end; ++c) commas += *c == ',';
      const uint64_t fields = skip_blanks<kAcrossLines>(f, params_end) == params_end ? 0 : commas + 1;
      if (n < 0 || fields != 2 * uint64_t(n))
        r.fail(at, "$$POLYLINE says " + std::to_string(n) + " points but carries " +
                       std::to_string(fields) + " coordinates");
      sink.polyline(at, dir, n, [&](double& x, double& y) {
        const char* c = f;
        if (!field(f, params_end, x) || !field(f, params_end, y))
          r.fail(at, "a polyline coordinate is not a number: " +
                         quote(skip_blanks<kAcrossLines>(c, params_end), params_end));
      });
    } else if (cmd == "HATCHES") {
      // Infill, not contours: skipped.
    } else {
      r.fail(at, "unknown command " + quote(p, e));
    }
    p = params_end;
    if (sink.fill && uint64_t(p - b) >= next_report) {
      report_progress(progress, double(p - b) / double(e - b), "reading CLI");
      next_report += 64 << 20;
    }
  }
}

template <class T>
T get(const char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

void walk_binary(Reader& r, const char* b, const char* e, Sink& sink, const Progress& progress) {
  const char* p = b;
  // Some writers end the $$HEADEREND line; no command id starts with these bytes.
  if (e - p >= 2 && p[0] == '\r' && p[1] == '\n') p += 2;
  else if (p < e && p[0] == '\n') ++p;
  uint64_t next_report = 64 << 20;
  while (p < e) {
    const Where at = r.byte_at(p);
    const char* start = p;
    // bytes: the whole command from its id on.
    auto need = [&](uint64_t bytes, const char* what) {
      if (uint64_t(e - start) < bytes)
        r.fail(at, std::string(what) + " needs " + std::to_string(bytes) + " bytes but only " +
                       std::to_string(e - start) + " remain: the file is truncated");
    };
    need(2, "a command id");
    const uint16_t cmd = get<uint16_t>(p);
    p += 2;
    switch (cmd) {
      case kLayerLong:
        need(2 + 4, "a layer (long)");
        sink.layer(at, double(get<float>(p)));
        p += 4;
        break;
      case kLayerShort:
        need(2 + 2, "a layer (short)");
        sink.layer(at, double(get<uint16_t>(p)));
        p += 2;
        break;
      case kPolylineLong: {
        need(2 + 12, "a polyline header (long)");
        const int64_t dir = get<int32_t>(p + 4), n = get<int32_t>(p + 8);
        p += 12;
        if (n < 0) r.fail(at, "a polyline with " + std::to_string(n) + " points");
        need(2 + 12 + 8 * uint64_t(n), ("a polyline of " + std::to_string(n) + " points").c_str());
        const char* q = p;
        sink.polyline(at, dir, n, [&](double& x, double& y) {
          x = get<float>(q);
          y = get<float>(q + 4);
          q += 8;
        });
        p += 8 * uint64_t(n);
        break;
      }
      case kPolylineShort: {
        need(2 + 6, "a polyline header (short)");
        const int64_t dir = get<uint16_t>(p + 2), n = get<uint16_t>(p + 4);
        p += 6;
        need(2 + 6 + 4 * uint64_t(n), ("a polyline of " + std::to_string(n) + " points").c_str());
        const char* q = p;
        sink.polyline(at, dir, n, [&](double& x, double& y) {
          x = get<uint16_t>(q);
          y = get<uint16_t>(q + 2);
          q += 4;
        });
        p += 4 * uint64_t(n);
        break;
      }
      case kHatchesLong: {
        need(2 + 8, "a hatches header (long)");
        const int64_t n = get<int32_t>(p + 4);
        p += 8;
        if (n < 0) r.fail(at, "hatches with " + std::to_string(n) + " lines");
        need(2 + 8 + 16 * uint64_t(n), ("hatches of " + std::to_string(n) + " lines").c_str());
        p += 16 * uint64_t(n);
        break;
      }
      case kHatchesShort: {
        need(2 + 4, "a hatches header (short)");
        const uint64_t n = get<uint16_t>(p + 2);
        p += 4;
        need(2 + 4 + 8 * n, ("hatches of " + std::to_string(n) + " lines").c_str());
        p += 8 * n;
        break;
      }
      default:
        r.fail(at, "unknown command id " + std::to_string(cmd) +
                       " (expected 127-132): the file is corrupted");
    }
    if (sink.fill && uint64_t(p - b) >= next_report) {
      report_progress(progress, double(p - b) / double(e - b), "reading CLI");
      next_report += 64 << 20;
    }
  }
}

}  // namespace

Slices read_cli_file(const std::string& path, const Progress& progress) {
  Buffer<char> data;
  {
    const detail::InputFile f = detail::open_input_file(path, "the CLI file");
    data.resize(size_t(f.size()));
    if (!data.empty() && std::fread(data.data(), 1, data.size(), f.get()) != data.size())
      throw Error("cannot read '" + path + "': " + std::strerror(errno));
  }
  const char* b = data.data();
  const char* e = b + data.size();
  Reader r(path, b);
  const Header h = parse_header(r, b, e);

  auto walk = [&](Sink& sink) {
    if (h.binary)
      walk_binary(r, h.geometry, e, sink, progress);
    else
      walk_ascii(r, h.geometry, e, sink, progress);
  };
  Sink count{r, h.units};
  walk(count);
  if (h.has_layers && h.layers != count.layers)
    r.fail("$$LAYERS says " + std::to_string(h.layers) + " layers but the file has " +
           std::to_string(count.layers) + " (truncated?)");

  Slices s;
  s.layer_z.resize(count.layers);
  s.layer_begin.resize(count.layers + 1);
  s.layer_begin.back() = count.contours;
  s.contour_begin.resize(count.contours + 1);
  s.contour_begin[0] = 0;
  s.contour_open.resize(count.contours);
  s.xyz.resize(3 * count.points);
  Sink fill{r, h.units, true};
  fill.s = &s;
  walk(fill);
  s.xyz.resize(3 * fill.p);
  const size_t L = s.layers();
  s.thickness = L >= 2 ? (s.layer_z[L - 1] - s.layer_z[0]) / double(L - 1) : 1.0;
  s.z_start = L >= 1 ? s.layer_z[0] - s.thickness / 2 : 0.0;
  try {
    validate_slices(s);
  } catch (const Error& err) {
    r.fail(err.what());
  }
  report_progress(progress, 1, "reading CLI");
  return s;
}

}  // namespace slicereuse
