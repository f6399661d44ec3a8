#include "lattice_registration.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

#include "slicereuse/mesh/vertex_normals.h"
#include "slicereuse/util/error.h"

namespace slicereuse {

DisplacementField::DisplacementField(const double lo[3], double spacing, const int dims[3], int components)
    : h_(spacing), components_(components) {
  for (int a = 0; a < 3; ++a) lo_[a] = lo[a], dims_[a] = std::max(2, dims[a]);
  d_.assign(nodes() * size_t(components), 0.0);
}

void DisplacementField::cell_weights(const double p[3], uint32_t node[8], double w[8]) const {
  int i[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    const double u = (p[a] - lo_[a]) / h_;
    i[a] = std::clamp(int(std::floor(u)), 0, dims_[a] - 2);
    f[a] = std::clamp(u - i[a], 0.0, 1.0);
  }
  for (int k = 0; k < 8; ++k) {
    const int dx = k & 1, dy = (k >> 1) & 1, dz = k >> 2;
    node[k] = uint32_t((size_t(i[2] + dz) * dims_[1] + (i[1] + dy)) * dims_[0] + (i[0] + dx));
    w[k] = (dx ? f[0] : 1 - f[0]) * (dy ? f[1] : 1 - f[1]) * (dz ? f[2] : 1 - f[2]);
  }
}

void DisplacementField::set_polynomial_frame(const double centre[3], double scale, double z_scale) {
  for (int a = 0; a < 3; ++a) centre_[a] = centre[a];
  poly_scale_ = scale;
  z_scale_ = z_scale;
}

void DisplacementField::polynomial_basis(const double p[3], double b[kPolyTerms]) const {
  const double u = (p[0] - centre_[0]) / poly_scale_, v = (p[1] - centre_[1]) / poly_scale_,
               t = (p[2] - centre_[2]) / z_scale_;
  const double lin[3] = {u, v, 1}, height[3] = {1, t, t * t};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) b[3 * i + k] = lin[i] * height[k];
}

void DisplacementField::apply(const double p[3], double out[3]) const {
  for (int a = 0; a < 3; ++a) out[a] = p[a];
  if (d_.empty()) return;
  double b[kPolyTerms];
  polynomial_basis(p, b);
  for (int c = 0; c < components_; ++c)
    for (int k = 0; k < kPolyTerms; ++k) out[c] += poly_scale_ * poly[c][k] * b[k];
  uint32_t node[8];
  double w[8];
  cell_weights(p, node, w);
  for (int k = 0; k < 8; ++k)
    for (int c = 0; c < components_; ++c) out[c] += w[k] * d_[size_t(node[k]) * components_ + c];
}

