// CLI writer (cli_file.h, docs/formats.md "CLI"). Output is produced layer by layer into a
// buffer that is flushed to the atomic file every few MB.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "slicereuse/formats/cli_file.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {
namespace {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "CLI binary I/O assumes a little-endian host");

constexpr size_t kFlushBytes = size_t(4) << 20;
constexpr uint16_t kLayerLong = 127, kPolylineLong = 130;
enum Direction : int32_t { kClockwise = 0, kCounterClockwise = 1, kOpen = 2 };

std::string real(double v) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

class Output {
 public:
  explicit Output(AtomicFile& f) : file_(f) {}
  void text(const char* s, size_t n) { buffer_.append(s, n); }
  void text(const std::string& s) { buffer_ += s; }
  void number(double v) {
    char buf[32];
    buffer_.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
  }
  void number(uint64_t v) {
    char buf[24];
    buffer_.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
  }
  template <class T>
  void binary(T v) {
    buffer_.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void maybe_flush() {
    if (buffer_.size() >= kFlushBytes) flush();
  }
  void flush() {
    file_.write(buffer_.data(), buffer_.size());
    buffer_.clear();
  }

 private:
  AtomicFile& file_;
  std::string buffer_;
};

struct Box {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
};

// x, y over all points; z over the layers' slabs (layer z -/+ thickness/2).
Box dimension(const Slices& s) {
  Box b;
  const size_t P = s.points();
  for (size_t p = 0; p < P; ++p)
    for (int a = 0; a < 2; ++a) {
      const double v = s.xyz[3 * p + a];
      if (p == 0 || v < b.lo[a]) b.lo[a] = v;
      if (p == 0 || v > b.hi[a]) b.hi[a] = v;
    }
  for (size_t k = 0; k < s.layers(); ++k) {
    const double lo = s.layer_z[k] - s.thickness / 2, hi = s.layer_z[k] + s.thickness / 2;
    if (k == 0 || lo < b.lo[2]) b.lo[2] = lo;
    if (k == 0 || hi > b.hi[2]) b.hi[2] = hi;
  }
  return b;
}

std::string header(const Slices& s, CliEncoding encoding) {
  const Box b = dimension(s);
  std::string h = "$$HEADERSTART\n";
  h += encoding == CliEncoding::Binary ? "$$BINARY\n" : "$$ASCII\n";
  h += "$$UNITS/1\n$$VERSION/200\n$$DATE/" + utc_time(creation_time(), "%d%m%y") + "\n";
  h += "$$DIMENSION/" + real(b.lo[0]) + "," + real(b.lo[1]) + "," + real(b.lo[2]) + "," +
       real(b.hi[0]) + "," + real(b.hi[1]) + "," + real(b.hi[2]) + "\n";
  h += "$$LAYERS/" + std::to_string(s.layers()) + "\n";
  // Binary data follows $$HEADEREND immediately: no line end (readers take the next byte as
  // the first command).
  h += encoding == CliEncoding::Binary ? "$$HEADEREND" : "$$HEADEREND\n$$GEOMETRYSTART\n";
  return h;
}

[[noreturn]] void fail(const std::string& path, size_t k, const std::string& what) {
  throw Error("cannot write CLI file '" + path + "': layer " + std::to_string(k) + ": " + what);
}

float to_float(const std::string& path, size_t k, double v) {
  const float f = float(v);
  if (!std::isfinite(f))
    fail(path, k, "coordinate " + real(v) + " does not fit in a float32 (binary CLI)");
  return f;
}

}  // namespace

void write_cli_file(const std::string& path, const Slices& s, CliEncoding encoding,
                    const Progress& progress) {
  try {
    validate_slices(s);
    if (!s.has_points()) throw Error("the slices carry no contour points (xyz)");
  } catch (const Error& e) {
    throw Error("cannot write CLI file '" + path + "': " + e.what());
  }
  const bool binary = encoding == CliEncoding::Binary;
  AtomicFile file(path);
  Output out(file);
  out.text(header(s, encoding));
  const size_t L = s.layers();
  for (size_t k = 0; k < L; ++k) {
    if (binary) {
      out.binary(kLayerLong);
      out.binary(to_float(path, k, s.layer_z[k]));
    } else {
      out.text("$$LAYER/", 8);
      out.number(s.layer_z[k]);
      out.text("\n", 1);
    }
    for (uint64_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c) {
      const uint64_t b = s.contour_begin[c], n = s.contour_begin[c + 1] - b;
      const bool open = s.contour_open[c] != 0;
      const int32_t dir = open ? kOpen : contour_area(s, c) > 0 ? kCounterClockwise : kClockwise;
      const uint64_t count = n + (open ? 0 : 1);  // a closed polyline repeats its first point
      if (count > uint64_t(std::numeric_limits<int32_t>::max()))
        fail(path, k, "contour " + std::to_string(c) + " has more points than CLI can count");
      if (binary) {
        out.binary(kPolylineLong);
        out.binary(int32_t(1));  // id: one part per file
        out.binary(dir);
        out.binary(int32_t(count));
        for (uint64_t i = 0; i < count; ++i) {
          const double* p = &s.xyz[3 * (b + (i == n ? 0 : i))];
          out.binary(to_float(path, k, p[0]));
          out.binary(to_float(path, k, p[1]));
        }
      } else {
        out.text("$$POLYLINE/1,", 13);
        out.number(uint64_t(dir));
        out.text(",", 1);
        out.number(count);
        for (uint64_t i = 0; i < count; ++i) {
          const double* p = &s.xyz[3 * (b + (i == n ? 0 : i))];
          out.text(",", 1);
          out.number(p[0]);
          out.text(",", 1);
          out.number(p[1]);
        }
        out.text("\n", 1);
      }
      out.maybe_flush();
    }
    if (k % 256 == 255) report_progress(progress, double(k + 1) / double(L), "writing CLI");
  }
  if (!binary) out.text("$$GEOMETRYEND\n");
  out.flush();
  file.commit();
}

}  // namespace slicereuse
