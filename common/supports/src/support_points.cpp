#include "slicereuse/supports/support_points.h"

#include <cmath>

#include "slicereuse/mesh/vec3.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse {

void SupportPoints::push_back_from(const SupportPoints& o, size_t i) {
  face.push_back(o.face[i]);
  kind.push_back(o.kind[i]);
  layer.push_back(o.layer[i]);
  for (int j = 0; j < 3; ++j) {
    bary.push_back(o.bary[3 * i + j]);
    xyz.push_back(o.xyz[3 * i + j]);
    normal.push_back(o.normal[3 * i + j]);
  }
}

bool normal_faces_up(double normal_z) { return normal_z > std::cos(M_PI / 6); }

bool faces_up(const SupportPoints& points, size_t i) { return normal_faces_up(points.normal[3 * i + 2]); }

void place_support_points(SupportPoints& points, const Mesh& mesh) {
  const size_t n = points.size();
  points.xyz.assign(3 * n, 0);
  points.normal.assign(3 * n, 0);
  for (size_t i = 0; i < n; ++i) {
    const uint32_t* f = &mesh.F[3 * size_t(points.face[i])];
    const double* v[3] = {&mesh.V[3 * size_t(f[0])], &mesh.V[3 * size_t(f[1])], &mesh.V[3 * size_t(f[2])]};
    for (int j = 0; j < 3; ++j)
      points.xyz[3 * i + j] = points.bary[3 * i] * v[0][j] + points.bary[3 * i + 1] * v[1][j] + points.bary[3 * i + 2] * v[2][j];
    const Vec3 nrm = cross(sub(v[1], v[0]), sub(v[2], v[0]));
    const double len = norm(nrm);
    for (int j = 0; j < 3; ++j) points.normal[3 * i + j] = len > 0 ? nrm[j] / len : 0;
  }
}

void validate_support_points(const SupportPoints& p, const Mesh* mesh) {
  const size_t n = p.size();
  if (p.bary.size() != 3 * n || p.xyz.size() != 3 * n || p.normal.size() != 3 * n || p.kind.size() != n ||
      p.layer.size() != n)
    throw Error(format("the support points' arrays disagree: %zu faces, %zu area coordinates, %zu positions, "
                       "%zu normals, %zu kinds, %zu layers",
                       n, p.bary.size(), p.xyz.size(), p.normal.size(), p.kind.size(), p.layer.size()));
  for (size_t i = 0; i < n; ++i) {
    if (p.face[i] >= p.fingerprint.faces)
      throw Error(format("support point %zu lies on face %u, but the mesh it was made for has %llu faces", i + 1,
                         p.face[i], (unsigned long long)p.fingerprint.faces));
    double sum = 0;
    for (int j = 0; j < 3; ++j) {
      const double b = p.bary[3 * i + j];
      if (!std::isfinite(b) || b < -1e-9 || b > 1 + 1e-9)
        throw Error(format("support point %zu has area coordinate %g, outside [0, 1]", i + 1, b));
      sum += b;
      if (!std::isfinite(p.xyz[3 * i + j]) || !std::isfinite(p.normal[3 * i + j]))
        throw Error(format("support point %zu has a position or normal that is not a finite number", i + 1));
    }
    if (std::fabs(sum - 1) > 1e-6)
      throw Error(format("support point %zu has area coordinates summing to %.9g, not 1", i + 1, sum));
    if (p.kind[i] > 1) throw Error(format("support point %zu has kind %u; 0 (island) and 1 (overhang) exist", i + 1, p.kind[i]));
  }
  if (mesh) {
    const Fingerprint fp = mesh_fingerprint(*mesh);
    if (fp != p.fingerprint)
      throw Error("the support points are for a mesh of " + describe_fingerprint(p.fingerprint) + ", this one has " +
                  describe_fingerprint(fp));
  }
}

}  // namespace slicereuse
