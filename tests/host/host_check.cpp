// host_check: asserts properties of the files a MeshLab host wrote, for the host tests.
//   host_check slice [--float] MESH.ply CONTOURS ENCODING
//       contour and encoding files agree in structure, every contour is closed, layer k has
//       exactly as many points as MESH has edges straddling layer_z[k] (one end below, one at
//       or above), every point lies on its plane, and the encoding (face, edge, t) on MESH
//       reproduces every point within 1e-9 of the mesh size; the fingerprint matches MESH.
//       --float rounds MESH's coordinates to float first, as MeshLab 2020.09 stores them.
//   host_check same [--prefix] A B
//       two contour files have the same layer planes and, per layer, exactly the same points
//       (contour order and loop start points may differ). --prefix: B may have more layers on
//       top (a member that grew taller, sliced directly, versus a transfer on the source's planes).
//   host_check layers FILE  prints the number of layers of a contour or encoding file.
//   host_check shifted A B DX
//       contour file B is A moved by DX along x, as MeshLab 2020.09 stores it (float): same
//       layers, contours and open flags, every x within 1e-5 (relative) of x_A + DX, y and z
//       equal as float.
//   host_check export CONTOURS EXPORT
//       EXPORT (.cli, ASCII or binary, or .slc), read by the reader written from the format's
//       specification (tests/support/spec_readers.h), holds exactly the contours of CONTOURS:
//       $$LAYERS and every layer's z, one polyline (SLC: boundary, closed contours only) per
//       contour in order, direction 2 for open ones, closed ones repeating their first point,
//       every coordinate equal (as float32 in binary CLI and SLC).
// Exits 0 when all holds, 1 with a message naming the first violation.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "shapes.h"
#include "slicereuse/formats/mesh_file.h"
#include "slicereuse/formats/slice_files.h"
#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/util/error.h"
#include "spec_readers.h"

using namespace slicereuse;

namespace {

[[noreturn]] void fail(const std::string& what) { throw Error("FAILED: " + what); }

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

void check_same_structure(const Slices& a, const Slices& b) {
  if (a.layer_z != b.layer_z) fail("contour and encoding files differ in layer planes");
  if (a.layer_begin != b.layer_begin || a.contour_begin != b.contour_begin ||
      a.contour_open != b.contour_open)
    fail("contour and encoding files differ in layers, contours or open flags");
}

// Number of distinct mesh edges straddling each plane.
std::vector<size_t> straddling_edges(const Mesh& m, const std::vector<double>& planes) {
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  edges.reserve(m.F.size());
  for (size_t f = 0; f < m.faces(); ++f)
    for (int j = 0; j < 3; ++j) {
      const uint32_t a = m.F[3 * f + j], b = m.F[3 * f + (j + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<size_t> count(planes.size(), 0);
  for (const auto& [a, b] : edges) {
    const double za = m.V[3 * a + 2], zb = m.V[3 * b + 2];
    const double lo = std::min(za, zb), hi = std::max(za, zb);
    // planes ascend: those with lo < z <= hi are cut by this edge.
    auto first = std::upper_bound(planes.begin(), planes.end(), lo);
    auto last = std::upper_bound(planes.begin(), planes.end(), hi);
    for (auto it = first; it != last; ++it) ++count[size_t(it - planes.begin())];
  }
  return count;
}

double mesh_size(const Mesh& m) {
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (size_t i = 0; i < m.V.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], m.V[i]);
    hi[i % 3] = std::max(hi[i % 3], m.V[i]);
  }
  return std::max(1.0, std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]));
}

