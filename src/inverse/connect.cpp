#include "inverse/connect.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include "inverse/geodesic_flow.hpp"
#include "inverse/richardson.hpp"
#include "linkage/chart.hpp"
#include "simulation/ambient_system.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

namespace {

double maxAbs(const Eigen::VectorXd& v) { return v.cwiseAbs().maxCoeff(); }

// A node's multipliers by least squares: G G^T mu = -G r with r = M (q_(i+1) - 2 q_i + q_(i-1)), the discrete
// Euler-Lagrange residual without them. Long chains (a sparse model) from the sparse M and G, O(n) instead of
// O(n^2) (docs/geometry.md, "Long chains"); small models by the dense formulas.
Eigen::VectorXd nodeMultipliers(const ConstrainedModel& model, const Eigen::VectorXd& before, const Eigen::VectorXd& q,
                                const Eigen::VectorXd& after) {
  if (model.sparse()) {
    const Eigen::SparseMatrix<double> g = model.sparseJacobian(q);
    const Eigen::VectorXd r = model.sparseMass() * (after - 2 * q + before);
    const Eigen::SparseMatrix<double> normal = g * g.transpose();
    return -Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(normal).solve(Eigen::VectorXd(g * r));
  }
  const Eigen::MatrixXd g = model.jacobian(q);
  const Eigen::VectorXd r = model.mass() * (after - 2 * q + before);
  return -(g * g.transpose()).ldlt().solve(g * r);
}

// The Newton matrix's entries of interior node i (row block (i - first) * block) from the sparse M, G and A_k:
// diagonal -(2 + shift) M + sum_k mu_k A_k and G, off-diagonal M to the unknown neighbours (`periodic`: the
// node count of a closed path, 0 for fixed ends). shift > 0 adds shift * M to the action's second variation
// (the Levenberg-Marquardt term of descendDiscrete).
void sparseNodeEntries(const ConstrainedModel& model, const Eigen::SparseMatrix<double>& g, const Eigen::VectorXd& mui,
                       int i, int first, int last, int block, int periodic, double shift,
                       std::vector<Eigen::Triplet<double>>& entries) {
  const int n = model.dimension(), m = model.constraintCount(), row = (i - first) * block;
  const Eigen::SparseMatrix<double>& mass = model.sparseMass();
  for (int k = 0; k < mass.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(mass, k); it; ++it) {
      const int r = static_cast<int>(it.row()), c = static_cast<int>(it.col());
      entries.emplace_back(row + r, row + c, -(2.0 + shift) * it.value());
      for (int neighbour : {i - 1, i + 1}) {
        int j = neighbour;
        if (periodic > 0) j = (j + periodic) % periodic;
        if (j < first || j > last) continue;
        entries.emplace_back(row + r, (j - first) * block + c, it.value());
      }
    }
  model.hessianEntries(mui, row, row, entries);
  for (int k = 0; k < g.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(g, k); it; ++it) {
      entries.emplace_back(row + n + static_cast<int>(it.row()), row + static_cast<int>(it.col()), it.value());
      entries.emplace_back(row + static_cast<int>(it.col()), row + n + static_cast<int>(it.row()), it.value());
    }
  for (int k = 0; k < m; ++k) entries.emplace_back(row + n + k, row + n + k, 0.0);
}

// The discrete Euler-Lagrange residual of interior node q between its neighbours (row block `row`) from the sparse
// M and G: M (next - 2 q + previous) + G^T mu, then the constraints' values.
void sparseNodeResidual(const ConstrainedModel& model, const Eigen::SparseMatrix<double>& g, const Eigen::VectorXd& mui,
                        const Eigen::VectorXd& previous, const Eigen::VectorXd& q, const Eigen::VectorXd& next, int row,
                        Eigen::VectorXd& residual) {
  const int n = model.dimension(), m = model.constraintCount();
  residual.segment(row, n) = model.sparseMass() * (next - 2 * q + previous) + Eigen::VectorXd(g.transpose() * mui);
  residual.segment(row + n, m) = model.values(q);
}

// The node system from its entries, factorised by `lu`, its pattern analysed on the first call only (the grid's
// pattern never changes); false if the factorisation fails.
bool factorNodeSystem(const std::vector<Eigen::Triplet<double>>& entries, int size,
                      Eigen::SparseLU<Eigen::SparseMatrix<double>>& lu, bool& analysed) {
  Eigen::SparseMatrix<double> jac(size, size);
  jac.setFromTriplets(entries.begin(), entries.end());
  if (!analysed) {
    lu.analyzePattern(jac);
    analysed = true;
  }
  lu.factorize(jac);
  return lu.info() == Eigen::Success;
}

// Newton's method on the discrete Euler-Lagrange equations with multipliers; nodes 0 and K fixed.
bool solveDiscrete(const ConstrainedModel& model, std::vector<Eigen::VectorXd>& nodes, bool periodic = false) {
  const int n = model.dimension(), m = model.constraintCount(), block = n + m;
  const int count = static_cast<int>(nodes.size());
  const int first = periodic ? 0 : 1, last = periodic ? count - 1 : count - 2;  // unknown nodes
  const int unknowns = last - first + 1;
  if (unknowns <= 0) return true;
  auto node = [&](int i) -> const Eigen::VectorXd& {
    if (periodic) return nodes[static_cast<std::size_t>((i + count) % count)];
    return nodes[static_cast<std::size_t>(i)];
  };
  // Multipliers from least squares on the current nodes.
  std::vector<Eigen::VectorXd> mu(static_cast<std::size_t>(count), Eigen::VectorXd::Zero(m));
  for (int i = first; i <= last; ++i)
    mu[static_cast<std::size_t>(i)] = nodeMultipliers(model, node(i - 1), node(i), node(i + 1));
  // Long chains (a sparse model) assemble from the sparse M, G and A_i: O(n) per node instead of O(n^2)
  // (docs/geometry.md, "Long chains"); small models keep the dense formulas.
  const bool sparse = model.sparse();
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  bool analysed = false;
  double previousStep = INFINITY, shrink = INFINITY, previousSize = 0;
  for (int iteration = 0; iteration < 40; ++iteration) {
    // Long chains: the factorisation is most of the work (the fill of a K x n grid), so near the solution
    // (steps below 1e-6 of the coordinates) it is kept while the steps it gives shrink tenfold (the chord
    // method; the residual is always the exact one, so the solution is the same).
    const bool factor = !sparse || !(shrink < 0.1 && previousStep < 1e-6 * (1.0 + previousSize));
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd residual(unknowns * block);
    for (int i = first; i <= last; ++i) {
      const int row = (i - first) * block;
      const Eigen::VectorXd& q = node(i);
      const Eigen::VectorXd& mui = mu[static_cast<std::size_t>(i)];
      if (sparse) {
        const Eigen::SparseMatrix<double> g = model.sparseJacobian(q);
        sparseNodeResidual(model, g, mui, node(i - 1), q, node(i + 1), row, residual);
        if (!factor) continue;
        sparseNodeEntries(model, g, mui, i, first, last, block, periodic ? count : 0, 0.0, entries);
        continue;
      }
      const Eigen::MatrixXd g = model.jacobian(q);
      residual.segment(row, n) = model.mass() * (node(i + 1) - 2 * q + node(i - 1)) + g.transpose() * mui;
      residual.segment(row + n, m) = model.values(q);
      const Eigen::MatrixXd diagonal = -2.0 * model.mass() + model.hessianMatrix(mui);
      for (int r = 0; r < n; ++r) {
        for (int c = 0; c < n; ++c) {
          if (diagonal(r, c) != 0.0) entries.emplace_back(row + r, row + c, diagonal(r, c));
          const double mass = model.mass()(r, c);
          if (mass == 0.0) continue;
          for (int neighbour : {i - 1, i + 1}) {
            int j = neighbour;
            if (periodic) j = (j + count) % count;
            if (j < first || j > last) continue;
            entries.emplace_back(row + r, (j - first) * block + c, mass);
          }
        }
        for (int k = 0; k < m; ++k) {
          if (g(k, r) == 0.0) continue;
          entries.emplace_back(row + r, row + n + k, g(k, r));
          entries.emplace_back(row + n + k, row + r, g(k, r));
        }
      }
      // Keep the structural diagonal of the multiplier rows (zero) so the pattern never changes.
      for (int k = 0; k < m; ++k) entries.emplace_back(row + n + k, row + n + k, 0.0);
    }
    if (factor && !factorNodeSystem(entries, unknowns * block, lu, analysed)) return false;
    const Eigen::VectorXd step = lu.solve(-residual);
    if (!step.allFinite()) return false;
    double largest = 0, size = 0;
    for (int i = first; i <= last; ++i) {
      const int row = (i - first) * block;
      Eigen::VectorXd& q = nodes[static_cast<std::size_t>(i)];
      q += step.segment(row, n);
      mu[static_cast<std::size_t>(i)] += step.segment(row + n, m);
      largest = std::max(largest, maxAbs(step.segment(row, n)));
      size = std::max(size, maxAbs(q));
    }
    if (largest > 10.0) return false;  // diverging
    // Converged when the step is down to rounding of the hinge coordinates (as large as the base L): below
    // 1e-14 of their size, or near it and no longer shrinking (Newton's steps at rounding level jitter).
    const double rounding = 1e-14 * (1.0 + size);
    if (largest < rounding || (largest < 100 * rounding && largest >= 0.5 * previousStep)) return true;
    shrink = std::isfinite(previousStep) ? largest / previousStep : INFINITY;
    previousStep = largest;
    previousSize = size;
  }
  return false;
}

double polygonLength(const ConstrainedModel& model, const std::vector<Eigen::VectorXd>& nodes) {
  double length = 0;
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) length += model.norm(nodes[i + 1] - nodes[i]);
  return length;
}

