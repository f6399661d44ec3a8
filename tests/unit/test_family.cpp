// Family generator: every member of every shape is a closed, consistently oriented 2-manifold
// of the shape's genus, shares the base's faces, keeps its z range (unless z_change), and is
// deterministic in the seed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "family.h"
#include "shapes.h"
#include "slicereuse/util/error.h"

using namespace slicereuse;
using namespace slicereuse::test;

namespace {

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

// Pairs of faces sharing no vertex where an edge of one pierces the other (segment-triangle
// test, faces binned in a uniform grid). A valid member has none.
size_t self_intersections(const Mesh& m) {
  const double* V = m.V.data();
  auto P = [&](uint32_t v) { return V + 3 * size_t(v); };
  double lo[3], hi[3], edge = 0;
  for (int a = 0; a < 3; ++a) lo[a] = hi[a] = V[a];
  for (size_t i = 0; i < m.V.size(); i += 3)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], V[i + a]), hi[a] = std::max(hi[a], V[i + a]);
  for (size_t f = 0; f < m.faces(); ++f) {
    const double* a = P(m.F[3 * f]);
    const double* b = P(m.F[3 * f + 1]);
    edge = std::max({edge, std::fabs(a[0] - b[0]), std::fabs(a[1] - b[1]), std::fabs(a[2] - b[2])});
  }
  const double cell = 2 * edge;
  int n[3];
  for (int a = 0; a < 3; ++a) n[a] = int((hi[a] - lo[a]) / cell) + 1;
  std::vector<std::vector<uint32_t>> grid(static_cast<size_t>(n[0]) * n[1] * n[2]);
  for (size_t f = 0; f < m.faces(); ++f) {
    int c0[3], c1[3];
    for (int a = 0; a < 3; ++a) {
      double l = 1e300, h = -1e300;
      for (int k = 0; k < 3; ++k) l = std::min(l, P(m.F[3 * f + k])[a]), h = std::max(h, P(m.F[3 * f + k])[a]);
      c0[a] = int((l - lo[a]) / cell), c1[a] = int((h - lo[a]) / cell);
    }
    for (int i = c0[0]; i <= c1[0]; ++i)
      for (int j = c0[1]; j <= c1[1]; ++j)
        for (int k = c0[2]; k <= c1[2]; ++k) grid[(size_t(i) * n[1] + j) * n[2] + k].push_back(uint32_t(f));
  }
  // Edge pq strictly crosses triangle abc (Moller-Trumbore).
  auto pierces = [&](const double* p, const double* q, const uint32_t* t) {
    const double *a = P(t[0]), *b = P(t[1]), *c = P(t[2]);
    const double d[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double h[3] = {d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0]};
    const double det = e1[0] * h[0] + e1[1] * h[1] + e1[2] * h[2];
    if (std::fabs(det) < 1e-300) return false;
    const double s[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    const double u = (s[0] * h[0] + s[1] * h[1] + s[2] * h[2]) / det;
    const double qv[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]};
    const double v = (d[0] * qv[0] + d[1] * qv[1] + d[2] * qv[2]) / det;
    const double t_ = (e2[0] * qv[0] + e2[1] * qv[1] + e2[2] * qv[2]) / det;
    return u > 0 && v > 0 && u + v < 1 && t_ > 0 && t_ < 1;
  };
  size_t hits = 0;
  for (const auto& bin : grid) {
    for (size_t i = 0; i < bin.size(); ++i) {
      for (size_t j = i + 1; j < bin.size(); ++j) {
        const uint32_t* A = &m.F[3 * size_t(bin[i])];
        const uint32_t* B = &m.F[3 * size_t(bin[j])];
        bool shared = false;
        for (int x = 0; x < 3; ++x)
          for (int y = 0; y < 3; ++y) shared |= A[x] == B[y];
        if (shared) continue;
        bool cross = false;
        for (int k = 0; k < 3 && !cross; ++k)
          cross = pierces(P(A[k]), P(A[(k + 1) % 3]), B) || pierces(P(B[k]), P(B[(k + 1) % 3]), A);
        hits += cross;
      }
    }
  }
  return hits;
}

// Number of closed loops in the section of a closed mesh by the plane z: faces crossing the
// plane, joined through the crossing edges they share (a vertex at z counts as above).
size_t section_loops(const Mesh& m, double z) {
  std::vector<uint32_t> parent(m.faces());
  for (size_t f = 0; f < parent.size(); ++f) parent[f] = uint32_t(f);
  auto root = [&](uint32_t f) {
    while (parent[f] != f) f = parent[f] = parent[parent[f]];
    return f;
  };
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> first_face;
  std::set<uint32_t> crossing;
  for (size_t f = 0; f < m.faces(); ++f) {
    for (int j = 0; j < 3; ++j) {
      uint32_t a = m.F[3 * f + j], b = m.F[3 * f + (j + 1) % 3];
      if ((m.V[3 * size_t(a) + 2] < z) == (m.V[3 * size_t(b) + 2] < z)) continue;
      crossing.insert(uint32_t(f));
      auto [it, fresh] = first_face.try_emplace({std::min(a, b), std::max(a, b)}, uint32_t(f));
      if (!fresh) parent[root(uint32_t(f))] = root(it->second);
    }
  }
  std::set<uint32_t> roots;
  for (uint32_t f : crossing) roots.insert(root(f));
  return roots.size();
}

}  // namespace

