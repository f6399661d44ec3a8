#include "lattice_registration.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

#include "slicereuse/mesh/vec3.h"
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
// few enough unknowns for a sparse direct factorization.
constexpr double kNodes = 2500;
constexpr size_t kSamples = 40000;
constexpr int kPolyIterations = 8;
// Samples per block of the polynomial fit's sums (see polynomial_normal_equations).
constexpr size_t kSumBlock = 512;
constexpr int kPolyTerms = DisplacementField::kPolyTerms;
// The weight of a point constraint against the samples' (whose weights sum to 1).
constexpr double kConstraintWeight = 0.02;
constexpr double kBeta = 0.1;    // point-to-point share, keeps sliding along walls in check
constexpr double kMinDot = 0.5;  // normals within 60 degrees
// Stiffness levels (times 1 / nodes), stiff first, and iterations per level.
constexpr double kAlphas[] = {100, 10, 1, 0.1};
constexpr int kPerLevel = 3;

// The lattice's box: the source's and the constraints' bounding box, lo moved out by one cell
// of margin, with a spacing h that gives about kNodes nodes.
struct LatticeBox {
  double lo[3], hi[3];  // lo includes the margin
  double extent, h;
  int dims[3];
};

LatticeBox lattice_box(const std::vector<double>& V, const std::vector<PointConstraint>& constraints) {
  LatticeBox box;
  double *lo = box.lo, *hi = box.hi;
  for (int a = 0; a < 3; ++a) lo[a] = hi[a] = V[a];
  for (size_t i = 0; i < V.size() / 3; ++i)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], V[3 * i + a]), hi[a] = std::max(hi[a], V[3 * i + a]);
  for (const PointConstraint& c : constraints)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], c.source[a]), hi[a] = std::max(hi[a], c.source[a]);
  box.extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-9});
  double h = box.extent / 4;
  auto node_count = [&](double step) {
    double n = 1;
    for (int a = 0; a < 3; ++a) n *= std::ceil((hi[a] - lo[a]) / step) + 3;
    return n;
  };
  while (node_count(h * 0.95) <= kNodes) h *= 0.95;
  for (int a = 0; a < 3; ++a) {
    box.dims[a] = int(std::ceil((hi[a] - lo[a]) / h)) + 3;
    lo[a] -= h;
  }
  box.h = h;
  return box;
}

// The polynomial part's frame: centred on the source's box, scaled to half its extent (and
// half its height for z), so that its terms stay near 1.
void set_polynomial_frame(DisplacementField& field, const LatticeBox& box) {
  double centre[3];
  for (int a = 0; a < 3; ++a) centre[a] = (box.lo[a] + box.h + box.hi[a]) / 2;  // lo has the lattice margin
  field.set_polynomial_frame(centre, std::max(box.extent / 2, 1e-9),
                             std::max((box.hi[2] - box.lo[2] - box.h) / 2, 1e-9));
}

// A third of the area of each face around each vertex.
std::vector<double> vertex_areas(const std::vector<double>& V, const std::vector<uint32_t>& F) {
  std::vector<double> area(V.size() / 3, 0.0);
  for (size_t f = 0; f < F.size(); f += 3) {
    const double *a = &V[3 * size_t(F[f])], *b = &V[3 * size_t(F[f + 1])], *c = &V[3 * size_t(F[f + 2])];
    const double A = norm(cross(sub(b, a), sub(c, a))) / 6;
    for (int j = 0; j < 3; ++j) area[F[f + j]] += A;
  }
  return area;
}

// The points the registration pulls: every vertex up to kSamples, else an even stride; each
// weighted by its vertex area over the samples' total (vertices without area are left out).
struct Samples {
  std::vector<uint32_t> vertex;
  std::vector<double> weight;
  size_t size() const { return vertex.size(); }
};

