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
#include "slicereuse/crossparam/surface_grid.h"
#include "slicereuse/mesh/fingerprint.h"
#include "slicereuse/mesh/mesh_topology.h"
#include "slicereuse/mesh/vec3.h"
#include "slicereuse/mesh/vertex_normals.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/seconds_since.h"
#include "surface_patches.h"

namespace slicereuse {
namespace {

constexpr size_t kPatches = 12;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
// A vertex normal with at least this horizontal length faces sideways (see ImagePlacer::place).
constexpr double kSideways = 0.3;
// Untangling (see untangle): at most this many passes, and this many placements of a
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
double cross_area(const double* const p[3], Vec3& n) {
  n = cross(sub(p[1], p[0]), sub(p[2], p[0]));
  return norm(n) / 2;
}

double angle(const double* a, const double* b, const double* c) {  // at a
  const Vec3 u = sub(b, a), v = sub(c, a);
  return std::atan2(norm(cross(u, v)), dot(u, v));
}

// Whether the image of source face f is folded over: its normal points against the normal of
// the registered source triangle (`moved`) it stands for, or it has no area. -1 for a
// degenerate registered triangle, which has no orientation to keep. Why the registered
// triangle: the registration is a smooth displacement field that keeps every triangle's
// orientation; only the projection onto the target can fold. (The target face nearest to the
// image's centroid would miscount long thin triangles over a tight bend, such as the arch's
// end-cap poles, where that centroid lies nearer the wall's other side.)
int folded(const Mesh& source, const std::vector<double>& moved, const std::vector<double>& image, size_t f) {
  const uint32_t* F = &source.F[3 * f];
  const double* r[3] = {&moved[3 * size_t(F[0])], &moved[3 * size_t(F[1])], &moved[3 * size_t(F[2])]};
  const double* m[3] = {&image[3 * size_t(F[0])], &image[3 * size_t(F[1])], &image[3 * size_t(F[2])]};
  Vec3 nr, ni;
  if (cross_area(r, nr) == 0) return -1;
  cross_area(m, ni);
  return !(dot(ni, nr) > 0);
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
    Vec3 ns, ni;
    const double as = cross_area(s, ns), ai = cross_area(m, ni);
    area_sum += std::abs(std::log(ai / as));
    for (int j = 0; j < 3; ++j)
      angle_sum += std::abs(angle(m[j], m[(j + 1) % 3], m[(j + 2) % 3]) - angle(s[j], s[(j + 1) % 3], s[(j + 2) % 3]));
  }
  q.flipped_triangles = flipped;
  q.area_distortion = measured ? area_sum / double(measured) : 0;
  q.angle_distortion = measured ? angle_sum / double(3 * measured) * 180 / kPi : 0;
}

void check_landmark_counts(const CrossParamOptions& options) {
  const size_t n = options.source_landmarks.size();
  if (n != options.target_landmarks.size())
    throw Error("cross-parameterization: " + num(int64_t(n)) + " source and " +
                num(int64_t(options.target_landmarks.size())) + " target landmarks; they must correspond one to one");
  if (n > 0 && n < 3)
    throw Error("cross-parameterization: at least 3 landmark pairs are needed, got " + num(int64_t(n)));
}

// The source aligned to the target: with landmarks, warped by the LandmarkWarp between their
// snapped positions, which then also pull the registration as point constraints; without, as it
// is, since family members sit on the same build plate.
struct Alignment {
  std::vector<double> V;                             // 3 per source vertex
  std::vector<PointConstraint> constraints;          // warped source landmark -> target landmark
  std::vector<std::array<double, 3>> source_marks;  // the snapped source landmarks
};

Alignment align(const Mesh& source, const SurfaceGrid& grid, const CrossParamOptions& options) {
  Alignment out{source.V, {}, {}};
  if (options.source_landmarks.empty()) return out;
  out.source_marks = snapped(options.source_landmarks, SurfaceGrid(source));
  const std::vector<std::array<double, 3>> target_marks = snapped(options.target_landmarks, grid);
  const LandmarkWarp warp(out.source_marks, target_marks, options.in_plane);
  const size_t nv = source.vertices();
#pragma omp parallel for schedule(static)
  for (long long i = 0; i < (long long)nv; ++i) warp.apply(&source.V[3 * i], &out.V[3 * i]);
  for (size_t k = 0; k < out.source_marks.size(); ++k) {
    PointConstraint c;
    warp.apply(out.source_marks[k].data(), c.source.data());
    c.target = target_marks[k];
    if (options.in_plane) c.target[2] = c.source[2];
    out.constraints.push_back(c);
  }
  return out;
}

// The aligned source vertices moved by the registration's field.
std::vector<double> moved_by(const DisplacementField& field, const std::vector<double>& aligned) {
  std::vector<double> moved(aligned.size());
#pragma omp parallel for schedule(static)
  for (long long i = 0; i < (long long)(aligned.size() / 3); ++i) field.apply(&aligned[3 * i], &moved[3 * i]);
  return moved;
}

// A map from source to target with room for every source vertex's image.
SurfaceMap empty_map(const Mesh& source, const Mesh& target) {
  SurfaceMap map;
  map.source = mesh_fingerprint(source);
  map.target = mesh_fingerprint(target);
  map.source_vertices = source.vertices();
  map.target_vertices = target.vertices();
  map.source_faces = source.F;
  map.face.resize(source.vertices());
  map.bary.resize(3 * source.vertices());
  return map;
}

// Places source vertices' images on the target: face and barycentric coordinates into the map,
// the point into image (3 per vertex).
struct ImagePlacer {
  const SurfaceGrid& grid;
  std::vector<double> normal;  // of the registered source, 3 per vertex
  bool in_plane;
  // A level-set point is taken when it is at most this much farther than the nearest surface
  // point: on walls the two coincide; where they differ by more, the target has no level set
  // near this height here (a lower ridge top) and the nearest point wins.
  double tolerance;
  double reach;  // farthest image sought facing the same way
  SurfaceMap& map;
  std::vector<double>& image;