class FamilyShape : public ::testing::TestWithParam<std::string> {};

namespace {
const char* z_change_name(ZChange z) {
  return z == ZChange::None ? "" : z == ZChange::Everywhere ? " z-change" : " z-band";
}
}  // namespace

TEST_P(FamilyShape, MembersAreClosedManifoldsSharingFaces) {
  for (ZChange z_change : {ZChange::None, ZChange::Everywhere, ZChange::Band}) {
    FamilyOptions o;
    o.shape = GetParam();
    o.faces = 4000;
    o.height = 14.484;
    o.seed = 11;
    o.z_change = z_change;
    const Mesh base = make_family_base(o);
    EXPECT_NEAR(double(base.faces()), 4000.0, 4000 * 0.05);
    const ZRange zb = z_range(base);
    EXPECT_EQ(zb.min, 0.0);
    EXPECT_EQ(zb.max, 14.484);
    const long euler = 2 - 2 * family_shape_genus(o.shape);
    for (int i = 0; i < 4; ++i) {
      SCOPED_TRACE(o.shape + " member " + std::to_string(i) + z_change_name(z_change));
      const Mesh m = make_family_member(base, o, i);
      ASSERT_EQ(m.F, base.F);
      ASSERT_EQ(m.V.size(), base.V.size());
      const EdgeCensus c = edge_census(m);
      EXPECT_EQ(c.bad_edges, 0u);
      EXPECT_EQ(long(m.vertices()) - long(c.edges) + long(m.faces()), euler);
      EXPECT_GT(signed_volume(m), 0);
      EXPECT_GT(min_normal_cosine(base, m), 0);
      EXPECT_EQ(self_intersections(m), 0u);
      const ZRange z = z_range(m);
      EXPECT_EQ(z.min, 0.0);
      if (z_change == ZChange::None) {
        EXPECT_EQ(z.max, zb.max);
        for (size_t v = 2; v < m.V.size(); v += 3) ASSERT_EQ(m.V[v], base.V[v]);
      }
      if (z_change == ZChange::Band) {
        // z moves inside one band of a fifth of the height within [0.2, 0.8] of it, and only
        // there: below 20 % and above 80 % every vertex keeps its z bit for bit.
        EXPECT_EQ(z.max, zb.max);
        double lo = zb.max, hi = 0;
        for (size_t v = 2; v < m.V.size(); v += 3) {
          if (m.V[v] == base.V[v]) continue;
          lo = std::min(lo, base.V[v]);
          hi = std::max(hi, base.V[v]);
        }
        if (i > 0) {
          EXPECT_GT(lo, 0.2 * zb.max);
          EXPECT_LT(hi, 0.8 * zb.max);
          EXPECT_LE(lo, hi);  // some vertex moved
          EXPECT_LE(hi - lo, 0.2 * zb.max);
        }
      }
      if (i == 0) {
        EXPECT_EQ(m.V, base.V);
      }
      if (i > 0) {
        EXPECT_NE(m.V, base.V);
        EXPECT_NEAR(signed_volume(m), signed_volume(base), 0.35 * signed_volume(base));
      }
      if (i > 0 && z_change == ZChange::Everywhere) {
        EXPECT_NE(z.max, zb.max);
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

TEST(Family, SectionsHaveTheIntendedLoops) {
  // Arch: wall ring (outer + hole), then the hollow's tooth-ridged roof splits the hole into 15,
  // then the solid crown is one loop, then 15 separate tooth tips. Ear: closed tip, then hollow.
  // Handle: one loop at the ends, the two legs in between. A z change moves the transitions, so
  // only heights well inside a band are checked with one.
  const struct { const char* shape; double z; size_t loops; bool z_change_too; } cases[] = {
      {"arch", 0.40, 2, true},   {"arch", 0.83, 16, false}, {"arch", 0.89, 1, true},
      {"arch", 0.96, 15, false}, {"ear", 0.05, 1, true},    {"ear", 0.5, 2, true},
      {"handle", 0.5, 2, true},  {"handle", 0.97, 1, true}, {"box", 0.5, 1, true},
      {"sphere", 0.5, 1, true},  {"torus", 0.5, 2, true}};
  for (const auto& c : cases) {
    for (ZChange z_change : {ZChange::None, ZChange::Everywhere, ZChange::Band}) {
      if (z_change != ZChange::None && !c.z_change_too) continue;
      FamilyOptions o;
      o.shape = c.shape;
      o.faces = 6000;
      o.height = 10;
      o.z_change = z_change;
      const Mesh base = make_family_base(o);
      for (int i = 0; i < 3; ++i)
        EXPECT_EQ(section_loops(make_family_member(base, o, i), c.z * 10), c.loops)
            << c.shape << " z " << c.z << " member " << i << z_change_name(z_change);
    }
  }
}

TEST(Family, SelfIntersectionCheckSeesOverlappingBoxes) {
  Mesh a = make_box(0, 0, 0, 2, 2, 2, 2);
  const Mesh b = make_box(0.7, 0.6, 0.5, 2.9, 2.8, 2.7, 3);
  test::append_mesh(a, b);
  EXPECT_GT(self_intersections(a), 0u);
}

TEST(Family, DeterministicInSeed) {
  FamilyOptions o;
  o.shape = "ear";
  o.faces = 3000;
  o.z_change = ZChange::Everywhere;
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