int check_slice(Mesh mesh, const std::string& contour_path, const std::string& encoding_path) {
  const Slices c = read_contour_file(contour_path);
  const Slices e = read_encoding_file(encoding_path);
  check_same_structure(c, e);
  if (c.layers() == 0) fail("no layers");
  if (c.open_contours() != 0) fail(std::to_string(c.open_contours()) + " open contours");
  if (e.fingerprint != mesh_fingerprint(mesh)) fail("encoding fingerprint differs from the mesh's");

  const std::vector<size_t> expected = straddling_edges(mesh, c.layer_z);
  for (size_t k = 0; k < c.layers(); ++k) {
    const size_t points = c.contour_begin[c.layer_begin[k + 1]] - c.contour_begin[c.layer_begin[k]];
    if (points != expected[k])
      fail("layer " + std::to_string(k) + " has " + std::to_string(points) + " points but " +
           std::to_string(expected[k]) + " mesh edges straddle z = " + num(c.layer_z[k]));
  }

  const double tolerance = 1e-9 * mesh_size(mesh);
  for (size_t k = 0; k < c.layers(); ++k)
    for (uint64_t p = c.contour_begin[c.layer_begin[k]]; p < c.contour_begin[c.layer_begin[k + 1]]; ++p) {
      const uint32_t f = e.face[p], j = e.edge[p];
      const double t = e.t[p];
      const uint32_t a = mesh.F[3 * f + j], b = mesh.F[3 * f + (j + 1) % 3];
      for (int d = 0; d < 3; ++d) {
        const double q = (1 - t) * mesh.V[3 * a + d] + t * mesh.V[3 * b + d];
        if (std::fabs(q - c.xyz[3 * p + d]) > tolerance)
          fail("point " + std::to_string(p) + " differs from its encoding by " +
               num(std::fabs(q - c.xyz[3 * p + d])));
      }
      if (std::fabs(c.xyz[3 * p + 2] - c.layer_z[k]) > tolerance)
        fail("point " + std::to_string(p) + " is off its layer plane");
    }
  std::printf("ok: %zu layers, %zu contours, %zu points, all closed, encoding reproduces points\n",
              c.layers(), c.contours(), c.points());
  return 0;
}

std::vector<std::array<double, 3>> layer_points(const Slices& s, size_t k) {
  std::vector<std::array<double, 3>> pts;
  for (uint64_t p = s.contour_begin[s.layer_begin[k]]; p < s.contour_begin[s.layer_begin[k + 1]]; ++p)
    pts.push_back({s.xyz[3 * p], s.xyz[3 * p + 1], s.xyz[3 * p + 2]});
  std::sort(pts.begin(), pts.end());
  return pts;
}

int check_same(const std::string& path_a, const std::string& path_b, bool prefix) {
  const Slices a = read_contour_file(path_a), b = read_contour_file(path_b);
  const bool planes_ok = prefix ? a.layers() <= b.layers() &&
                                      std::equal(a.layer_z.begin(), a.layer_z.end(), b.layer_z.begin())
                                : a.layer_z == b.layer_z;
  if (!planes_ok) fail("the files have different layer planes");
  for (size_t k = 0; k < a.layers(); ++k)
    if (layer_points(a, k) != layer_points(b, k)) fail("layer " + std::to_string(k) + " differs");
  std::printf("ok: %zu layers, %zu points, identical per layer\n", a.layers(), a.points());
  return 0;
}

// The points of contour c as written to a closed-or-open polyline, x and y rounded by round().
template <class Round>
std::vector<double> polyline_of(const Slices& s, size_t c, Round round) {
  std::vector<double> xy;
  const uint64_t b = s.contour_begin[c], n = s.contour_begin[c + 1] - b;
  for (uint64_t j = 0; j < n + (s.contour_open[c] ? 0 : 1); ++j)
    for (int a = 0; a < 2; ++a) xy.push_back(round(s.xyz[3 * (b + j % n) + a]));
  return xy;
}