double pathEnergy(const ConstrainedModel& model, const std::vector<Eigen::VectorXd>& nodes) {
  double energy = 0;
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i)
    energy += model.inner(nodes[i + 1] - nodes[i], nodes[i + 1] - nodes[i]);
  return energy;
}

// Descent on the discrete action from a seed far from any geodesic (long chains, docs/geometry.md, "Long
// chains"): Newton's steps on the stationarity equations with shift * M added to the action's second variation
// (Levenberg-Marquardt), the nodes projected back onto the constraints after each step, a step kept only when
// it lowers the action; the shift shrinks after a kept step and grows after a refused one. It ends near a
// local minimum (a geodesic without conjugate points inside), where plain Newton (solveDiscrete) takes over.
bool descendDiscrete(const ConstrainedModel& model, std::vector<Eigen::VectorXd>& nodes) {
  if (!model.sparse()) return true;
  const int n = model.dimension(), m = model.constraintCount(), block = n + m;
  const int count = static_cast<int>(nodes.size()), first = 1, last = count - 2, unknowns = last - first + 1;
  if (unknowns <= 0) return true;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  bool analysed = false;
  double shift = 1.0, energy = pathEnergy(model, nodes);
  for (int iteration = 0; iteration < 60; ++iteration) {
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd residual(unknowns * block);
    for (int i = first; i <= last; ++i) {
      const int row = (i - first) * block;
      const Eigen::VectorXd &previous = nodes[static_cast<std::size_t>(i - 1)], &q = nodes[static_cast<std::size_t>(i)],
                            &next = nodes[static_cast<std::size_t>(i + 1)];
      const Eigen::VectorXd mui = nodeMultipliers(model, previous, q, next);
      const Eigen::SparseMatrix<double> g = model.sparseJacobian(q);
      sparseNodeResidual(model, g, mui, previous, q, next, row, residual);
      sparseNodeEntries(model, g, mui, i, first, last, block, 0, shift, entries);
    }
    if (!factorNodeSystem(entries, unknowns * block, lu, analysed)) return false;
    const Eigen::VectorXd step = lu.solve(-residual);
    if (!step.allFinite()) return false;
    std::vector<Eigen::VectorXd> trial = nodes;
    double largest = 0, size = 0;
    bool projected = true;
    for (int i = first; i <= last; ++i) {
      Eigen::VectorXd& q = trial[static_cast<std::size_t>(i)];
      q += step.segment((i - first) * block, n);
      projected = projected && model.projectPosition(q);
      largest = std::max(largest, maxAbs(step.segment((i - first) * block, n)));
      size = std::max(size, maxAbs(q));
    }
    const double trialEnergy = projected ? pathEnergy(model, trial) : INFINITY;
    if (trialEnergy < energy) {
      nodes = std::move(trial);
      energy = trialEnergy;
      shift /= 4;
      if (shift < 1e-6 && largest < 1e-6 * (1.0 + size)) return true;
    } else {
      shift *= 8;
      if (shift > 1e8) return false;
    }
  }
  return false;
}