Samples area_weighted_samples(const std::vector<double>& V, const std::vector<uint32_t>& F) {
  const size_t nv = V.size() / 3;
  const size_t stride = std::max<size_t>(1, (nv + kSamples - 1) / kSamples);
  const std::vector<double> area = vertex_areas(V, F);
  Samples samples;
  double total_area = 0;
  for (size_t i = 0; i < nv; i += stride)
    if (area[i] > 0) samples.vertex.push_back(uint32_t(i)), total_area += area[i];
  if (samples.vertex.empty()) throw Error("cross-parameterization: the source mesh has no area");
  for (const uint32_t i : samples.vertex) samples.weight.push_back(area[i] / total_area);
  return samples;
}

// The lattice cell of each point: its 8 nodes and their trilinear weights.
struct Cells {
  explicit Cells(size_t points) : node(points), w(points) {}
  std::vector<std::array<uint32_t, 8>> node;
  std::vector<std::array<double, 8>> w;
};

Cells sample_cells(const DisplacementField& field, const std::vector<double>& V, const Samples& samples) {
  Cells cells(samples.size());
  for (size_t s = 0; s < samples.size(); ++s)
    field.cell_weights(&V[3 * size_t(samples.vertex[s])], cells.node[s].data(), cells.w[s].data());
  return cells;
}

Cells constraint_cells(const DisplacementField& field, const std::vector<PointConstraint>& constraints) {
  Cells cells(constraints.size());
  for (size_t k = 0; k < constraints.size(); ++k)
    field.cell_weights(constraints[k].source.data(), cells.node[k].data(), cells.w[k].data());
  return cells;
}

// What every phase reads: the source, the target, the constraints and the samples.
struct Problem {
  const std::vector<double>& V;
  const std::vector<uint32_t>& F;
  const SurfaceGrid& target;
  const std::vector<PointConstraint>& constraints;
  bool in_plane;
  int C;  // moved coordinates: 2 in the plane, else 3
  Samples samples;
  Cells sample_cells, constraint_cells;
};

// Pairs farther than `distance` are dropped; it shrinks to 4 RMS after every iteration, never
// below `floor`.
struct Trust {
  double distance, floor;
  void shrink(double rms) { distance = std::max(floor, std::min(distance, 4 * rms)); }
};

// The source moved by the field (P: 3 per vertex).
void move_source(const DisplacementField& field, const std::vector<double>& V, std::vector<double>& P) {
#pragma omp parallel for schedule(static)
  for (long long i = 0; i < (long long)(V.size() / 3); ++i) field.apply(&V[3 * i], &P[3 * i]);
}

// The pair of sample s at the current positions P: the nearest target point facing the same
// way within the trust distance, on the level set at the sample's own height when in_plane;
// n is the unit normal to pull along and gamma its weight. In the plane, the level set's
// normal is the face normal's xy part; on nearly horizontal faces it is unreliable and the
// point-to-point term takes over. False when there is no pair.
struct Pairing {
  double q[3], n[3], gamma;
};

bool pair_sample(const Problem& pb, size_t s, const std::vector<double>& P, const std::vector<double>& normal,
                 double trust, Pairing& out) {
  const size_t i = pb.samples.vertex[s];
  const double* p = &P[3 * i];
  const SurfacePoint q = pb.in_plane ? pb.target.nearest_on_level(p, pb.V[3 * i + 2], &normal[3 * i], kMinDot, trust)
                                     : pb.target.nearest_on_surface(p, &normal[3 * i], kMinDot, trust);
  if (q.face == kNoFace) return false;
  const double* tn = &pb.target.face_normals()[3 * size_t(q.face)];
  for (int a = 0; a < 3; ++a) out.q[a] = q.xyz[a], out.n[a] = a == 2 && pb.in_plane ? 0.0 : tn[a];
  const double len = norm(out.n);
  out.gamma = pb.in_plane ? std::min(1.0, len / 0.3) : 1.0;
  if (len > 0)
    for (double& x : out.n) x /= len;
  return true;
}

// The polynomial part's normal equations (C * kPolyTerms unknowns) at the current positions,
// exact point-to-plane plus a little point-to-point per paired sample, and the pairs' squared
// distance and weight.
struct PolynomialSystem {
  Eigen::MatrixXd M;
  Eigen::VectorXd r;
  double sq = 0, matched = 0;
};

