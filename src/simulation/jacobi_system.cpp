#include "simulation/jacobi_system.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "linkage/chain_constants.hpp"
#include "linkage/chart.hpp"
#include "linkage/kinetic_metric.hpp"
#include "simulation/family.hpp"
#include "simulation/initial_state.hpp"

namespace sl {

namespace {

using Hinges = Eigen::Map<Eigen::Matrix2Xd>;
using ConstHinges = Eigen::Map<const Eigen::Matrix2Xd>;

// Rod-wise differences of hinge displacements (the pins do not move): dD_k for dq, dV_k for dv.
Eigen::Matrix2Xd differences(const Eigen::Matrix2Xd& perHinge) {
  Eigen::Matrix2Xd out;
  ConstraintSolver::relativeVelocities(perHinge, out);
  return out;
}

// Column-wise dot products: one number per rod.
Eigen::VectorXd rodDots(const Eigen::Matrix2Xd& a, const Eigen::Matrix2Xd& b) {
  return a.cwiseProduct(b).colwise().sum().transpose();
}


// det and adjugate (transposed cofactors) of a small symmetric matrix: adj(G) stays finite where G is singular,
// so d/dt det G = tr(adj(G) G') is smooth through conjugate points.
double determinant(const Eigen::MatrixXd& a) { return a.size() == 0 ? 1.0 : a.determinant(); }
Eigen::MatrixXd adjugate(const Eigen::MatrixXd& a) {
  const Eigen::Index m = a.rows();
  Eigen::MatrixXd adj(m, m);
  if (m == 1) {
    adj(0, 0) = 1.0;
    return adj;
  }
  Eigen::MatrixXd minor(m - 1, m - 1);
  for (Eigen::Index i = 0; i < m; ++i)
    for (Eigen::Index j = 0; j < m; ++j) {
      for (Eigen::Index r = 0, rr = 0; r < m; ++r) {
        if (r == i) continue;
        for (Eigen::Index c = 0, cc = 0; c < m; ++c) {
          if (c == j) continue;
          minor(rr, cc++) = a(r, c);
        }
        ++rr;
      }
      adj(j, i) = ((i + j) % 2 ? -1.0 : 1.0) * determinant(minor);
    }
  return adj;
}

// d/dt det G = tr(adj(G) G'), finite and smooth where G is singular (at conjugate points). Up to three fields
// adj(G) by its cofactors; beyond, from G's eigen decomposition G = Q diag(l) Q^T: adj(G) = Q diag(a) Q^T with
// a_i the product of the other eigenvalues (prefix and suffix products: no division), so the rate is
// sum_i a_i (Q^T G' Q)_ii in O(m^3) where the cofactors take O(m^5).
double determinantRate(const Eigen::MatrixXd& gram, const Eigen::MatrixXd& rate) {
  const Eigen::Index m = gram.rows();
  if (m <= 3) return (adjugate(gram) * rate).trace();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram);
  const Eigen::VectorXd& values = eigen.eigenvalues();
  const Eigen::MatrixXd& vectors = eigen.eigenvectors();
  Eigen::VectorXd others(m);
  double product = 1.0;
  for (Eigen::Index i = 0; i < m; ++i) {
    others(i) = product;
    product *= values(i);
  }
  product = 1.0;
  for (Eigen::Index i = m - 1; i >= 0; --i) {
    others(i) *= product;
    product *= values(i);
  }
  const Eigen::MatrixXd rotated = rate * vectors;
  double sum = 0.0;
  for (Eigen::Index i = 0; i < m; ++i) sum += others(i) * vectors.col(i).dot(rotated.col(i));
  return sum;
}

}  // namespace

bool isConjugateMinimum(double smallestEigenvalueAtMinimum, double largestMean) {
  return smallestEigenvalueAtMinimum <= 1e-12 * largestMean;
}

double gramDeterminantRate(const Eigen::MatrixXd& gram, const Eigen::MatrixXd& rate) {
  return determinantRate(gram, rate);
}

