#pragma once
// The linear algebra of the rod constraints, in O(n) (spec section 1's mass matrix M, block-tridiagonal).
// Rod k joins p_(k-1) and p_k (p_0 = 0 and p_n = (L, 0) pinned); its constraint is
// c_k = (|p_k - p_(k-1)|^2 - 1) / 2 with gradient row G_k. For a right-hand side r (one entry per rod),
// solve() returns the M-orthogonal correction x = M^-1 G^T mu with (G M^-1 G^T) mu = r, so that G x = r.
// It serves the index-1 accelerations (r = -|relative velocity|^2) and both projections.
//   Massless rods: M is diagonal, G M^-1 G^T is tridiagonal SPD -> Thomas algorithm, no pivoting needed.
//   Rod masses: M^-1 is dense, so the banded KKT system [M G^T; G 0] is solved instead, unknowns
//   interleaved per hinge (bandwidth 3), by Eigen's SparseLU (pattern analysed once).

#include <memory>
#include <stdexcept>

#include <Eigen/Dense>

#include "linkage/chain.hpp"

namespace sl {

// The rod constraints lost rank: every rod on one line (a chain folded flat or stretched straight), where
// G M^-1 G^T is singular and no acceleration is determined. A run stops there (StopReason::ConstraintRankLoss).
struct ConstraintRankLoss : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The hinges or the right-hand side of a solve are not finite (a step that overflowed): not a loss of rank, which
// would name a chain folded flat that is nowhere near a line. A run stops there (StopReason::NonFinite).
struct NonFiniteConstraintData : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class ConstraintSolver {
 public:
  explicit ConstraintSolver(const Chain& chain);
  ~ConstraintSolver();
  ConstraintSolver(ConstraintSolver&&) noexcept;

  // hinges: 2 x (n-1); rhs: n entries; correction: 2 x (n-1). Throws ConstraintRankLoss if the system is
  // singular to working precision (every rod on one line), NonFiniteConstraintData if an input is not finite.
  void solve(const Eigen::Matrix2Xd& hinges, const Eigen::VectorXd& rhs, Eigen::Matrix2Xd& correction);
  // The multipliers mu of the last solve (one per rod): correction = M^-1 G^T mu, where (G^T mu) at hinge p_h is
  // D_(h-1) mu_(h-1) - D_h mu_h. The Jacobi fields' linearisation needs them (simulation/jacobi_system.hpp).
  const Eigen::VectorXd& multipliers() const { return mu_; }
  // solve() for another right-hand side at the hinges of the last solve(): its factorisation is reused, and the
  // numbers are those solve() would give. The rod vectors D_k of those hinges (2 x n) as solve() computed them.
  void solveAgain(const Eigen::VectorXd& rhs, Eigen::Matrix2Xd& correction);
  const Eigen::Matrix2Xd& rodVectorsOfLastSolve() const { return rods_; }

  // Rod vectors D_k = p_k - p_(k-1), k = 1..n, pins included: 2 x n.
  void rodVectors(const Eigen::Matrix2Xd& hinges, Eigen::Matrix2Xd& rods) const;
  // The same differences for hinge velocities (the pins do not move).
  static void relativeVelocities(const Eigen::Matrix2Xd& velocities, Eigen::Matrix2Xd& relative);

 private:
  void factorTridiagonal();
  void substituteTridiagonal(const Eigen::VectorXd& rhs, Eigen::Matrix2Xd& correction);
  void factorKkt();
  void substituteKkt(const Eigen::VectorXd& rhs, Eigen::Matrix2Xd& correction);

  double baseLength_;
  Eigen::VectorXd inverseMass_;  // w_h for p_0..p_n: 0 at the pins
  bool diagonalMass_;
  Eigen::Matrix2Xd rods_;
  Eigen::VectorXd lower_, diagonal_, upper_, pivots_, mu_;  // Thomas work space
  struct Kkt;
  std::unique_ptr<Kkt> kkt_;
};

}  // namespace sl