  // Places source vertex i's image at the target point for p (p's z is the vertex's own height
  // in the plane); false when nothing faces the same way within reach. on_level = false takes
  // the nearest surface point only (the soft height term).
  bool place(size_t i, const double p[3], bool on_level) {
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
  }
};

ImagePlacer image_placer(const SurfaceGrid& grid, const Mesh& source, const std::vector<double>& moved,
                         const RegistrationStats& reg, bool in_plane, SurfaceMap& map, std::vector<double>& image) {
  const double tolerance = 2 * grid.mean_edge(), reach = std::max(10 * reg.rms, 10 * grid.mean_edge());
  return {grid, vertex_normals(moved, source.F), in_plane, tolerance, reach, map, image};
}

// Every source vertex's image, from its registered position (at its own height in the plane);
// returns how many found no target surface facing the same way within reach.
uint64_t project_vertices(const Mesh& source, const std::vector<double>& moved, ImagePlacer& placer) {
  const bool in_plane = placer.in_plane;
  uint64_t far = 0;
#pragma omp parallel for schedule(dynamic, 512) reduction(+ : far)
  for (long long i = 0; i < (long long)source.vertices(); ++i) {
    const double p[3] = {moved[3 * i], moved[3 * i + 1], in_plane ? source.V[3 * i + 2] : moved[3 * i + 2]};
    far += !placer.place(size_t(i), p, true);
  }
  return far;
}

// Local untangling: where independent projections of neighbours fold a small triangle over
// (tight level-set curves near a saddle such as the arch's end-cap poles), each corner of a
// folded triangle is placed again from the mean image of its neighbours (a Laplacian step).
// A vertex still folded after kLevelTries placements sits where the target's level set at its
// height cannot hold its neighbourhood (a ridge top that reaches that height in one point on
// the target, a whole row of vertices on the source): it takes the nearest surface point
// instead, the soft height term, and its |dz| is reported as height error.
void untangle(const Mesh& source, const std::vector<double>& moved, ImagePlacer& placer) {
  const std::vector<double>& image = placer.image;
  const size_t nv = source.vertices(), nf = source.faces();
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
      if (placer.in_plane) p[2] = source.V[3 * v + 2];
      placer.place(v, p, ++tries[v] < kLevelTries);
    }
  }
}

// Without landmarks nothing but the registration vouches for the correspondence: refuses a
// result where much of the source found no matching surface or the image folds over.
void refuse_unregistered(const Mesh& source, const RegistrationStats& reg, uint64_t far, const CrossParamQuality& q) {
  const double far_share = double(far) / double(std::max<size_t>(1, source.vertices()));
  if (reg.matched < 0.9 || far_share > 0.02 || q.flipped_triangles * 100 > source.faces())
    throw Error("cross-parameterization: the meshes could not be registered automatically (" +
                std::to_string(int(std::lround(100 * (1 - reg.matched)))) +
                " % of the source found no matching target surface, " + num(int64_t(q.flipped_triangles)) +
                " folded triangles); give corresponding landmarks (.pp files picked in MeshLab) for both meshes");
}

// About kPatches patches on the source (seeded at the landmarks first); a target vertex takes
// the patch of the source triangle whose image is nearest to it.
void colour_patches(const Mesh& source, const Mesh& target, const std::vector<double>& image,
                    const std::vector<std::array<double, 3>>& seeds, CrossParamResult& result) {
  result.source_patch = surface_patches(source, kPatches, seeds);
  result.quality.patches = *std::max_element(result.source_patch.begin(), result.source_patch.end()) + 1;
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
}

}  // namespace

CrossParamResult cross_parameterize(const Mesh& source, const Mesh& target, const CrossParamOptions& options,
                                    const Progress& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  CrossParamResult result;
  report_progress(progress, 0, "checking");
  check_topology(source, target, result.quality);
  check_landmark_counts(options);

  const SurfaceGrid grid(target);
  report_progress(progress, 0.1, "aligning");
  const Alignment aligned = align(source, grid, options);
  RegistrationStats reg;
  const DisplacementField field = register_on_lattice(aligned.V, source.F, grid, aligned.constraints, options.in_plane,
                                                      &reg, sub_progress(progress, 0.1, 0.7));

  report_progress(progress, 0.7, "projecting");
  std::vector<double> moved = moved_by(field, aligned.V);
  result.map = empty_map(source, target);
  std::vector<double> image(3 * source.vertices());
  ImagePlacer placer = image_placer(grid, source, moved, reg, options.in_plane, result.map, image);
  const uint64_t far = project_vertices(source, moved, placer);
  untangle(source, moved, placer);

  report_progress(progress, 0.8, "measuring");
  measure(source, moved, image, result.quality);
  if (options.source_landmarks.empty()) refuse_unregistered(source, reg, far, result.quality);

  report_progress(progress, 0.9, "patches");
  colour_patches(source, target, image, aligned.source_marks, result);
  result.registered = std::move(moved);
  result.quality.seconds = seconds_since(t0);
  report_progress(progress, 1, "done");
  return result;
}

}  // namespace slicereuse