std::vector<Eigen::VectorXd> refine(const ConstrainedModel& model, const std::vector<Eigen::VectorXd>& nodes) {
  std::vector<Eigen::VectorXd> finer;
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
    finer.push_back(nodes[i]);
    Eigen::VectorXd middle = (nodes[i] + nodes[i + 1]) / 2.0;
    model.projectPosition(middle);
    finer.push_back(middle);
  }
  finer.push_back(nodes.back());
  return finer;
}

Eigen::VectorXd samplesOf(const std::vector<Eigen::VectorXd>& nodes) {
  const int intervals = static_cast<int>(nodes.size()) - 1, n = static_cast<int>(nodes[0].size());
  Eigen::VectorXd out((kPathSamples + 1) * n);
  for (int j = 0; j <= kPathSamples; ++j)
    out.segment(j * n, n) = nodes[static_cast<std::size_t>(j * intervals / kPathSamples)];
  return out;
}

std::vector<Eigen::VectorXd> unpackSamples(const Eigen::VectorXd& packed, int n) {
  std::vector<Eigen::VectorXd> out;
  for (int j = 0; j <= kPathSamples; ++j) out.push_back(packed.segment(j * n, n));
  return out;
}

double pathDistance(const std::vector<Eigen::VectorXd>& a, const std::vector<Eigen::VectorXd>& b) {
  double worst = 0;
  for (std::size_t j = 0; j < a.size() && j < b.size(); ++j) worst = std::max(worst, maxAbs(a[j] - b[j]));
  return worst;
}

}  // namespace