JacobiSystem::JacobiSystem(const Chain& chain, const InitialState& start, double projectBeyond)
    : motion_(chain, start, projectBeyond),
      chain_(chain),
      mass_(ambientMassMatrix(chain)),
      hinges_(chain.hingeCount()),
      fields_(chain.rods - 3),
      solver_(chain) {
  if (fields_ < 1) throw std::invalid_argument("Jacobi fields need at least 4 rods (a direction across the motion)");
  if (!mass_.isDiagonal) massFactor_.compute(stackedMassMatrix(chain));
  start_ = motion_.initialState();
  const std::size_t block = static_cast<std::size_t>(4 * hinges_);
  start_.resize(block * static_cast<std::size_t>(fields_ + 1), 0.0);
  // J_i(0) = 0, J_i'(0) = dPsi(e_i): e_i g-orthonormal and g-orthogonal to the velocity.
  const std::vector<Eigen::VectorXd> frame = orthonormalTangentFrame(chain, start.spherePoint, start.sphereVelocity);
  if (static_cast<int>(frame.size()) != fields_ + 1)
    throw std::invalid_argument("the start's tangent space is degenerate (a chart-free frame was not found)");
  // dPsi of each frame vector: from the whole Jacobian on short chains, one forward-AD pass each on long ones.
  const Eigen::MatrixXd jacobian =
      chain.rods <= kWholeJacobianRods ? sphereJacobian(chain, start.spherePoint) : Eigen::MatrixXd();
  const ConstHinges q(start_.data(), 2, hinges_);
  Eigen::Matrix2Xd rods, correction;
  solver_.rodVectors(q, rods);
  for (int i = 0; i < fields_; ++i) {
    Hinges dv(start_.data() + block * static_cast<std::size_t>(i + 1) + 2 * hinges_, 2, hinges_);
    const Eigen::VectorXd& e = frame[static_cast<std::size_t>(i + 1)];
    if (jacobian.size() > 0) {
      const Eigen::VectorXd stacked = jacobian * e;
      dv = ConstHinges(stacked.data(), 2, hinges_);
    } else {
      dv = hingeVelocitiesOnSphere(chain, start.spherePoint, e);
    }
    // Onto the projected motion's tangent space (G dv = 0), as the motion's own velocity was.
    solver_.solve(q, -rodDots(rods, differences(dv)), correction);
    dv += correction;
  }
}

void JacobiSystem::inverseMassTimes(const Eigen::Matrix2Xd& f, Eigen::Matrix2Xd& out) const {
  if (mass_.isDiagonal) {
    out = f * mass_.diagonal.cwiseInverse().asDiagonal();
    return;
  }
  const Eigen::VectorXd x = massFactor_.solve(Eigen::Map<const Eigen::VectorXd>(f.data(), f.size()));
  out = Eigen::Map<const Eigen::Matrix2Xd>(x.data(), 2, f.cols());
}

void JacobiSystem::derivative(const State& y, State& dydt) const {
  const Eigen::Index h = hinges_, n = h + 1;
  const std::size_t block = static_cast<std::size_t>(4 * h);
  dydt.resize(y.size());
  // Copied into work space sized once (the solver takes matrices: a map would be copied into a new one).
  hingePositions_ = ConstHinges(y.data(), 2, h);
  const ConstHinges v(y.data() + 2 * h, 2, h);
  // The motion, as AmbientSystem::derivative computes it (the same solve, so the same numbers).
  ConstraintSolver::relativeVelocities(v, relative_);
  rhs_ = -relative_.colwise().squaredNorm().transpose();
  solver_.solve(hingePositions_, rhs_, acceleration_);
  mu_ = solver_.multipliers();
  const Eigen::Matrix2Xd& rods = solver_.rodVectorsOfLastSolve();
  Hinges(dydt.data(), 2, h) = v;
  Hinges(dydt.data() + 2 * h, 2, h) = acceleration_;
  ConstraintSolver::relativeVelocities(acceleration_, relativeAcceleration_);
  force_.resize(2, h);
  for (int i = 0; i < fields_; ++i) {
    const std::size_t offset = block * static_cast<std::size_t>(i + 1);
    fieldQ_ = ConstHinges(y.data() + offset, 2, h);
    fieldV_ = ConstHinges(y.data() + offset + 2 * h, 2, h);
    ConstraintSolver::relativeVelocities(fieldQ_, dRods_);
    ConstraintSolver::relativeVelocities(fieldV_, dRelative_);
    for (Eigen::Index p = 1; p <= h; ++p)  // dG^T mu at hinge p
      force_.col(p - 1) = dRods_.col(p - 1) * mu_(p - 1) - dRods_.col(p) * mu_(p);
    inverseMassTimes(force_, first_);  // M^-1 dG^T mu
    ConstraintSolver::relativeVelocities(first_, relativeFirst_);
    for (Eigen::Index k = 0; k < n; ++k)
      rhs_(k) = -2.0 * relative_.col(k).dot(dRelative_.col(k)) - dRods_.col(k).dot(relativeAcceleration_.col(k)) -
                rods.col(k).dot(relativeFirst_.col(k));
    solver_.solveAgain(rhs_, correction_);  // the same hinges: the motion's factorisation
    Hinges(dydt.data() + offset, 2, h) = fieldV_;
    Hinges(dydt.data() + offset + 2 * h, 2, h) = first_ + correction_;
  }
}

