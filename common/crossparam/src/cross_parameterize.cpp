// cross_parameterize: in-plane non-rigid registration, then in-plane projection onto the
// target's level sets.
//
// Approach. (1) Check both meshes and compare their topology (genus from the Euler
// characteristic, connected components, boundary loops); a mismatch is refused with both
// values named. (2) Align: with >= 3 landmark pairs (snapped to the nearest surface points), a
// least-squares affine LandmarkWarp that keeps z in-plane; without landmarks the
// identity, since family members sit on the same build plate. (3) Register: non-rigid ICP with
// a smooth displacement field (register_on_lattice: a low-order polynomial in (x, y, z) by exact
// point-to-plane ICP, then a lattice field for the rest), each source vertex paired with the nearest
// point of the target's level set at the vertex's own height that faces the same way, stiff
// first, then more detailed. (4) Project: every source vertex onto the target's level set at its
// own height (face + barycentric coordinates, so z(image) == z(vertex) up to rounding); where
// the target has no level set near that height (a ridge top that is lower on the target), onto
// the nearest target surface point instead, a soft height term whose |dz| is reported as the
// height error. With in_plane = false every step works in 3D and the projection is the plain
// closest point. Untangle: where neighbouring projections fold a triangle over (near saddles of
// the height, e.g. the arch's end-cap poles), move its corners to their neighbours' mean image
// on their level sets, or after repeated tries to the nearest surface point (soft height).
// (5) Measure the quality: folded (flipped) image triangles, height error, area and angle
// distortion. (6) Colour: ~12 patches on the source, carried to the target.
//
// Why not the method's consistent patch layouts + mean value coordinates, or a height-cylinder
// chart (v = z, u = arc length): both need consistent slice topology, and the product's shapes
// do not have it. A dental arch has 2-4 loops per slice (two walls plus tooth ridges), an ear
// shell 2, and a remeshed member's critical heights differ slightly from the source's, so the
// loops appear and merge at other heights. Registration + level-set projection needs none of it.
//
// Handles: genus 1 and higher (nothing here needs a disc or sphere topology: a handle or torus
// is mapped like any other shape, as long as both meshes have the same genus), different vertex
// counts, faces and vertex order, open meshes with the same boundary count, landmarks optional.
// Limits: shapes that differ by more than the registration can bridge (more than about a wall
// distance after alignment, or large rotations) need landmarks; without them such a pair is
// refused when too little of the source finds matching target surface. There are no MVC base
// domains: the map is bijective in practice (flipped triangles are counted and reported), not
// by construction.
#include "slicereuse/crossparam/cross_parameterize.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "landmark_warp.h"
#include "lattice_registration.h"
#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/mesh/mesh_topology.h"
#include "slicereuse/mesh/vertex_normals.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/seconds_since.h"
#include "surface_grid.h"
#include "surface_patches.h"

namespace slicereuse {
namespace {

constexpr size_t kPatches = 12;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
// A vertex normal with at least this horizontal length faces sideways (see place()).
constexpr double kSideways = 0.3;
// Untangling (see cross_parameterize): at most this many passes, and this many placements of a
// vertex on its level set before it takes the nearest surface point instead.
constexpr int kUntanglePasses = 64;
constexpr int kLevelTries = 8;

std::string num(int64_t v) { return std::to_string(v); }

void check_topology(const Mesh& source, const Mesh& target, CrossParamQuality& q) {
  for (const Mesh* m : {&source, &target}) {
    try {
      validate_mesh(*m);
    } catch (const Error& e) {
      throw Error(std::string("cross-parameterization: the ") + (m == &source ? "source" : "target") +
                  " mesh is invalid: " + e.what());
    }
  }
  const MeshTopology s = mesh_topology(source), t = mesh_topology(target);
  auto refuse = [&](const std::string& what, int64_t a, int64_t b, const std::string& why) {
    throw Error("cross-parameterization: the source has " + what + " " + num(a) + ", the target " + num(b) +
                "; " + why);
  };
  if (s.components != t.components)
    refuse("connected components:", int64_t(s.components), int64_t(t.components),
           "meshes of one family must consist of the same parts");
  if (s.boundary_loops != t.boundary_loops)
    refuse("boundary loops (holes):", int64_t(s.boundary_loops), int64_t(t.boundary_loops),
           "close or open the meshes alike first");
  if (s.genus != t.genus)
    refuse("genus", s.genus, t.genus, "no continuous one-to-one map exists between surfaces of different genus");
  q.genus = int(s.genus);
}

// Landmarks snapped to the nearest surface point (a landmark need not be a vertex).
std::vector<std::array<double, 3>> snapped(const std::vector<std::array<double, 3>>& points, const SurfaceGrid& grid) {
  std::vector<std::array<double, 3>> out;
  for (const auto& p : points) {
    const SurfacePoint s = grid.nearest_on_surface(p.data(), nullptr, -2, kInf);
    out.push_back({s.xyz[0], s.xyz[1], s.xyz[2]});
  }
  return out;
}

// Half the cross product's length; n receives the cross product.
double cross_area(const double* const p[3], double n[3]) {
  double u[3], v[3];
  for (int k = 0; k < 3; ++k) u[k] = p[1][k] - p[0][k], v[k] = p[2][k] - p[0][k];
  n[0] = u[1] * v[2] - u[2] * v[1], n[1] = u[2] * v[0] - u[0] * v[2], n[2] = u[0] * v[1] - u[1] * v[0];
  return std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) / 2;
}

double angle(const double* a, const double* b, const double* c) {  // at a
  double u[3], v[3];
  for (int k = 0; k < 3; ++k) u[k] = b[k] - a[k], v[k] = c[k] - a[k];
  const double cr[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return std::atan2(std::sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]), u[0] * v[0] + u[1] * v[1] + u[2] * v[2]);
}