std::vector<Eigen::VectorXd> shootingPath(const ConstrainedModel& model, const Eigen::VectorXd& from,
                                          const Eigen::VectorXd& velocity, int intervals, double tolerance) {
  const GeodesicFlow flow(model, tolerance);
  const int n = model.dimension();
  FlowState state{from, velocity, Eigen::MatrixXd(n, 0), Eigen::MatrixXd(n, 0)};
  std::vector<Eigen::VectorXd> path{from};
  for (int j = 1; j <= intervals; ++j) {
    flow.advance(state, 1.0 / intervals);
    path.push_back(state.q);
  }
  return path;
}

std::optional<Connection> shootConnection(const ConstrainedModel& model, const Eigen::VectorXd& from,
                                          const Eigen::VectorXd& to, Eigen::VectorXd velocity, double tolerance) {
  const GeodesicFlow flow(model, tolerance);
  const int n = model.dimension();
  const Eigen::MatrixXd basis = model.tangentBasis(from);
  const int d = static_cast<int>(basis.cols());
  // Long chains: the derivative dq(1)/dv costs d variation columns, O(d) times a bare shot; shot once, then
  // kept up to date by Broyden's rank-one updates from bare shots, and shot again only when a step fails
  // to halve the error (docs/geometry.md, "Long chains"). Small models take the exact derivative every time.
  const bool broyden = d > kExactShootingFreedom;
  velocity = model.projectVelocity(from, velocity);
  double previous = INFINITY;
  Eigen::MatrixXd jacobian;                // dq(1)/dv B: exact, or Broyden's estimate
  bool fresh = false;                      // the last step came from the exact derivative
  Eigen::VectorXd lastStep, lastResidual;  // for Broyden's update
  int exactShots = 0;
  for (int iteration = 1; iteration <= (broyden ? 80 : 40); ++iteration) {
    const bool exact = !broyden || jacobian.size() == 0 || lastStep.size() == 0;
    // Near the conjugate locus Newton stalls with the exact derivative too; the exact shots, the costly ones,
    // are bounded so that such a seed fails in a few of them.
    if (broyden && exact && ++exactShots > kMaxExactShots) return std::nullopt;
    FlowState state{from, velocity, Eigen::MatrixXd::Zero(n, exact ? d : 0), exact ? basis : Eigen::MatrixXd(n, 0)};
    try {
      flow.advance(state, 1.0);
    } catch (const std::runtime_error&) {
      return std::nullopt;
    }
    const Eigen::VectorXd residual = state.q - to;
    const double error = maxAbs(residual);
    if (error <= 1e-13 || (error <= 1e-12 && error >= previous * 0.5)) {
      Connection c;
      c.velocity = velocity;
      c.length = model.norm(velocity);
      c.endError = error;
      c.newtonIterations = iteration;
      return c;
    }
    if (exact) {
      jacobian = state.dq;
      fresh = true;
    } else if (error > 0.5 * previous && !fresh) {
      // Broyden's estimate no longer halves the error: back to the last point, the exact derivative there.
      velocity -= basis * lastStep;
      lastStep.resize(0);
      continue;
    } else {
      const Eigen::VectorXd change = residual - lastResidual;
      jacobian += (change - jacobian * lastStep) * lastStep.transpose() / lastStep.squaredNorm();
      fresh = false;
    }
    previous = error;
    lastResidual = residual;
    // Gauss-Newton in the mass metric: min |J x + r|_M.
    const Eigen::MatrixXd& j = jacobian;
    Eigen::VectorXd x;
    if (broyden) {
      const Eigen::MatrixXd mj = model.sparseMass() * j;
      x = (j.transpose() * mj).ldlt().solve(-(mj.transpose() * residual));
    } else {
      const Eigen::MatrixXd normal = j.transpose() * model.mass() * j;
      x = normal.ldlt().solve(-(j.transpose() * model.mass() * residual));
    }
    Eigen::VectorXd step = basis * x;
    const double limit = 0.5 * std::max(1.0, model.norm(velocity));
    if (model.norm(step) > limit) {
      x *= limit / model.norm(step);
      step = basis * x;
    }
    velocity += step;
    lastStep = x;
    if (!velocity.allFinite()) return std::nullopt;
  }
  return std::nullopt;
}

