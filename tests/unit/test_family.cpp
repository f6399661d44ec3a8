// Family generator: every member of every shape is a closed, consistently oriented 2-manifold
// of the shape's genus, shares the base's faces, keeps its z range (unless z_change), and is
// deterministic in the seed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "family.h"
#include "shapes.h"
#include "slicereuse/error.h"

using namespace slicereuse;
using namespace slicereuse::test;

namespace {

struct Range {
  double lo, hi;
};
Range z_range(const Mesh& m) {
  Range r{m.V[2], m.V[2]};
  for (size_t i = 2; i < m.V.size(); i += 3) r.lo = std::min(r.lo, m.V[i]), r.hi = std::max(r.hi, m.V[i]);
  return r;
}

// Smallest cosine between a face's normal in `m` and in `base`: positive means no face flipped.
double min_normal_cosine(const Mesh& base, const Mesh& m) {
  double worst = 1;
  for (size_t f = 0; f < base.faces(); ++f) {
    double n[2][3];
    for (int k = 0; k < 2; ++k) {
      const double* V = (k ? m : base).V.data();
      const double* a = V + 3 * size_t(base.F[3 * f]);
      const double* b = V + 3 * size_t(base.F[3 * f + 1]);
      const double* c = V + 3 * size_t(base.F[3 * f + 2]);
      const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      n[k][0] = u[1] * v[2] - u[2] * v[1];
      n[k][1] = u[2] * v[0] - u[0] * v[2];
      n[k][2] = u[0] * v[1] - u[1] * v[0];
    }
    const double dot = n[0][0] * n[1][0] + n[0][1] * n[1][1] + n[0][2] * n[1][2];
    worst = std::min(worst, dot / std::sqrt((n[0][0] * n[0][0] + n[0][1] * n[0][1] + n[0][2] * n[0][2]) *
                                            (n[1][0] * n[1][0] + n[1][1] * n[1][1] + n[1][2] * n[1][2])));
  }
  return worst;
}

}  // namespace

class FamilyShape : public ::testing::TestWithParam<std::string> {};

TEST_P(FamilyShape, MembersAreClosedManifoldsSharingFaces) {
  for (bool z_change : {false, true}) {
    FamilyOptions o;
    o.shape = GetParam();
    o.faces = 4000;
    o.height = 14.484;
    o.seed = 11;
    o.z_change = z_change;
    const Mesh base = make_family_base(o);
    EXPECT_NEAR(double(base.faces()), 4000.0, 4000 * 0.05);
    const Range zb = z_range(base);
    EXPECT_EQ(zb.lo, 0.0);
    EXPECT_EQ(zb.hi, 14.484);
    const long euler = 2 - 2 * family_shape_genus(o.shape);
    for (int i = 0; i < 4; ++i) {
      SCOPED_TRACE(o.shape + " member " + std::to_string(i) + (z_change ? " z-change" : ""));
      const Mesh m = make_family_member(base, o, i);
      ASSERT_EQ(m.F, base.F);
      ASSERT_EQ(m.V.size(), base.V.size());
      const EdgeCensus c = edge_census(m);
      EXPECT_EQ(c.bad_edges, 0u);
      EXPECT_EQ(long(m.vertices()) - long(c.edges) + long(m.faces()), euler);
      EXPECT_GT(signed_volume(m), 0);
      EXPECT_GT(min_normal_cosine(base, m), 0);
      const Range z = z_range(m);
      EXPECT_EQ(z.lo, 0.0);
      if (!z_change) {
        EXPECT_EQ(z.hi, zb.hi);
        for (size_t v = 2; v < m.V.size(); v += 3) ASSERT_EQ(m.V[v], base.V[v]);
      }
      if (i == 0) {
        EXPECT_EQ(m.V, base.V);
      }
      if (i > 0) {
        EXPECT_NE(m.V, base.V);
        EXPECT_NEAR(signed_volume(m), signed_volume(base), 0.35 * signed_volume(base));
      }
      if (i > 0 && z_change) {
        EXPECT_NE(z.hi, zb.hi);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllShapes, FamilyShape, ::testing::ValuesIn(family_shapes()));

TEST(Family, BaseVolumesOfBoxAndSphereMatchAnalytic) {
  FamilyOptions o;
  o.faces = 20000;
  o.height = 10;
  o.shape = "box";
  const double box = signed_volume(make_family_base(o));
  const double k = 10 / 14.5;  // the box is 20 x 12 x 14.5 scaled to height 10
  EXPECT_NEAR(box, 20 * 12 * 14.5 * k * k * k, 1e-9 * box);
  o.shape = "sphere";
  const double ball = 4.0 / 3 * 3.14159265358979323846 * 125;
  EXPECT_NEAR(signed_volume(make_family_base(o)), ball, 0.002 * ball);
}

TEST(Family, DeterministicInSeed) {
  FamilyOptions o;
  o.shape = "ear";
  o.faces = 3000;
  o.z_change = true;
  const Mesh base = make_family_base(o);
  EXPECT_EQ(make_family_member(base, o, 2).V, make_family_member(base, o, 2).V);
  EXPECT_NE(make_family_member(base, o, 2).V, make_family_member(base, o, 3).V);
  FamilyOptions other = o;
  other.seed = 2;
  EXPECT_NE(make_family_member(base, o, 2).V, make_family_member(base, other, 2).V);
}

TEST(Family, RejectsBadOptions) {
  FamilyOptions o;
  o.shape = "teapot";
  EXPECT_THROW(make_family_base(o), Error);
  o.shape = "arch";
  o.faces = 10;
  EXPECT_THROW(make_family_base(o), Error);
  o.faces = 2000;
  o.height = 0;
  EXPECT_THROW(make_family_base(o), Error);
  o.height = 5;
  EXPECT_THROW(make_family_member(make_family_base(o), o, -1), Error);
}