int check_export(const std::string& contours, const std::string& exported) {
  const Slices s = read_contour_file(contours);
  std::ifstream in(exported, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  const std::string what = "'" + exported + "'";
  const bool slc = exported.size() > 4 && exported.substr(exported.size() - 4) == ".slc";
  auto as_float = [](double v) { return double(float(v)); };
  if (slc) {
    const test::SpecSlc f = test::read_slc_per_spec(bytes);
    if (f.layers.size() != s.layers()) fail(what + " has " + std::to_string(f.layers.size()) + " layers");
    for (size_t k = 0; k < s.layers(); ++k) {
      size_t i = 0;
      for (uint64_t c = s.layer_begin[k]; c < s.layer_begin[k + 1]; ++c) {
        if (s.contour_open[c]) continue;
        if (i >= f.layers[k].boundaries.size()) fail(what + ": layer " + std::to_string(k) + " lacks boundaries");
        std::vector<double> xy;
        for (const auto& p : f.layers[k].boundaries[i++]) xy.insert(xy.end(), {double(p[0]), double(p[1])});
        if (xy != polyline_of(s, c, as_float)) fail(what + ": contour " + std::to_string(c) + " differs");
      }
      if (i != f.layers[k].boundaries.size()) fail(what + ": layer " + std::to_string(k) + " has extra boundaries");
    }
    std::printf("ok: SLC with %zu layers\n", f.layers.size());
    return 0;
  }
  const test::SpecCli f = test::read_cli_per_spec(bytes);
  auto round = [&](double v) { return f.binary ? as_float(v) : v; };
  if (f.layers != long(s.layers()) || f.geometry.size() != s.layers())
    fail(what + ": $$LAYERS/" + std::to_string(f.layers) + " and " + std::to_string(f.geometry.size()) +
         " layers for " + std::to_string(s.layers()));
  for (size_t k = 0; k < s.layers(); ++k) {
    const auto& l = f.geometry[k];
    if (l.z != round(s.layer_z[k])) fail(what + ": layer " + std::to_string(k) + " z differs");
    if (l.polylines.size() != s.layer_begin[k + 1] - s.layer_begin[k])
      fail(what + ": layer " + std::to_string(k) + " has " + std::to_string(l.polylines.size()) + " polylines");
    for (size_t i = 0; i < l.polylines.size(); ++i) {
      const size_t c = s.layer_begin[k] + i;
      if ((l.polylines[i].dir == 2) != (s.contour_open[c] != 0)) fail(what + ": contour " + std::to_string(c) + " direction");
      if (l.polylines[i].xy != polyline_of(s, c, round)) fail(what + ": contour " + std::to_string(c) + " differs");
    }
  }
  std::printf("ok: %s CLI, $$LAYERS/%ld\n", f.binary ? "binary" : "ASCII", f.layers);
  return 0;
}

int check_shifted(const std::string& path_a, const std::string& path_b, double dx) {
  const Slices a = read_contour_file(path_a), b = read_contour_file(path_b);
  if (a.layer_begin != b.layer_begin || a.contour_begin != b.contour_begin || a.contour_open != b.contour_open)
    fail("the files have different layers or contours");
  for (size_t p = 0; p < a.points(); ++p) {
    const double* q = &a.xyz[3 * p];
    const double* r = &b.xyz[3 * p];
    if (std::abs(r[0] - (q[0] + dx)) > 1e-5 * (1 + std::abs(q[0])) || r[1] != double(float(q[1])) ||
        r[2] != double(float(q[2])))
      fail("point " + std::to_string(p) + " is not moved by " + std::to_string(dx) + " along x");
  }
  std::printf("ok: %zu points moved by %g along x\n", a.points(), dx);
  return 0;
}

int usage() {
  std::fprintf(stderr, "usage: host_check slice [--float] MESH.ply CONTOURS ENCODING\n"
                       "       host_check same [--prefix] A B\n       host_check layers FILE\n"
                       "       host_check export CONTOURS EXPORT.cli|EXPORT.slc\n"
                       "       host_check shifted A B DX\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty()) return usage();
    const std::string command = args[0];
    args.erase(args.begin());
    if (command == "slice") {
      const bool as_float = !args.empty() && args[0] == "--float";
      if (as_float) args.erase(args.begin());
      if (args.size() != 3) return usage();
      Mesh mesh = read_mesh_file(args[0]);
      if (as_float)
        for (double& v : mesh.V) v = double(float(v));
      return check_slice(std::move(mesh), args[1], args[2]);
    }
    if (command == "same") {
      const bool prefix = !args.empty() && args[0] == "--prefix";
      if (prefix) args.erase(args.begin());
      if (args.size() != 2) return usage();
      return check_same(args[0], args[1], prefix);
    }
    if (command == "layers" && args.size() == 1) {
      const std::string& p = args[0];
      Slices s;
      try {
        s = read_contour_file(p);
      } catch (const Error&) {
        s = read_encoding_file(p);
      }
      std::printf("%zu\n", s.layers());
      return 0;
    }
    if (command == "shifted" && args.size() == 3) return check_shifted(args[0], args[1], std::stod(args[2]));
    if (command == "export" && args.size() == 2) return check_export(args[0], args[1]);
    return usage();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "host_check: %s\n", e.what());
    return 1;
  }
}
