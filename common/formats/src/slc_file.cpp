// SLC writer (slc_file.h, docs/formats.md "SLC").
#include "slicereuse/formats/slc_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"

namespace slicereuse {
namespace {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "SLC I/O assumes a little-endian host");

constexpr size_t kFlushBytes = size_t(4) << 20;
constexpr size_t kReservedBytes = 256;
constexpr size_t kMaxHeaderBytes = 2048;
constexpr uint32_t kTermination = 0xFFFFFFFFu;

std::string real(double v) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw Error("cannot write SLC file '" + path + "': " + what);
}

template <class T>
void put(std::string& out, T v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

float to_float(const std::string& path, size_t k, double v) {
  const float f = float(v);
  if (!std::isfinite(f))
    fail(path, "layer " + std::to_string(k) + ": " + real(v) + " does not fit in a float32");
  return f;
}

}  // namespace

SlcExportStats write_slc_file(const std::string& path, const Slices& s, const Progress& progress) {
  try {
    validate_slices(s);
    if (!s.has_points()) throw Error("the slices carry no contour points (xyz)");
  } catch (const Error& e) {
    fail(path, e.what());
  }
  const size_t L = s.layers();
  const double h = s.thickness;
  // Extents of what is written: closed contours in x and y, the layers' slabs in z.
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool any = false;
  for (size_t c = 0; c < s.contours(); ++c) {
    if (s.contour_open[c]) continue;
    for (uint64_t p = s.contour_begin[c]; p < s.contour_begin[c + 1]; ++p, any = true)
      for (int a = 0; a < 2; ++a) {
        const double v = s.xyz[3 * p + a];
        lo[a] = any ? std::min(lo[a], v) : v;
        hi[a] = any ? std::max(hi[a], v) : v;
      }
  }
  const double z_bottom = L ? s.layer_z[0] - h / 2 : s.z_start;
  const double z_top = L ? s.layer_z[L - 1] + h / 2 : s.z_start;
  lo[2] = z_bottom;
  hi[2] = z_top;

  std::string out = "-SLCVER 2.0 -UNIT MM -TYPE PART -PACKAGE slicereuse -EXTENTS " +
                    real(lo[0]) + "," + real(hi[0]) + " " + real(lo[1]) + "," + real(hi[1]) +
                    " " + real(lo[2]) + "," + real(hi[2]) + " ";
  out += "\r\n\x1a";
  if (out.size() > kMaxHeaderBytes) fail(path, "the header exceeds 2048 bytes");
  out.append(kReservedBytes, '\0');
  // Sample table: one entry for the whole part.
  put(out, uint8_t(1));
  put(out, to_float(path, 0, z_bottom));
  put(out, to_float(path, 0, h));
  put(out, 0.0f);  // line width compensation
  put(out, 0.0f);  // reserved

  AtomicFile file(path);
  SlcExportStats stats;
  for (size_t k = 0; k < L; ++k) {
    uint32_t boundaries = 0;
    for (uint64_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c) boundaries += !s.contour_open[c];
    put(out, to_float(path, k, s.layer_z[k] - h / 2));
    put(out, boundaries);
    for (uint64_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c) {
      if (s.contour_open[c]) {
        ++stats.skipped_open_contours;
        continue;
      }
      const uint64_t b = s.contour_begin[c], n = s.contour_begin[c + 1] - b;
      if (n + 1 > std::numeric_limits<uint32_t>::max())
        fail(path, "layer " + std::to_string(k) + ": a contour has more points than SLC can count");
      put(out, uint32_t(n + 1));  // vertices, the first repeated at the end
      put(out, uint32_t(0));      // gaps
      for (uint64_t i = 0; i <= n; ++i) {
        const double* p = &s.xyz[3 * (b + (i == n ? 0 : i))];
        put(out, to_float(path, k, p[0]));
        put(out, to_float(path, k, p[1]));
      }
      ++stats.boundaries;
      if (out.size() >= kFlushBytes) {
        file.write(out.data(), out.size());
        out.clear();
      }
    }
    if (k % 256 == 255) report_progress(progress, double(k + 1) / double(L), "writing SLC");
  }
  put(out, to_float(path, L ? L - 1 : 0, z_top));
  put(out, kTermination);
  file.write(out.data(), out.size());
  file.commit();
  return stats;
}

}  // namespace slicereuse