PolynomialSystem polynomial_normal_equations(const Problem& pb, const DisplacementField& field,
                                             const std::vector<double>& P, const std::vector<double>& normal,
                                             double trust) {
  constexpr int T = kPolyTerms;
  const int C = pb.C, U = C * T;
  const size_t ns = pb.samples.size();
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
      if (!pair_sample(pb, s, P, normal, trust, pr)) continue;
      const size_t i = pb.samples.vertex[s];
      const double* p = &P[3 * i];
      const double W = pb.samples.weight[s];
      const double d[3] = {pr.q[0] - p[0], pr.q[1] - p[1], pb.in_plane ? 0.0 : pr.q[2] - p[2]};
      sqb[blk] += W * dot(d, d);
      mb[blk] += W;
      const double* n = pr.n;
      const double gamma = pr.gamma;
      // Residual of the whole polynomial displacement against the original position.
      const double g[3] = {pr.q[0] - pb.V[3 * i], pr.q[1] - pb.V[3 * i + 1], pr.q[2] - pb.V[3 * i + 2]};
      double b[T];
      field.polynomial_basis(&pb.V[3 * i], b);
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
          for (int l = 0; l < T; ++l) Ml(c * T + k, c * T + l) += W * kBeta * S * S * b[k] * b[l];
          rl(c * T + k) += W * kBeta * S * b[k] * g[c];
        }
    }
  }
  PolynomialSystem sys{Eigen::MatrixXd::Zero(U, U), Eigen::VectorXd::Zero(U)};
  for (size_t blk = 0; blk < blocks; ++blk)
    sys.M += Mb[blk], sys.r += rb[blk], sys.sq += sqb[blk], sys.matched += mb[blk];
  return sys;
}

// The constraints' point-to-point terms, added to the polynomial's normal equations.
void add_polynomial_constraints(const Problem& pb, const DisplacementField& field, PolynomialSystem& sys) {
  constexpr int T = kPolyTerms;
  for (const PointConstraint& pc : pb.constraints) {
    double b[T];
    field.polynomial_basis(pc.source.data(), b);
    const double S = field.poly_scale();
    for (int c = 0; c < pb.C; ++c)
      for (int k = 0; k < T; ++k) {
        for (int l = 0; l < T; ++l) sys.M(c * T + k, c * T + l) += kConstraintWeight * S * S * b[k] * b[l];
        sys.r(c * T + k) += kConstraintWeight * S * b[k] * (pc.target[c] - pc.source[c]);
      }
  }
}

// Stage 1: the polynomial part by exact point-to-plane ICP (a dense system of kPolyTerms terms
// per moved coordinate), the lattice part still zero.
void fit_polynomial(const Problem& pb, DisplacementField& field, Trust& trust, RegistrationStats& st,
                    const Progress& progress) {
  std::vector<double> P(pb.V.size());
  for (int it = 0; it < kPolyIterations; ++it) {
    report_progress(progress, double(it) / kPolyIterations, "registering");
    move_source(field, pb.V, P);
    const std::vector<double> normal = vertex_normals(P, pb.F);
    PolynomialSystem sys = polynomial_normal_equations(pb, field, P, normal, trust.distance);
    add_polynomial_constraints(pb, field, sys);
    sys.M.diagonal().array() += 1e-9;
    const Eigen::VectorXd x = sys.M.ldlt().solve(sys.r);
    for (int c = 0; c < pb.C; ++c)
      for (int k = 0; k < kPolyTerms; ++k) field.poly[c][k] = x(c * kPolyTerms + k);
    st.rms = sys.matched > 0 ? std::sqrt(sys.sq / sys.matched) : 0;
    st.matched = sys.matched;
    trust.shrink(st.rms);
  }
}