// Whether the image of source face f is folded over: its normal points against the normal of
// the registered source triangle (`moved`) it stands for, or it has no area. -1 for a
// degenerate registered triangle, which has no orientation to keep. Why the registered
// triangle: the registration is a smooth displacement field that keeps every triangle's
// orientation; only the projection onto the target can fold. (Comparing with the target face
// nearest to the image's centroid, as before, miscounts long thin triangles over a tight bend:
// at the arch's end-cap poles that centroid lies nearer the wall's other side, and the true
// deformation itself scored 3-19 "flips" there.)
int folded(const Mesh& source, const std::vector<double>& moved, const std::vector<double>& image, size_t f) {
  const uint32_t* F = &source.F[3 * f];
  const double* r[3] = {&moved[3 * size_t(F[0])], &moved[3 * size_t(F[1])], &moved[3 * size_t(F[2])]};
  const double* m[3] = {&image[3 * size_t(F[0])], &image[3 * size_t(F[1])], &image[3 * size_t(F[2])]};
  double nr[3], ni[3];
  if (cross_area(r, nr) == 0) return -1;
  cross_area(m, ni);
  return !(ni[0] * nr[0] + ni[1] * nr[1] + ni[2] * nr[2] > 0);
}

// Height error, folded triangles, area and angle distortion of the map (image: 3 per vertex).
void measure(const Mesh& source, const std::vector<double>& moved, const std::vector<double>& image,
             CrossParamQuality& q) {
  const size_t nv = source.vertices(), nf = source.faces();
  double max_dz = 0, sum_dz2 = 0;
  for (size_t i = 0; i < nv; ++i) {
    const double dz = std::abs(image[3 * i + 2] - source.V[3 * i + 2]);
    max_dz = std::max(max_dz, dz);
    sum_dz2 += dz * dz;
  }
  q.max_height_error = max_dz;
  q.rms_height_error = nv ? std::sqrt(sum_dz2 / double(nv)) : 0;
  uint64_t flipped = 0, measured = 0;
  double area_sum = 0, angle_sum = 0;
#pragma omp parallel for reduction(+ : flipped, measured, area_sum, angle_sum) schedule(static)
  for (long long f = 0; f < (long long)nf; ++f) {
    const uint32_t* F = &source.F[3 * f];
    const double* s[3] = {&source.V[3 * size_t(F[0])], &source.V[3 * size_t(F[1])], &source.V[3 * size_t(F[2])]};
    const double* m[3] = {&image[3 * size_t(F[0])], &image[3 * size_t(F[1])], &image[3 * size_t(F[2])]};
    const int fold = folded(source, moved, image, size_t(f));
    if (fold < 0) continue;
    ++measured;
    if (fold) {
      ++flipped;
      continue;
    }
    double ns[3], ni[3];
    const double as = cross_area(s, ns), ai = cross_area(m, ni);
    area_sum += std::abs(std::log(ai / as));
    for (int j = 0; j < 3; ++j)
      angle_sum += std::abs(angle(m[j], m[(j + 1) % 3], m[(j + 2) % 3]) - angle(s[j], s[(j + 1) % 3], s[(j + 2) % 3]));
  }
  q.flipped_triangles = flipped;
  q.area_distortion = measured ? area_sum / double(measured) : 0;
  q.angle_distortion = measured ? angle_sum / double(3 * measured) * 180 / kPi : 0;
}

}  // namespace