std::optional<DiscreteGeodesic> discreteGeodesic(const ConstrainedModel& model, std::vector<Eigen::VectorXd> nodes,
                                                 DiscreteSeed seedKind, bool descend) {
  for (std::size_t i = 1; i + 1 < nodes.size(); ++i) model.projectPosition(nodes[i]);
  Richardson lengths, paths;
  DiscreteGeodesic out;
  out.seed = seedKind;
  Eigen::VectorXd previousLength;
  Eigen::VectorXd previousPath;
  for (int level = 0; level < 7; ++level) {
    if (level > 0) nodes = refine(model, nodes);
    const std::vector<Eigen::VectorXd> seed = level == 0 && descend ? nodes : std::vector<Eigen::VectorXd>{};
    if (!solveDiscrete(model, nodes)) {
      if (seed.empty()) return std::nullopt;
      nodes = seed;
      if (!descendDiscrete(model, nodes) || !solveDiscrete(model, nodes)) return std::nullopt;
    }
    const Eigen::VectorXd length = lengths.add(Eigen::VectorXd::Constant(1, polygonLength(model, nodes)));
    const Eigen::VectorXd path = paths.add(samplesOf(nodes));
    out.nodes = static_cast<int>(nodes.size()) - 1;
    out.startVelocity = (nodes[1] - nodes[0]) * out.nodes;
    if (level > 0) {
      out.lengthChange = std::abs(length(0) - previousLength(0));
      const double pathChange = maxAbs(path - previousPath);
      out.length = length(0);
      out.path = unpackSamples(path, model.dimension());
      if (level >= 3 && out.lengthChange < 1e-11 && pathChange < 1e-10) return out;
    }
    previousLength = length;
    previousPath = path;
  }
  return out;  // the best estimate; lengthChange says how good
}

std::vector<std::vector<Eigen::VectorXd>> sphereArcPaths(const Chain& chain, const Eigen::VectorXd& from,
                                                         const Eigen::VectorXd& to, int intervals) {
  std::vector<std::vector<Eigen::VectorXd>> out;
  if (chain.isSlack()) return out;
  const Eigen::VectorXd a = spherePointFromHinges(chain, ConstrainedModel::unstack(from));
  const Eigen::VectorXd b = spherePointFromHinges(chain, ConstrainedModel::unstack(to));
  Eigen::VectorXd w = b - a.dot(b) * a;
  if (w.norm() < 1e-9) {  // antipodal or equal: any perpendicular direction
    w = Eigen::VectorXd::Unit(a.size(), 0) - a(0) * a;
    if (w.norm() < 1e-3) w = Eigen::VectorXd::Unit(a.size(), 1) - a(1) * a;
  }
  w.normalize();
  const double angle = std::atan2(b.dot(w), a.dot(b));  // in [0, pi]
  for (double total : {angle, angle - 2 * std::numbers::pi}) {
    std::vector<Eigen::VectorXd> path;
    for (int i = 0; i <= intervals; ++i) {
      const double s = total * i / intervals;
      path.push_back(i == 0 ? from
                     : i == intervals
                         ? to
                         : ConstrainedModel::stack(hingePositionsAt(chain, std::cos(s) * a + std::sin(s) * w)));
    }
    out.push_back(path);
  }
  return out;
}