// The data term's matrix: per sample (weight W) and constraint, W * w_k * w_l between the
// nodes k, l of its cell. The same for every coordinate and, since every sample keeps its
// weight (an unmatched one is held where it is), for every iteration of a level.
Eigen::SparseMatrix<double> data_matrix(const Problem& pb, Eigen::Index nodes) {
  std::vector<Eigen::Triplet<double>> data;
  data.reserve((pb.samples.size() + pb.constraints.size()) * 64);
  auto add_data = [&](const uint32_t* node, const double* w, double W) {
    for (int k = 0; k < 8; ++k)
      for (int l = 0; l < 8; ++l)
        if (w[k] != 0 && w[l] != 0) data.emplace_back(int(node[k]), int(node[l]), W * w[k] * w[l]);
  };
  for (size_t s = 0; s < pb.samples.size(); ++s)
    add_data(pb.sample_cells.node[s].data(), pb.sample_cells.w[s].data(), pb.samples.weight[s]);
  for (size_t k = 0; k < pb.constraints.size(); ++k)
    add_data(pb.constraint_cells.node[k].data(), pb.constraint_cells.w[k].data(), kConstraintWeight);
  Eigen::SparseMatrix<double> m(nodes, nodes);
  m.setFromTriplets(data.begin(), data.end());
  return m;
}

// Bending energy: squared second differences along every lattice line, per coordinate.
Eigen::SparseMatrix<double> bending_matrix(const DisplacementField& field) {
  const size_t N = field.nodes();
  const int* D = field.dims();
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
  const Eigen::Index n_nodes = Eigen::Index(N);
  Eigen::SparseMatrix<double> bend(n_nodes, n_nodes);
  bend.setFromTriplets(bt.begin(), bt.end());
  return bend;
}

// Each sample's goal: its current position moved toward its pair, point-to-plane plus a little
// point-to-point (the linearized goal of that energy), or kept when unpaired; with the pairs'
// squared distance and weight.
struct Goals {
  std::vector<double> goal;  // 3 per sample
  double sq = 0, matched = 0;
};

Goals sample_goals(const Problem& pb, const std::vector<double>& P, const std::vector<double>& normal, double trust) {
  const size_t ns = pb.samples.size();
  Goals goals{std::vector<double>(3 * ns)};
  std::vector<double> sq_of(ns, 0.0), matched_of(ns, 0.0);  // summed in order below
#pragma omp parallel for schedule(dynamic, 256)
  for (long long s = 0; s < (long long)ns; ++s) {
    const size_t i = pb.samples.vertex[s];
    const double* p = &P[3 * i];
    double* g = &goals.goal[3 * s];
    for (int a = 0; a < 3; ++a) g[a] = p[a];
    Pairing pr;
    if (!pair_sample(pb, size_t(s), P, normal, trust, pr)) continue;
    const double W = pb.samples.weight[s];
    const double r[3] = {pr.q[0] - p[0], pr.q[1] - p[1], pb.in_plane ? 0.0 : pr.q[2] - p[2]};
    sq_of[s] = W * dot(r, r);
    matched_of[s] = W;
    const double* n = pr.n;
    const double gamma = pr.gamma;
    const double rn = dot(n, r);
    for (int a = 0; a < 3; ++a) g[a] += (gamma * n[a] * rn + kBeta * r[a]) / (gamma + kBeta);
  }
  for (size_t s = 0; s < ns; ++s) goals.sq += sq_of[s], goals.matched += matched_of[s];
  return goals;
}

// The lattice's right-hand side (nodes x C): what the samples' goals and the constraints'
// targets ask of the lattice beyond the polynomial part's image.
Eigen::MatrixXd lattice_rhs(const Problem& pb, const DisplacementField& polynomial_only, const Goals& goals,
                            Eigen::Index nodes) {
  const int C = pb.C;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nodes, C);
  for (size_t s = 0; s < pb.samples.size(); ++s) {
    const double W = pb.samples.weight[s];
    const size_t i = pb.samples.vertex[s];
    double base[3];  // the polynomial part's image; the lattice carries the rest
    polynomial_only.apply(&pb.V[3 * i], base);
    const std::array<uint32_t, 8>& node = pb.sample_cells.node[s];
    const std::array<double, 8>& w = pb.sample_cells.w[s];
    for (int k = 0; k < 8; ++k)
      for (int c = 0; c < C; ++c) rhs(node[k], c) += W * w[k] * (goals.goal[3 * s + c] - base[c]);
  }
  for (size_t k = 0; k < pb.constraints.size(); ++k) {
    double base[3];
    polynomial_only.apply(pb.constraints[k].source.data(), base);
    const std::array<uint32_t, 8>& node = pb.constraint_cells.node[k];
    const std::array<double, 8>& w = pb.constraint_cells.w[k];
    for (int j = 0; j < 8; ++j)
      for (int c = 0; c < C; ++c) rhs(node[j], c) += kConstraintWeight * w[j] * (pb.constraints[k].target[c] - base[c]);
  }
  return rhs;
}

