// Throughput of the contour and encoding files, text and binary, of CLI (ASCII, binary) and SLC
// export, and of the conversion to and from a contour layer's arrays (contour_mesh.h), on 10M+
// synthetic points.
// Usage: bench_files [folder]   (default /tmp; files are removed afterwards)
// Prints the median of 3 runs. Reads follow writes, so they are served from the page cache:
// the figures measure parsing and copying, not the disk.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "slicereuse/formats/cli_file.h"
#include "slicereuse/formats/contour_mesh.h"
#include "slicereuse/formats/slc_file.h"
#include "slicereuse/formats/slice_files.h"

using namespace slicereuse;

namespace {

// Layers of circular contours with jittered, full-precision coordinates, like a real part.
Slices make_slices(size_t layers, size_t contours_per_layer, size_t points_per_contour) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01), unit(0, 1);
  Slices s;
  s.thickness = 0.025;
  s.z_start = 0;
  s.fingerprint = {4000000, 0x0123456789abcdefull};
  s.layer_begin = {0};
  s.contour_begin = {0};
  const size_t P = layers * contours_per_layer * points_per_contour;
  s.xyz.resize(3 * P);
  s.face.resize(P);
  s.edge.resize(P);
  s.t.resize(P);
  size_t p = 0;
  for (size_t k = 0; k < layers; ++k) {
    const double z = (double(k) + 0.5) * s.thickness;
    s.layer_z.push_back(z);
    for (size_t c = 0; c < contours_per_layer; ++c) {
      const double r = 5 + 3 * double(c);
      for (size_t i = 0; i < points_per_contour; ++i, ++p) {
        const double a = 2 * M_PI * double(i) / double(points_per_contour);
        s.xyz[3 * p] = r * std::cos(a) + jitter(rng);
        s.xyz[3 * p + 1] = r * std::sin(a) + jitter(rng);
        s.xyz[3 * p + 2] = z;
        s.face[p] = uint32_t(rng() % s.fingerprint.faces);
        s.edge[p] = uint8_t(rng() % 3);
        s.t[p] = 1 - unit(rng);  // in (0, 1]
      }
      s.contour_open.push_back(c == contours_per_layer - 1);
      s.contour_begin.push_back(p);
    }
    s.layer_begin.push_back(s.contour_open.size());
  }
  return s;
}

double median_seconds(const std::function<void()>& f) {
  std::vector<double> t;
  for (int i = 0; i < 3; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(t.begin(), t.end());
  return t[1];
}

template <class A>
bool same(const A& a, const A& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof a[0]) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string folder = argc > 1 ? argv[1] : "/tmp";
  const Slices s = make_slices(1000, 10, 1000);
  std::printf("%zu layers, %zu contours, %zu points, %d threads\n", s.layers(), s.contours(),
              s.points(), omp_get_max_threads());
  std::printf("%-9s %-7s %9s %9s %10s %9s %10s\n", "kind", "format", "size_MB", "write_s",
              "write_MB/s", "read_s", "read_MB/s");
  for (int encoding = 0; encoding < 2; ++encoding) {
    for (FileFormat format : {FileFormat::Text, FileFormat::Binary}) {
      const bool text = format == FileFormat::Text;
      const std::string path =
          folder + "/bench_files" + (text ? (encoding ? ".enc" : ".ctr") : ".srb");
      const double w = median_seconds([&] {
        encoding ? write_encoding_file(path, s, format) : write_contour_file(path, s, format);
      });
      Slices r;
      const double rd = median_seconds(
          [&] { r = encoding ? read_encoding_file(path) : read_contour_file(path); });
      const bool ok = encoding ? same(r.face, s.face) && same(r.edge, s.edge) && same(r.t, s.t)
                               : same(r.xyz, s.xyz);
      const double mb = double(std::filesystem::file_size(path)) / 1e6;
      std::printf("%-9s %-7s %9.1f %9.3f %10.1f %9.3f %10.1f%s\n",
                  encoding ? "encoding" : "contours", text ? "text" : "binary", mb, w, mb / w, rd,
                  mb / rd, ok ? "" : "  ROUND TRIP MISMATCH");
      std::filesystem::remove(path);
      if (!ok) return 1;
    }
  }
  // CLI: ASCII keeps every double, binary rounds x, y and the layer z to float32.
  for (CliEncoding encoding : {CliEncoding::Ascii, CliEncoding::Binary}) {
    const bool binary = encoding == CliEncoding::Binary;
    const std::string path = folder + "/bench_files.cli";
    const double w = median_seconds([&] { write_cli_file(path, s, encoding); });
    Slices r;
    const double rd = median_seconds([&] { r = read_cli_file(path); });
    bool ok = r.xyz.size() == s.xyz.size();
    for (size_t i = 0; ok && i < s.xyz.size(); ++i)
      ok = r.xyz[i] == (binary ? double(float(s.xyz[i])) : s.xyz[i]);  // z: the layer's, float32 too
    const double mb = double(std::filesystem::file_size(path)) / 1e6;
    std::printf("%-9s %-7s %9.1f %9.3f %10.1f %9.3f %10.1f%s\n", "CLI", binary ? "binary" : "ASCII", mb, w,
                mb / w, rd, mb / rd, ok ? "" : "  ROUND TRIP MISMATCH");
    std::filesystem::remove(path);
    if (!ok) return 1;
  }
  {
    const std::string path = folder + "/bench_files.slc";
    const double w = median_seconds([&] { write_slc_file(path, s); });
    const double mb = double(std::filesystem::file_size(path)) / 1e6;
    std::printf("%-9s %-7s %9.1f %9.3f %10.1f %9s %10s\n", "SLC", "binary", mb, w, mb / w, "-", "-");
    std::filesystem::remove(path);
  }
  // A contour layer's arrays (what io_encoding copies into and out of MeshLab).
  ContourMesh m;
  const double to_mesh = median_seconds([&] { m = contour_mesh_from_slices(s); });
  Slices back;
  const double from_mesh = median_seconds([&] { back = slices_from_contour_mesh(m); });
  const double hash = median_seconds([&] { (void)contour_mesh_hash(m); });
  const bool ok = same(back.xyz, s.xyz) && same(back.t, s.t) && back.contour_open == s.contour_open;
  std::printf("contour layer arrays: from slices %.3f s, back to slices %.3f s, hash %.3f s%s\n", to_mesh,
              from_mesh, hash, ok ? "" : "  ROUND TRIP MISMATCH");
  return ok ? 0 : 1;
}