int morseIndexOnChain(const Chain& chain, const Eigen::VectorXd& from, const Eigen::VectorXd& velocity) {
  if (chain.rods < 4) return 0;  // a circle has no conjugate points
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  const double length = model.norm(velocity);
  if (chain.isSlack()) return -1;  // the Jacobi fields start from a point of the configuration sphere
  const Eigen::VectorXd x = spherePointFromHinges(chain, ConstrainedModel::unstack(from));
  const InitialState start(x,
                           sphereVelocityFromHingeVelocities(chain, x, ConstrainedModel::unstack(velocity / length)));
  RunConfig config;
  config.jacobi = true;
  Trajectory run(chain, start, config);
  run.sampleAt(length);
  int count = 0;
  for (double t : run.conjugateTimes())
    if (t < length * (1 - 1e-9)) ++count;
  return count;
}

int discreteMorseIndex(const ConstrainedModel& model, const Eigen::VectorXd& from, const Eigen::VectorXd& velocity,
                       int intervals) {
  std::vector<Eigen::VectorXd> nodes = shootingPath(model, from, velocity, intervals);
  if (!solveDiscrete(model, nodes)) return -1;
  // The second variation of the discrete energy sum |q_(i+1) - q_i|_M^2 / 2 - sum mu_i . c(q_i) on the
  // tangent spaces of the interior nodes: diagonal blocks Z_i^T (2M - sum_k mu_ik A_k) Z_i, off-diagonal
  // -Z_i^T M Z_(i+1). Its negative eigenvalues, counted by the block LDL^T (Sylvester's law of inertia), are
  // the Morse index of the broken geodesic, which is the geodesic's for short enough segments.
  const int count = static_cast<int>(nodes.size());
  const Eigen::SparseMatrix<double>& mass = model.sparseMass();
  int index = 0;
  Eigen::MatrixXd schur, previousBasis;
  for (int i = 1; i + 1 < count; ++i) {
    const Eigen::VectorXd& q = nodes[static_cast<std::size_t>(i)];
    const Eigen::VectorXd mu =
        nodeMultipliers(model, nodes[static_cast<std::size_t>(i - 1)], q, nodes[static_cast<std::size_t>(i + 1)]);
    const Eigen::MatrixXd basis = model.tangentBasis(q);
    const Eigen::MatrixXd hz = 2.0 * (mass * basis) - [&] {
      Eigen::MatrixXd out(basis.rows(), basis.cols());
      for (Eigen::Index c = 0; c < basis.cols(); ++c) out.col(c) = model.hessianCombination(mu, basis.col(c));
      return out;
    }();
    Eigen::MatrixXd block = basis.transpose() * hz;
    if (i > 1) {
      const Eigen::MatrixXd coupling = -(previousBasis.transpose() * (mass * basis));
      block -= coupling.transpose() * schur.ldlt().solve(coupling);
    }
    schur = 0.5 * (block + block.transpose());
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(schur, Eigen::EigenvaluesOnly);
    for (Eigen::Index k = 0; k < eigen.eigenvalues().size(); ++k)
      if (eigen.eigenvalues()(k) < 0) ++index;
    previousBasis = basis;
  }
  return index;
}

namespace {

// When the continuation fails: shot from the arc's first chord; on long chains, where the arc's branch of
// shots can fold before the target (docs/geometry.md, "Long chains"), from route 2's geodesic found by descent
// from the arc.
std::optional<Connection> fromTheArc(const ConstrainedModel& model, const Chain& chain, const Eigen::VectorXd& from,
                                     const Eigen::VectorXd& to, const std::vector<Eigen::VectorXd>& arc,
                                     double tolerance) {
  const int intervals = static_cast<int>(arc.size()) - 1;
  auto c = shootConnection(model, from, to, (arc[1] - arc[0]) * intervals, tolerance);
  if (c || static_cast<int>(model.tangentBasis(from).cols()) <= kExactShootingFreedom) return c;
  // The first chord over its time step, projected onto the tangent space, is the initial velocity to O(h^2)
  // (the geodesic's acceleration is normal to it); two node counts extrapolate it to O(h^4). No refinement to
  // route 2's accuracy: Newton's shots finish the job.
  std::vector<Eigen::VectorXd> nodes = sphereArcPaths(chain, from, to, 5 * kPathSamples)[0];
  for (std::size_t i = 1; i + 1 < nodes.size(); ++i) model.projectPosition(nodes[i]);
  if (!descendDiscrete(model, nodes) || !solveDiscrete(model, nodes)) return std::nullopt;
  const auto chord = [&] {
    const double k = static_cast<double>(nodes.size() - 1);
    return model.projectVelocity(from, (nodes[1] - nodes[0]) * k);
  };
  const Eigen::VectorXd coarse = chord();
  if ((c = shootConnection(model, from, to, coarse, tolerance))) return c;
  nodes = refine(model, nodes);
  if (!solveDiscrete(model, nodes)) return std::nullopt;
  return shootConnection(model, from, to, (4 * chord() - coarse) / 3, tolerance);
}

}  // namespace

