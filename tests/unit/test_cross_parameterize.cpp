// cross_parameterize on pairs of really different connectivity: two tessellations of one
// family shape (different vertex and face counts and order), the target a deformed member; and
// a member with shuffled vertices and faces. The true image of each source vertex is known: the
// member's deformation applied to it (deform_like_family_member), or for the shuffled mesh the
// same vertex.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <string>

#include "family.h"
#include "slicereuse/cross_parameterize.h"
#include "slicereuse/error.h"
#include "slicereuse/mesh_topology.h"

using namespace slicereuse;
using namespace slicereuse::test;

namespace {

struct Pair {
  Mesh source, target;
  std::vector<double> truth;  // true image of each source vertex
};

Pair family_pair(const std::string& shape, size_t source_faces, size_t target_faces, int member) {
  FamilyOptions o;
  o.shape = shape;
  o.faces = source_faces;
  Pair p;
  p.source = make_family_base(o);
  o.faces = target_faces;
  const Mesh base2 = make_family_base(o);
  p.target = make_family_member(base2, o, member);
  p.truth = deform_like_family_member(base2, o, member, p.source.V);
  return p;
}

// Largest distance between a source vertex's image and its true image.
double max_truth_distance(const Pair& p, const SurfaceMap& map) {
  double worst = 0;
  for (size_t i = 0; i < map.size(); ++i) {
    double x[3];
    map_point(map, p.target, i, x);
    worst = std::max(worst, std::sqrt((x[0] - p.truth[3 * i]) * (x[0] - p.truth[3 * i]) +
                                      (x[1] - p.truth[3 * i + 1]) * (x[1] - p.truth[3 * i + 1]) +
                                      (x[2] - p.truth[3 * i + 2]) * (x[2] - p.truth[3 * i + 2])));
  }
  return worst;
}

void print(const std::string& what, const CrossParamQuality& q, double truth) {
  std::printf("%-28s flipped %llu  dz max %.3g rms %.3g  area %.4f angle %.3f deg  patches %llu genus %d  %.2f s  truth %.4f mm\n",
              what.c_str(), (unsigned long long)q.flipped_triangles, q.max_height_error, q.rms_height_error,
              q.area_distortion, q.angle_distortion, (unsigned long long)q.patches, q.genus, q.seconds, truth);
}

}  // namespace

TEST(CrossParameterize, Explore) {
  for (const std::string shape : {"arch", "ear", "sphere", "box", "handle", "torus"}) {
    const Pair p = family_pair(shape, 8000, 11000, 1);
    const CrossParamResult r = cross_parameterize(p.source, p.target, {});
    validate_surface_map(r.map);
    print(shape, r.quality, max_truth_distance(p, r.map));
  }
}
