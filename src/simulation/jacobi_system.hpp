#pragma once
// Jacobi fields along a geodesic of the chart-free method (spec section 1's constrained system).
// A Jacobi field is the variation of a family of geodesics: along the motion (q, v) of AmbientSystem,
// (dq, dv) solves the linearised equations dq' = dv, dv' = da with, from M a = G^T mu and G a = r(v):
//   M da = dG^T mu + G^T dmu,   G da = dr - dG a,   dr_k = -2 (V_k . dV_k)
// (D_k the rod vectors, V_k the relative velocities, dD_k and dV_k theirs for dq and dv), i.e.
//   da = M^-1 dG^T mu + x,  x = M^-1 G^T nu with G x = dr - dG a - G M^-1 dG^T mu,
// two solves of the same O(n) constraint system as the motion itself. The derivatives are exact (analytic):
// no finite difference anywhere.
//
// For n rods the orthogonal complement of the velocity in the tangent space has m = n - 3 dimensions: the
// state carries m fields J_i with J_i(0) = 0 and J_i'(0) = e_i, a g-orthonormal basis of it (for 4 rods one
// field, for 5+ a matrix Jacobi field). Their Gram matrix G_ij = <J_i, J_j> (mass inner product) measures the
// family's spread: conjugate points are the times t > 0 where it is singular.

#include <vector>

#include "contracts/run_config.hpp"
#include "linkage/chain.hpp"
#include "simulation/ambient_system.hpp"

namespace sl {

// What a Jacobi field is at one time.
struct JacobiState {
  // (det G)^(1/(2m)): |J_perp| for 4 rods (the orthogonal part of the field), the geometric mean of the
  // singular values of the matrix field for 5+; zero exactly at conjugate points.
  double size = 0;
  double gramDeterminant = 0;  // det G
  double gramRate = 0;         // d/dt det G: changes sign at each zero of det G (and at its maxima)
  double gramMean = 0;         // tr G / m, the mean eigenvalue: the fields' squared size, the scale of a zero
};

// d/dt det G = tr(adj(G) G') for a symmetric positive semi-definite G (the fields' Gram matrix) and its rate
// G': finite where G is singular. O(m^3) for m fields (exposed for tests).
double gramDeterminantRate(const Eigen::MatrixXd& gram, const Eigen::MatrixXd& rate);

// Whether a minimum of det G found between two steps is a zero of it (a conjugate point) and not a dip that stays
// away from zero: G's smallest eigenvalue there is zero to rounding, at most 1e-12 of `largestMean`, the largest
// mean eigenvalue tr G / m of the motion so far (a true zero located to ~1e-14 in time leaves far less;
// tests/simulation/jacobi_test.cpp). Eigenvalues, not det G itself: det G is a product of m eigenvalues, so with
// many fields a dip where each is a few times below its largest would fall under any fixed share of the largest
// det G. For one field (4 rods) the two tests are the same.
bool isConjugateMinimum(double smallestEigenvalueAtMinimum, double largestMean);

class JacobiSystem : public GeodesicSystem {
 public:
  // Throws std::invalid_argument for fewer than 4 rods (no direction orthogonal to the motion).
  JacobiSystem(const Chain& chain, const InitialState& start, double projectBeyond);

  State initialState() const override { return start_; }
  void derivative(const State& y, State& dydt) const override;
  bool settleBetweenSteps(State& y) override;
  PhysicalState physicalState(const State& y) const override { return motion_.physicalState(y); }
  StepInvariants stepInvariants(const State& y, double previousT) const override {
    return motion_.stepInvariants(y, previousT);
  }
  std::string describe(const State& y) const override { return motion_.describe(y); }
  // The step control watches the motion only: the fields ride along on its steps.
  std::size_t motionSize(const State&) const override { return static_cast<std::size_t>(4 * hinges_); }

  int fieldCount() const { return fields_; }
  JacobiState jacobiAt(const State& y) const;
  // The smallest eigenvalue of the fields' Gram matrix G at y (isConjugateMinimum), asked at minima of det G only.
  double smallestGramEigenvalue(const State& y) const;

 private:
  void inverseMassTimes(const Eigen::Matrix2Xd& f, Eigen::Matrix2Xd& out) const;
  // G = (<J_i, J_j>) of the fields' parts across the motion, and G' = (<J_i, J_j>)' where `rate` is given.
  void gramAt(const State& y, Eigen::MatrixXd& gram, Eigen::MatrixXd* rate = nullptr) const;

  AmbientSystem motion_;  // the geodesic: the first 4(n-1) numbers of the state
  Chain chain_;
  AmbientMassMatrix mass_;
  Eigen::LDLT<Eigen::MatrixXd> massFactor_;  // for M^-1 when the rods have mass
  int hinges_, fields_;
  State start_;
  mutable ConstraintSolver solver_;
  // Work space of derivative(): sized once, so an evaluation allocates nothing.
  mutable Eigen::Matrix2Xd hingePositions_, fieldQ_, fieldV_, relative_, acceleration_, relativeAcceleration_, dRods_, dRelative_, force_, first_,
      relativeFirst_, correction_;
  mutable Eigen::VectorXd rhs_, mu_;
};

}  // namespace sl