namespace {

// Lattice size and sample count: enough for the smooth deformations between family members,
// small enough for a sparse factorization in milliseconds.
constexpr double kNodes = 2500;
constexpr size_t kSamples = 40000;
constexpr int kPolyIterations = 8;
// Samples per block of the polynomial fit's sums (see its loop).
constexpr size_t kSumBlock = 512;

inline double dot3(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

DisplacementField register_on_lattice(const std::vector<double>& V, const std::vector<uint32_t>& F,
                                      const SurfaceGrid& target, const std::vector<PointConstraint>& constraints,
                                      bool in_plane, RegistrationStats* stats, const Progress& progress) {
  const size_t nv = V.size() / 3;
  const int C = in_plane ? 2 : 3;
  // Lattice over the source's bounding box with about kNodes nodes, one cell of margin.
  double lo[3], hi[3];
  for (int a = 0; a < 3; ++a) lo[a] = hi[a] = V[a];
  for (size_t i = 0; i < nv; ++i)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], V[3 * i + a]), hi[a] = std::max(hi[a], V[3 * i + a]);
  for (const PointConstraint& c : constraints)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], c.source[a]), hi[a] = std::max(hi[a], c.source[a]);
  const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-9});
  double h = extent / 4;
  auto node_count = [&](double step) {
    double n = 1;
    for (int a = 0; a < 3; ++a) n *= std::ceil((hi[a] - lo[a]) / step) + 3;
    return n;
  };
  while (node_count(h * 0.95) <= kNodes) h *= 0.95;
  int dims[3];
  for (int a = 0; a < 3; ++a) {
    dims[a] = int(std::ceil((hi[a] - lo[a]) / h)) + 3;
    lo[a] -= h;
  }
  DisplacementField field(lo, h, dims, C);
  const size_t N = field.nodes();
  const int* D = field.dims();

  // Samples: every vertex up to kSamples, else an even stride; weights are vertex areas.
  const size_t stride = std::max<size_t>(1, (nv + kSamples - 1) / kSamples);
  std::vector<double> area(nv, 0.0);
  for (size_t f = 0; f < F.size(); f += 3) {
    const double *a = &V[3 * size_t(F[f])], *b = &V[3 * size_t(F[f + 1])], *c = &V[3 * size_t(F[f + 2])];
    const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    const double A = std::sqrt(dot3(n, n)) / 6;
    for (int j = 0; j < 3; ++j) area[F[f + j]] += A;
  }
  std::vector<uint32_t> sample;
  double total_area = 0;
  for (size_t i = 0; i < nv; i += stride)
    if (area[i] > 0) sample.push_back(uint32_t(i)), total_area += area[i];
  if (sample.empty()) throw Error("cross-parameterization: the source mesh has no area");
  const size_t ns = sample.size();
  std::vector<uint32_t> s_node(8 * ns);
  std::vector<double> s_w(8 * ns);
  for (size_t s = 0; s < ns; ++s) field.cell_weights(&V[3 * size_t(sample[s])], &s_node[8 * s], &s_w[8 * s]);
  std::vector<std::array<uint32_t, 8>> c_node(constraints.size());
  std::vector<std::array<double, 8>> c_w(constraints.size());
  for (size_t k = 0; k < constraints.size(); ++k) field.cell_weights(constraints[k].source.data(), c_node[k].data(), c_w[k].data());

  // The normal equations' matrix is the same for every coordinate and, since every sample
  // keeps its weight (an unmatched one is held where it is), for every iteration of a level:
  // one factorization per level, then two or three back substitutions per iteration.
  const double constraint_weight = 0.02;
  std::vector<Eigen::Triplet<double>> data;
  data.reserve((ns + constraints.size()) * 64);
  auto add_data = [&](const uint32_t* node, const double* w, double W) {
    for (int k = 0; k < 8; ++k)
      for (int l = 0; l < 8; ++l)
        if (w[k] != 0 && w[l] != 0) data.emplace_back(int(node[k]), int(node[l]), W * w[k] * w[l]);
  };
  for (size_t s = 0; s < ns; ++s) add_data(&s_node[8 * s], &s_w[8 * s], area[sample[s]] / total_area);
  for (size_t k = 0; k < constraints.size(); ++k) add_data(c_node[k].data(), c_w[k].data(), constraint_weight);
  const Eigen::Index n_nodes = Eigen::Index(N);
  Eigen::SparseMatrix<double> data_matrix(n_nodes, n_nodes), bend(n_nodes, n_nodes), identity(n_nodes, n_nodes);
  data_matrix.setFromTriplets(data.begin(), data.end());
  data = {};
  // Bending energy: squared second differences along every lattice line, per coordinate.
  std::vector<Eigen::Triplet<double>> bt;
  for (size_t n = 0; n < N; ++n) {
    const int c[3] = {int(n % D[0]), int(n / D[0] % D[1]), int(n / (size_t(D[0]) * D[1]))};
    for (int a = 0; a < 3; ++a) {
      if (c[a] == 0 || c[a] == D[a] - 1) continue;
      const size_t e = a == 0 ? 1 : a == 1 ? size_t(D[0]) : size_t(D[0]) * D[1];
      const size_t idx[3] = {n - e, n, n + e};
      const double coef[3] = {1, -2, 1};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) bt.emplace_back(int(idx[i]), int(idx[j]), coef[i] * coef[j]);
    }
  }
  bend.setFromTriplets(bt.begin(), bt.end());
  identity.setIdentity();

  const double alpha0 = 1.0 / double(N);
  const double alphas[] = {100 * alpha0, 10 * alpha0, alpha0, 0.1 * alpha0};
  const int per_level = 3;
  const int total_iterations = int(std::size(alphas)) * per_level;
  const double beta = 0.1;     // point-to-point share, keeps sliding along walls in check
  const double min_dot = 0.5;  // normals within 60 degrees
  double trust = std::max(0.15 * std::sqrt(3.0) * extent, 10 * target.mean_edge());
  const double trust_floor = 3 * target.mean_edge();

  std::vector<double> P(V.size());
  RegistrationStats st;
  // The pair of sample s at the current positions P: the nearest target point facing the same
  // way within the trust distance, on the level set at the sample's own height when in_plane;
  // n is the unit normal to pull along and gamma its weight. In the plane, the level set's
  // normal is the face normal's xy part; on nearly horizontal faces it is unreliable and the
  // point-to-point term takes over. False when there is no pair.
  struct Pairing {
    double q[3], n[3], gamma;
  };
  auto pair_sample = [&](size_t s, const std::vector<double>& normal, Pairing& out) {
    const size_t i = sample[s];
    const double* p = &P[3 * i];
    const SurfacePoint q = in_plane ? target.nearest_on_level(p, V[3 * i + 2], &normal[3 * i], min_dot, trust)
                                    : target.nearest_on_surface(p, &normal[3 * i], min_dot, trust);
    if (q.face == kNoFace) return false;
    const double* tn = &target.face_normals()[3 * size_t(q.face)];
    for (int a = 0; a < 3; ++a) out.q[a] = q.xyz[a], out.n[a] = a == 2 && in_plane ? 0.0 : tn[a];
    const double len = std::sqrt(dot3(out.n, out.n));
    out.gamma = in_plane ? std::min(1.0, len / 0.3) : 1.0;
    if (len > 0)
      for (double& x : out.n) x /= len;
    return true;
  };
  // Stage 1: the polynomial part by exact point-to-plane ICP (a dense system of 9 terms per
  // moved coordinate), the lattice part still zero.
  {
    double centre[3];
    for (int a = 0; a < 3; ++a) centre[a] = (lo[a] + h + hi[a]) / 2;  // lo has the lattice margin
    field.set_polynomial_frame(centre, std::max(extent / 2, 1e-9), std::max((hi[2] - lo[2] - h) / 2, 1e-9));
  }
  constexpr int T = DisplacementField::kPolyTerms;
  const int U = C * T;
  const Progress polynomial_stage = sub_progress(progress, 0, 0.3), lattice_stage = sub_progress(progress, 0.3, 1);
  for (int it = 0; it < kPolyIterations; ++it) {
    report_progress(polynomial_stage, double(it) / kPolyIterations, "registering");
#pragma omp parallel for schedule(static)
    for (long long i = 0; i < (long long)nv; ++i) field.apply(&V[3 * i], &P[3 * i]);
    const std::vector<double> normal = vertex_normals(P, F);
    // Summed per fixed block of samples, then block by block in order (not by OpenMP's
    // reductions, which add in whatever order the threads finish), so the map is the same bytes
    // on every run and any thread count.
    const size_t blocks = (ns + kSumBlock - 1) / kSumBlock;
    std::vector<Eigen::MatrixXd> Mb(blocks, Eigen::MatrixXd::Zero(U, U));
    std::vector<Eigen::VectorXd> rb(blocks, Eigen::VectorXd::Zero(U));
    std::vector<double> sqb(blocks, 0.0), mb(blocks, 0.0);
#pragma omp parallel for schedule(dynamic, 1)
    for (long long blk = 0; blk < (long long)blocks; ++blk) {
      Eigen::MatrixXd& Ml = Mb[blk];
      Eigen::VectorXd& rl = rb[blk];
      for (size_t s = size_t(blk) * kSumBlock; s < std::min(ns, size_t(blk + 1) * kSumBlock); ++s) {
        Pairing pr;
        if (!pair_sample(s, normal, pr)) continue;
        const size_t i = sample[s];
        const double* p = &P[3 * i];
        const double W = area[i] / total_area;
        const double d[3] = {pr.q[0] - p[0], pr.q[1] - p[1], in_plane ? 0.0 : pr.q[2] - p[2]};
        sqb[blk] += W * dot3(d, d);
        mb[blk] += W;
        const double* n = pr.n;
        const double gamma = pr.gamma;
        // Residual of the whole polynomial displacement against the original position.
        const double g[3] = {pr.q[0] - V[3 * i], pr.q[1] - V[3 * i + 1], pr.q[2] - V[3 * i + 2]};
        double b[T];
        field.polynomial_basis(&V[3 * i], b);
        const double S = field.poly_scale();
        Eigen::VectorXd j = Eigen::VectorXd::Zero(U);
        for (int c = 0; c < C; ++c)
          for (int k = 0; k < T; ++k) j(c * T + k) = n[c] * S * b[k];
        double gn = 0;
        for (int c = 0; c < C; ++c) gn += n[c] * g[c];
        Ml.noalias() += (W * gamma) * j * j.transpose();
        rl += (W * gamma * gn) * j;
        for (int c = 0; c < C; ++c)
          for (int k = 0; k < T; ++k) {
            for (int l = 0; l < T; ++l) Ml(c * T + k, c * T + l) += W * beta * S * S * b[k] * b[l];
            rl(c * T + k) += W * beta * S * b[k] * g[c];
          }
      }
    }
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(U, U);
    Eigen::VectorXd r = Eigen::VectorXd::Zero(U);
    double sq = 0, matched = 0;
    for (size_t blk = 0; blk < blocks; ++blk) M += Mb[blk], r += rb[blk], sq += sqb[blk], matched += mb[blk];
    for (const PointConstraint& pc : constraints) {
      double b[T];
      field.polynomial_basis(pc.source.data(), b);
      const double S = field.poly_scale();
      for (int c = 0; c < C; ++c)
        for (int k = 0; k < T; ++k) {
          for (int l = 0; l < T; ++l) M(c * T + k, c * T + l) += constraint_weight * S * S * b[k] * b[l];
          r(c * T + k) += constraint_weight * S * b[k] * (pc.target[c] - pc.source[c]);
        }
    }
    M.diagonal().array() += 1e-9;
    const Eigen::VectorXd x = M.ldlt().solve(r);
    for (int c = 0; c < C; ++c)
      for (int k = 0; k < T; ++k) field.poly[c][k] = x(c * T + k);
    st.rms = matched > 0 ? std::sqrt(sq / matched) : 0;
    st.matched = matched;
    trust = std::max(trust_floor, std::min(trust, 4 * st.rms));
  }

  Eigen::MatrixXd rhs(Eigen::Index(N), C), values(Eigen::Index(N), C);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  const DisplacementField polynomial_only = field;  // lattice values all zero
  int iteration = 0;
  for (double alpha : alphas) {
    solver.compute(data_matrix + alpha * bend + (1e-9 * alpha) * identity);
    if (solver.info() != Eigen::Success)
      throw Error("cross-parameterization: the registration system could not be factorized");
    for (int it = 0; it < per_level; ++it, ++iteration) {
      report_progress(lattice_stage, double(iteration) / total_iterations, "registering");
#pragma omp parallel for schedule(static)
      for (long long i = 0; i < (long long)nv; ++i) field.apply(&V[3 * i], &P[3 * i]);
      const std::vector<double> normal = vertex_normals(P, F);
      // Each sample's goal: the current position moved toward its pair, point-to-plane plus a
      // little point-to-point (the linearized goal of that energy), or kept when unpaired.
      std::vector<double> goal(3 * ns);
      std::vector<double> sq_of(ns, 0.0), matched_of(ns, 0.0);  // summed in order below
#pragma omp parallel for schedule(dynamic, 256)
      for (long long s = 0; s < (long long)ns; ++s) {
        const size_t i = sample[s];
        const double* p = &P[3 * i];
        double* g = &goal[3 * s];
        for (int a = 0; a < 3; ++a) g[a] = p[a];
        Pairing pr;
        if (!pair_sample(size_t(s), normal, pr)) continue;
        const double W = area[i] / total_area;
        const double r[3] = {pr.q[0] - p[0], pr.q[1] - p[1], in_plane ? 0.0 : pr.q[2] - p[2]};
        sq_of[s] = W * dot3(r, r);
        matched_of[s] = W;
        const double* n = pr.n;
        const double gamma = pr.gamma;
        const double rn = dot3(n, r);
        for (int a = 0; a < 3; ++a) g[a] += (gamma * n[a] * rn + beta * r[a]) / (gamma + beta);
      }
      double sq = 0, matched = 0;
      for (size_t s = 0; s < ns; ++s) sq += sq_of[s], matched += matched_of[s];
      rhs.setZero();
      for (size_t s = 0; s < ns; ++s) {
        const double W = area[sample[s]] / total_area;
        const size_t i = sample[s];
        double base[3];  // the polynomial part's image; the lattice carries the rest
        polynomial_only.apply(&V[3 * i], base);
        for (int k = 0; k < 8; ++k)
          for (int c = 0; c < C; ++c) rhs(s_node[8 * s + k], c) += W * s_w[8 * s + k] * (goal[3 * s + c] - base[c]);
      }
      for (size_t k = 0; k < constraints.size(); ++k) {
        double base[3];
        polynomial_only.apply(constraints[k].source.data(), base);
        for (int j = 0; j < 8; ++j)
          for (int c = 0; c < C; ++c) rhs(c_node[k][j], c) += constraint_weight * c_w[k][j] * (constraints[k].target[c] - base[c]);
      }
      st.rms = matched > 0 ? std::sqrt(sq / matched) : 0;
      st.matched = matched;
      st.iterations = iteration + 1;
      values = solver.solve(rhs);
      for (size_t n = 0; n < N; ++n)
        for (int c = 0; c < C; ++c) field.values()[n * C + c] = values(Eigen::Index(n), c);
      trust = std::max(trust_floor, std::min(trust, 4 * st.rms));
    }
  }
  if (stats) *stats = st;
  return field;
}

}  // namespace slicereuse
