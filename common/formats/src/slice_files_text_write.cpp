// Text writer (.ctr / .enc, see docs/formats.md). Layers are grouped into chunks that are
// formatted into char buffers in parallel and then written in order: formatting numbers is the
// bottleneck, and the output stays the same for any thread count.
#include <omp.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "area_coordinates.h"
#include "slice_files_detail.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/parallel_blocks.h"

namespace slicereuse::detail {
namespace {

// to_chars prints a double in shortest round-trip form in at most 24 characters, a uint64 in 20.
constexpr size_t kDoubleChars = 24, kUintChars = 20;
constexpr size_t kLayerBound = 6 + kUintChars + 1 + kDoubleChars + 1 + kUintChars + 1;
constexpr size_t kContourBound = 5 + 1;  // "open " and the newline
constexpr size_t kContourPointBound = 3 * (kDoubleChars + 1);
constexpr size_t kEncodingPointBound = (kUintChars + 1) + 3 * (kDoubleChars + 1);
constexpr size_t kChunkPoints = size_t(1) << 18;

inline char* put(char* p, double v) { return std::to_chars(p, p + kDoubleChars, v).ptr; }
inline char* put(char* p, uint64_t v) { return std::to_chars(p, p + kUintChars, v).ptr; }
inline char* put(char* p, const char* text) {
  const size_t n = std::strlen(text);
  std::memcpy(p, text, n);
  return p + n;
}

struct Chunk {
  size_t first_layer, end_layer;
  size_t bound;  // bytes the chunk can take at most
};

std::vector<Chunk> make_chunks(const Slices& s, FileKind kind) {
  const size_t point_bound = kind == FileKind::Contours ? kContourPointBound : kEncodingPointBound;
  std::vector<Chunk> chunks;
  size_t k0 = 0;
  for (size_t k = 0; k < s.layers(); ++k) {
    const size_t c0 = s.layer_begin[k0], c1 = s.layer_begin[k + 1];
    const size_t points = s.contour_begin[c1] - s.contour_begin[c0];
    if (points >= kChunkPoints || k + 1 == s.layers()) {
      chunks.push_back({k0, k + 1,
                        (k + 1 - k0) * kLayerBound + (c1 - c0) * kContourBound +
                            points * point_bound});
      k0 = k + 1;
    }
  }
  return chunks;
}

char* format_layers(const Slices& s, FileKind kind, size_t k0, size_t k1, char* p) {
  for (size_t k = k0; k < k1; ++k) {
    const size_t c0 = s.layer_begin[k], c1 = s.layer_begin[k + 1];
    p = put(p, "layer ");
    p = put(p, uint64_t(k));
    *p++ = ' ';
    p = put(p, s.layer_z[k]);
    *p++ = ' ';
    p = put(p, uint64_t(c1 - c0));
    *p++ = '\n';
    for (size_t c = c0; c < c1; ++c) {
      if (s.contour_open[c]) p = put(p, "open ");
      for (size_t i = s.contour_begin[c]; i < s.contour_begin[c + 1]; ++i) {
        if (i != s.contour_begin[c]) *p++ = ' ';
        if (kind == FileKind::Contours) {
          p = put(p, s.xyz[3 * i]);
          *p++ = ' ';
          p = put(p, s.xyz[3 * i + 1]);
          *p++ = ' ';
          p = put(p, s.xyz[3 * i + 2]);
        } else {
          const unsigned j = s.edge[i];
          double lambda[3];
          encode_area_coordinates(j, s.t[i], lambda);
          p = put(p, uint64_t(s.face[i]));
          for (double l : lambda) {
            *p++ = ' ';
            p = put(p, l);
          }
        }
      }
      *p++ = '\n';
    }
  }
  return p;
}

std::string header(const Slices& s, FileKind kind) {
  auto real = [](double v) {
    char buf[kDoubleChars];
    return std::string(buf, put(buf, v));
  };
  std::string h = "# slicereuse " + std::string(kind_word(kind)) + " " +
                  std::to_string(kFormatVersion) + "\n";
  h += "# thickness " + real(s.thickness) + "\n";
  h += "# z_start " + real(s.z_start) + "\n";
  h += "# layers " + std::to_string(s.layers()) + " contours " + std::to_string(s.contours()) +
       " points " + std::to_string(s.points()) + "\n";
  if (kind == FileKind::Encoding) {
    char hash[17];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(s.fingerprint.hash));
    h += "# fingerprint " + std::to_string(s.fingerprint.faces) + " " + hash + "\n";
  }
  return h;
}

}  // namespace

void write_text(const std::string& path, const Slices& s, FileKind kind, const Progress& progress) {
  AtomicFile file(path);
  const std::string head = header(s, kind);
  file.write(head.data(), head.size());

  const std::vector<Chunk> chunks = make_chunks(s, kind);
  const size_t batch = 2 * size_t(std::max(1, omp_get_max_threads()));
  std::vector<Buffer<char>> buffers(std::min(batch, chunks.size()));
  std::vector<size_t> lengths(buffers.size());
  for (size_t b0 = 0; b0 < chunks.size(); b0 += batch) {
    const size_t n = std::min(batch, chunks.size() - b0);
    for (size_t i = 0; i < n; ++i)
      if (buffers[i].size() < chunks[b0 + i].bound) buffers[i].resize(chunks[b0 + i].bound);
    parallel_blocks(
        n,
        [&](size_t i) {
          const Chunk& c = chunks[b0 + i];
          char* begin = buffers[i].data();
          lengths[i] = size_t(format_layers(s, kind, c.first_layer, c.end_layer, begin) - begin);
        },
        {}, "writing");
    for (size_t i = 0; i < n; ++i) file.write(buffers[i].data(), lengths[i]);
    report_progress(progress, double(b0 + n) / double(chunks.size()), "writing");
  }
  file.commit();
}

}  // namespace slicereuse::detail