std::optional<Connection> directConnection(const ConstrainedModel& model, const Chain* chain,
                                           const Eigen::VectorXd& from, const Eigen::VectorXd& to, double tolerance) {
  if (chain == nullptr || chain->isSlack()) return shootConnection(model, from, to, to - from, tolerance);
  // Continuation along the great-circle arc: shoot at the arc's points one stage further each time, from
  // the previous stage's velocity stretched to the longer arc, so Newton always starts close.
  const int intervals = 64, stages = 4;
  const auto arc = sphereArcPaths(*chain, from, to, intervals)[0];
  Eigen::VectorXd velocity = (arc[1] - arc[0]) * intervals / stages;
  std::optional<Connection> c;
  for (int stage = 1; stage <= stages; ++stage) {
    c = shootConnection(model, from, arc[static_cast<std::size_t>(stage * intervals / stages)], velocity, tolerance);
    if (!c) return fromTheArc(model, *chain, from, to, arc, tolerance);
    velocity = c->velocity * (stage + 1.0) / stage;
  }
  return c;
}

bool sameShape(const ConstrainedModel& model, const Eigen::VectorXd& from, const Eigen::VectorXd& to) {
  return model.norm(from - to) < kSameShapeDistance;
}

std::vector<Connection> findConnections(const ConstrainedModel& model, const Chain* chain, const Eigen::VectorXd& from,
                                        const Eigen::VectorXd& to, const ConnectOptions& options) {
  std::vector<Connection> found;
  auto add = [&](std::optional<Connection> c) {
    // The motion of no length (staying put) is no motion: its direction would be rounding noise.
    if (!c || c->length < kSameShapeDistance) return;
    for (const Connection& known : found)
      if (model.norm(known.velocity - c->velocity) < 1e-6 * std::max(1.0, c->length)) return;
    found.push_back(*c);
  };
  add(directConnection(model, chain, from, to, options.tolerance));
  double maxLength = options.maxLength;
  if (maxLength <= 0) maxLength = found.empty() ? 10.0 : 2.5 * found[0].length;

  // The fan: unit-speed geodesics from the start, their closest approaches to the target as seeds.
  const Eigen::MatrixXd basis = model.tangentBasis(from);
  const int d = static_cast<int>(basis.cols());
  std::vector<Eigen::VectorXd> directions;
  if (d == 1) {
    directions = {basis.col(0), -basis.col(0)};
  } else if (d == 2) {
    for (int k = 0; k < options.directions; ++k) {
      const double a = 2 * std::numbers::pi * (k + 0.5) / options.directions;
      directions.push_back(std::cos(a) * basis.col(0) + std::sin(a) * basis.col(1));
    }
  } else {
    for (int i = 0; i < d; ++i) {
      directions.push_back(basis.col(i));
      directions.push_back(-basis.col(i));
      for (int j = i + 1; j < std::min(d, 4); ++j)  // diagonals among the first four only: O(d) rays
        for (double s : {1.0, -1.0}) {
          directions.push_back((basis.col(i) + s * basis.col(j)) / std::sqrt(2.0));
          directions.push_back(-(basis.col(i) + s * basis.col(j)) / std::sqrt(2.0));
        }
    }
  }
  struct Seed {
    double distance;
    Eigen::VectorXd velocity;
  };
  std::vector<Seed> seeds;
  const GeodesicFlow flow(model, 1e-9);
  const int n = model.dimension();
  const std::size_t shots = d > kExactShootingFreedom ? kLongChainSeeds : 60;
  const auto tell = [&](std::size_t done, std::size_t total) {
    if (options.progress) options.progress(static_cast<long>(done), static_cast<long>(total));
  };
  std::size_t raysDone = 0;
  for (const Eigen::VectorXd& u : directions) {
    tell(raysDone++, directions.size() + shots);
    stopIfCancelled(options.cancelled);
    FlowState state{from, u, Eigen::MatrixXd(n, 0), Eigen::MatrixXd(n, 0)};
    double d2 = INFINITY, d1 = INFINITY, t1 = 0;
    try {
      flow.advance(state, maxLength * 1.05, [&](double t, const FlowState& s) {
        if (options.cancelled && options.cancelled()) return false;  // a long ray answers within a step
        const double d0 = model.norm(s.q - to);
        if (d1 < d2 && d1 <= d0 && d1 < 0.6 && t1 > 0) seeds.push_back({d1, t1 * u});
        d2 = d1;
        d1 = d0;
        t1 = t;
        return true;
      });
    } catch (const std::runtime_error&) {
    }
  }
  std::sort(seeds.begin(), seeds.end(), [](const Seed& a, const Seed& b) { return a.distance < b.distance; });
  // Each seed costs a shot with the derivative; in high dimension the fan's close approaches mostly lead
  // back to the same few geodesics, so only the closest are shot (docs/geometry.md, "Long chains").
  if (seeds.size() > shots) seeds.resize(shots);
  std::size_t shotsDone = 0;
  for (const Seed& seed : seeds) {
    tell(directions.size() + shotsDone++, directions.size() + seeds.size());
    stopIfCancelled(options.cancelled);
    add(shootConnection(model, from, to, seed.velocity, options.tolerance));
  }
  found.erase(std::remove_if(found.begin(), found.end(),
                             [&](const Connection& c) { return c.length > maxLength * (1 + 1e-12); }),
              found.end());
  const auto shorter = [](const Connection& a, const Connection& b) { return a.length < b.length; };
  std::sort(found.begin(), found.end(), shorter);

  // A motion route 1 found: its path and its Morse index.
  const auto describe = [&](Connection& c) {
    c.path = shootingPath(model, from, c.velocity, kPathSamples, options.tolerance);
    // The Jacobi fields' Gram determinant of n - 3 fields loses its zeros among the products of many small
    // factors on long chains; there the discrete action's second variation counts them.
    if (chain != nullptr)
      c.morseIndex = d > kExactShootingFreedom ? discreteMorseIndex(model, from, c.velocity)
                                               : morseIndexOnChain(*chain, from, c.velocity);
  };
  tell(directions.size() + seeds.size(), directions.size() + seeds.size());
  for (Connection& c : found) {
    stopIfCancelled(options.cancelled);
    describe(c);
  }
  if (!options.discreteRoute) return found;

  // Route 2: first from seeds that know nothing of route 1, then from route 1's paths for the rest.
  auto match = [&](const DiscreteGeodesic& g) -> Connection* {
    for (Connection& c : found)
      if (std::abs(c.length - g.length) < 1e-6 && pathDistance(c.path, g.path) < 1e-5) return &c;
    return nullptr;
  };
  auto record = [&](Connection* c, const DiscreteGeodesic& g) {
    if (c == nullptr || c->discrete) return;
    c->discrete = g;
    c->lengthDifference = std::abs(c->length - g.length);
    c->pathDifference = pathDistance(c->path, g.path);
  };
  if (chain != nullptr) {
    const auto arcs = sphereArcPaths(*chain, from, to, 5 * kPathSamples);
    for (std::size_t k = 0; k < arcs.size(); ++k) {
      const auto g = discreteGeodesic(model, arcs[k], k == 0 ? DiscreteSeed::SphereArc : DiscreteSeed::SphereArcLongWay,
                                      d > kExactShootingFreedom);
      if (!g) continue;
      Connection* c = match(*g);
      // Long chains shoot few of the fan's seeds and may miss a geodesic route 2 found from the arc: shot
      // from the discrete path's first chord (projected onto the tangent space, O(h^2) from the geodesic's
      // velocity), it is found by route 1 too and then checked like the others.
      if (c == nullptr && d > kExactShootingFreedom && g->length <= maxLength * (1 + 1e-12)) {
        const std::size_t before = found.size();
        add(shootConnection(model, from, to, g->startVelocity, options.tolerance));
        if (found.size() > before) describe(found.back());
        std::sort(found.begin(), found.end(), shorter);
        c = match(*g);
      }
      record(c, *g);
    }
  }
  for (Connection& c : found) {
    if (c.discrete) continue;
    const int intervals = kPathSamples * std::max(5, static_cast<int>(std::ceil(2 * c.length)));
    const auto g = discreteGeodesic(model, shootingPath(model, from, c.velocity, intervals, options.tolerance),
                                    DiscreteSeed::ShootingPath);
    if (g && match(*g) == &c) record(&c, *g);
  }
  return found;
}

}  // namespace sl