// Stage 2: the lattice part, level by level from stiff to detailed. Its matrix is the same for
// every coordinate and iteration of a level: one factorization per level, then a back
// substitution per moved coordinate and iteration.
void fit_lattice(const Problem& pb, DisplacementField& field, Trust& trust, RegistrationStats& st,
                 const Progress& progress) {
  const size_t N = field.nodes();
  const Eigen::Index n_nodes = Eigen::Index(N);
  const Eigen::SparseMatrix<double> data = data_matrix(pb, n_nodes), bend = bending_matrix(field);
  Eigen::SparseMatrix<double> identity(n_nodes, n_nodes);
  identity.setIdentity();
  const double alpha0 = 1.0 / double(N);
  const int total_iterations = int(std::size(kAlphas)) * kPerLevel;
  std::vector<double> P(pb.V.size());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  const DisplacementField polynomial_only = field;  // lattice values all zero
  int iteration = 0;
  for (const double level : kAlphas) {
    const double alpha = level * alpha0;
    solver.compute(data + alpha * bend + (1e-9 * alpha) * identity);
    if (solver.info() != Eigen::Success)
      throw Error("cross-parameterization: the registration system could not be factorized");
    for (int it = 0; it < kPerLevel; ++it, ++iteration) {
      report_progress(progress, double(iteration) / total_iterations, "registering");
      move_source(field, pb.V, P);
      const std::vector<double> normal = vertex_normals(P, pb.F);
      const Goals goals = sample_goals(pb, P, normal, trust.distance);
      const Eigen::MatrixXd rhs = lattice_rhs(pb, polynomial_only, goals, n_nodes);
      st.rms = goals.matched > 0 ? std::sqrt(goals.sq / goals.matched) : 0;
      st.matched = goals.matched;
      st.iterations = iteration + 1;
      const Eigen::MatrixXd values = solver.solve(rhs);
      for (size_t n = 0; n < N; ++n)
        for (int c = 0; c < pb.C; ++c) field.values()[n * pb.C + c] = values(Eigen::Index(n), c);
      trust.shrink(st.rms);
    }
  }
}

}  // namespace

DisplacementField register_on_lattice(const std::vector<double>& V, const std::vector<uint32_t>& F,
                                      const SurfaceGrid& target, const std::vector<PointConstraint>& constraints,
                                      bool in_plane, RegistrationStats* stats, const Progress& progress) {
  const LatticeBox box = lattice_box(V, constraints);
  DisplacementField field(box.lo, box.h, box.dims, in_plane ? 2 : 3);
  set_polynomial_frame(field, box);
  Samples samples = area_weighted_samples(V, F);
  Cells cells = sample_cells(field, V, samples);
  const Problem pb{V, F, target, constraints, in_plane, field.components(), std::move(samples), std::move(cells),
                   constraint_cells(field, constraints)};
  Trust trust{std::max(0.15 * std::sqrt(3.0) * box.extent, 10 * target.mean_edge()), 3 * target.mean_edge()};
  RegistrationStats st;
  fit_polynomial(pb, field, trust, st, sub_progress(progress, 0, 0.3));
  fit_lattice(pb, field, trust, st, sub_progress(progress, 0.3, 1));
  if (stats) *stats = st;
  return field;
}

}  // namespace slicereuse