CrossParamResult cross_parameterize(const Mesh& source, const Mesh& target, const CrossParamOptions& options,
                                    const Progress& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  CrossParamResult result;
  CrossParamQuality& q = result.quality;
  const bool in_plane = options.in_plane;
  report_progress(progress, 0, "checking");
  check_topology(source, target, q);
  if (options.source_landmarks.size() != options.target_landmarks.size())
    throw Error("cross-parameterization: " + num(int64_t(options.source_landmarks.size())) + " source and " +
                num(int64_t(options.target_landmarks.size())) + " target landmarks; they must correspond one to one");
  const bool landmarks = !options.source_landmarks.empty();
  if (landmarks && options.source_landmarks.size() < 3)
    throw Error("cross-parameterization: at least 3 landmark pairs are needed, got " +
                num(int64_t(options.source_landmarks.size())));

  const SurfaceGrid grid(target);
  report_progress(progress, 0.1, "aligning");
  const size_t nv = source.vertices();
  std::vector<double> aligned = source.V;
  std::vector<PointConstraint> constraints;
  std::vector<std::array<double, 3>> source_marks;
  if (landmarks) {
    source_marks = snapped(options.source_landmarks, SurfaceGrid(source));
    const std::vector<std::array<double, 3>> target_marks = snapped(options.target_landmarks, grid);
    const LandmarkWarp warp(source_marks, target_marks, in_plane);
#pragma omp parallel for schedule(static)
    for (long long i = 0; i < (long long)nv; ++i) warp.apply(&source.V[3 * i], &aligned[3 * i]);
    for (size_t k = 0; k < source_marks.size(); ++k) {
      PointConstraint c;
      warp.apply(source_marks[k].data(), c.source.data());
      c.target = target_marks[k];
      if (in_plane) c.target[2] = c.source[2];
      constraints.push_back(c);
    }
  }

  RegistrationStats reg;
  const DisplacementField field =
      register_on_lattice(aligned, source.F, grid, constraints, in_plane, &reg, sub_progress(progress, 0.1, 0.7));
  report_progress(progress, 0.7, "projecting");
  std::vector<double> moved(3 * nv);
#pragma omp parallel for schedule(static)
  for (long long i = 0; i < (long long)nv; ++i) field.apply(&aligned[3 * i], &moved[3 * i]);
  const std::vector<double> normal = vertex_normals(moved, source.F);

  SurfaceMap& map = result.map;
  map.source = mesh_fingerprint(source);
  map.target = mesh_fingerprint(target);
  map.source_vertices = nv;
  map.target_vertices = target.vertices();
  map.source_faces = source.F;
  map.face.resize(nv);
  map.bary.resize(3 * nv);
  std::vector<double> image(3 * nv);
  // A level-set point is taken when it is at most this much farther than the nearest surface
  // point: on walls the two coincide; where they differ by more, the target has no level set
  // near this height here (a lower ridge top) and the nearest point wins.
  const double tolerance = 2 * grid.mean_edge();
  const double reach = std::max(10 * reg.rms, 10 * grid.mean_edge());
  // Places source vertex i's image at the target point for p (p's z is the vertex's own height
  // in the plane); false when nothing faces the same way within reach. on_level = false takes
  // the nearest surface point only (the soft height term).
  auto place = [&](size_t i, const double p[3], bool on_level) {
    const double* n = &normal[3 * i];
    const bool has_normal = n[0] != 0 || n[1] != 0 || n[2] != 0;
    SurfacePoint best = grid.nearest_on_surface(p, has_normal ? n : nullptr, 0.0, reach);
    if (in_plane && on_level) {
      // Where the vertex faces sideways, the level set's points must face the same way in xy:
      // this keeps a wall's foot off a flat floor at its own height (a horizontal face lies
      // wholly in its plane and would catch every point registered slightly inside it).
      const double side[3] = {n[0], n[1], 0};
      const bool sideways = n[0] * n[0] + n[1] * n[1] > kSideways * kSideways;
      const SurfacePoint level = sideways ? grid.nearest_on_level(p, p[2], side, kSideways * 1e-3, reach)
                                          : grid.nearest_on_level(p, p[2], has_normal ? n : nullptr, 0.0, reach);
      if (level.face != kNoFace && (best.face == kNoFace || level.distance <= best.distance + tolerance)) best = level;
    }
    const bool found = best.face != kNoFace;
    if (!found) best = grid.nearest_on_surface(p, nullptr, -2, kInf);
    map.face[i] = best.face;
    for (int j = 0; j < 3; ++j) map.bary[3 * i + j] = best.bary[j], image[3 * i + j] = best.xyz[j];
    return found;
  };
  uint64_t far = 0;
#pragma omp parallel for schedule(dynamic, 512) reduction(+ : far)
  for (long long i = 0; i < (long long)nv; ++i) {
    const double p[3] = {moved[3 * i], moved[3 * i + 1], in_plane ? source.V[3 * i + 2] : moved[3 * i + 2]};
    far += !place(size_t(i), p, true);
  }
  // Local untangling: where independent projections of neighbours fold a small triangle over
  // (tight level-set curves near a saddle such as the arch's end-cap poles), each corner of a
  // folded triangle is placed again from the mean image of its neighbours (a Laplacian step).
  // A vertex still folded after kLevelTries placements sits where the target's level set at its
  // height cannot hold its neighbourhood (a ridge top that reaches that height in one point on
  // the target, a whole row of vertices on the source): it takes the nearest surface point
  // instead, the soft height term, and its |dz| is reported as height error.
  const size_t nf = source.faces();
  // After the first pass only faces around moved vertices can change: only they are checked.
  std::vector<uint8_t> bad(nf), moved_vertex(nv, 1), tries(nv, 0);
  for (int pass = 0; pass < kUntanglePasses; ++pass) {
#pragma omp parallel for schedule(dynamic, 4096)
    for (long long f = 0; f < (long long)nf; ++f) {
      const uint32_t* F = &source.F[3 * f];
      if (moved_vertex[F[0]] || moved_vertex[F[1]] || moved_vertex[F[2]])
        bad[f] = folded(source, moved, image, size_t(f)) > 0;
    }
    std::vector<uint8_t>& mark = moved_vertex;
    std::fill(mark.begin(), mark.end(), 0);
    std::vector<uint32_t> touched;
    for (size_t f = 0; f < nf; ++f)
      if (bad[f])
        for (int j = 0; j < 3; ++j) {
          const uint32_t v = source.F[3 * f + j];
          if (!mark[v]) mark[v] = 1, touched.push_back(v);
        }
    if (touched.empty()) break;
    // The mean image of each marked vertex's neighbours (its one-ring, through all its faces).
    std::vector<double> sum(3 * nv, 0.0);
    std::vector<uint32_t> count(nv, 0);
    for (size_t f = 0; f < nf; ++f)
      for (int j = 0; j < 3; ++j) {
        const uint32_t v = source.F[3 * f + j];
        if (!mark[v]) continue;
        for (int k = 1; k < 3; ++k)
          for (int a = 0; a < 3; ++a) sum[3 * size_t(v) + a] += image[3 * size_t(source.F[3 * f + (j + k) % 3]) + a];
        count[v] += 2;
      }
#pragma omp parallel for schedule(dynamic, 64)
    for (long long k = 0; k < (long long)touched.size(); ++k) {
      const size_t v = touched[k];
      double p[3];
      for (int a = 0; a < 3; ++a) p[a] = sum[3 * v + a] / count[v];
      if (in_plane) p[2] = source.V[3 * v + 2];
      place(v, p, ++tries[v] < kLevelTries);
    }
  }

  report_progress(progress, 0.8, "measuring");
  measure(source, moved, image, q);
  // Without landmarks nothing but the registration vouches for the correspondence: refuse a
  // result where much of the source found no matching surface or the image folds over.
  const double far_share = double(far) / double(std::max<size_t>(1, nv));
  if (!landmarks && (reg.matched < 0.9 || far_share > 0.02 || q.flipped_triangles * 100 > source.faces()))
    throw Error("cross-parameterization: the meshes could not be registered automatically (" +
                std::to_string(int(std::lround(100 * (1 - reg.matched)))) +
                " % of the source found no matching target surface, " + num(int64_t(q.flipped_triangles)) +
                " folded triangles); give corresponding landmarks (.pp files picked in MeshLab) for both meshes");

  report_progress(progress, 0.9, "patches");
  result.source_patch = surface_patches(source, kPatches, source_marks);
  q.patches = *std::max_element(result.source_patch.begin(), result.source_patch.end()) + 1;
  // A target vertex takes the patch of the source triangle whose image is nearest to it.
  Mesh image_mesh;
  image_mesh.V = image;
  image_mesh.F = source.F;
  const SurfaceGrid image_grid(image_mesh);
  const std::vector<double> target_normal = vertex_normals(target.V, target.F);
  result.target_patch.resize(target.vertices());
#pragma omp parallel for schedule(dynamic, 512)
  for (long long i = 0; i < (long long)target.vertices(); ++i) {
    const double* n = &target_normal[3 * i];
    SurfacePoint s = image_grid.nearest_on_surface(&target.V[3 * i], n, 0.0, kInf);
    if (s.face == kNoFace) s = image_grid.nearest_on_surface(&target.V[3 * i], nullptr, -2, kInf);
    const int corner = int(std::max_element(s.bary, s.bary + 3) - s.bary);
    result.target_patch[i] = result.source_patch[source.F[3 * size_t(s.face) + corner]];
  }
  result.registered = std::move(moved);
  q.seconds = seconds_since(t0);
  report_progress(progress, 1, "done");
  return result;
}

}  // namespace slicereuse
