#include "inverse/discrete_action.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include "inverse/connect.hpp"
#include "inverse/richardson.hpp"

namespace sl {
namespace {

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

}  // namespace

bool solveDiscrete(const ConstrainedModel& model, std::vector<Eigen::VectorXd>& nodes, bool periodic) {
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

}  // namespace sl