bool JacobiSystem::settleBetweenSteps(State& y) {
  if (!motion_.settleBetweenSteps(y)) return false;
  // The motion was projected back onto the constraints: bring each field back to the linearised constraints
  // there (G dq = 0, G dv + dG v = 0), M-orthogonally, as the motion's velocity was.
  const Eigen::Index h = hinges_;
  const std::size_t block = static_cast<std::size_t>(4 * h);
  const ConstHinges q(y.data(), 2, h), v(y.data() + 2 * h, 2, h);
  Eigen::Matrix2Xd rods, correction;
  solver_.rodVectors(q, rods);
  const Eigen::Matrix2Xd relative = differences(v);
  for (int i = 0; i < fields_; ++i) {
    const std::size_t offset = block * static_cast<std::size_t>(i + 1);
    Hinges dq(y.data() + offset, 2, h), dv(y.data() + offset + 2 * h, 2, h);
    solver_.solve(q, -rodDots(rods, differences(dq)), correction);
    dq += correction;
    solver_.solve(q, -rodDots(rods, differences(dv)) - rodDots(differences(dq), relative), correction);
    dv += correction;
  }
  return true;
}

void JacobiSystem::gramAt(const State& y, Eigen::MatrixXd& gram, Eigen::MatrixXd* rate) const {
  const Eigen::Index h = hinges_;
  const std::size_t block = static_cast<std::size_t>(4 * h);
  const ConstHinges v(y.data() + 2 * h, 2, h);
  const double vv = mass_.innerProduct(v, v);
  std::vector<Eigen::Matrix2Xd> fields, rates;
  for (int i = 0; i < fields_; ++i) {
    const std::size_t offset = block * static_cast<std::size_t>(i + 1);
    const Eigen::Matrix2Xd dq = ConstHinges(y.data() + offset, 2, h);
    fields.push_back(dq - (mass_.innerProduct(dq, v) / vv) * v);  // the part across the motion
    rates.push_back(ConstHinges(y.data() + offset + 2 * h, 2, h));
  }
  gram.resize(fields_, fields_);
  if (rate) rate->resize(fields_, fields_);
  for (int i = 0; i < fields_; ++i)
    for (int j = 0; j < fields_; ++j) {
      const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
      gram(i, j) = mass_.innerProduct(fields[ui], fields[uj]);
      // <J_i, J_j>' = <dv_i, J_j> + <J_i, dv_j>: dv's normal part is M-orthogonal to the tangent J's.
      if (rate)
        (*rate)(i, j) = mass_.innerProduct(rates[ui], fields[uj]) + mass_.innerProduct(fields[ui], rates[uj]);
    }
}

JacobiState JacobiSystem::jacobiAt(const State& y) const {
  Eigen::MatrixXd gram, rate;
  gramAt(y, gram, &rate);
  JacobiState out;
  out.gramDeterminant = determinant(gram);
  out.gramRate = determinantRate(gram, rate);
  out.gramMean = gram.trace() / fields_;
  out.size = std::pow(std::max(out.gramDeterminant, 0.0), 0.5 / fields_);
  return out;
}

double JacobiSystem::smallestGramEigenvalue(const State& y) const {
  Eigen::MatrixXd gram;
  gramAt(y, gram);
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(gram, Eigen::EigenvaluesOnly).eigenvalues()(0);
}

}  // namespace sl
