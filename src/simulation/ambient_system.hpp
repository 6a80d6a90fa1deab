#pragma once
// The chart-free method: the chain as a constrained mechanical system in (R^2)^(n-1), any n, any masses
// (spec section 1). Index-1 form: M q'' = G^T lambda with (G M^-1 G^T) lambda fixed by c'' = 0, i.e.
// G q'' = -|p_k' - p_(k-1)'|^2 per rod. O(n) per evaluation (ConstraintSolver). Between steps, when the rod
// lengths have drifted past projectBeyond, positions are projected back (Newton, M-orthogonal) and then
// velocities onto the tangent space. No chart: it passes straight through the poles.

#include "contracts/run_config.hpp"
#include "linkage/chain.hpp"
#include "simulation/constraint_solver.hpp"
#include "simulation/geodesic_system.hpp"

namespace sl {

class AmbientSystem : public GeodesicSystem {
 public:
  AmbientSystem(const Chain& chain, const InitialState& start, double projectBeyond);

  State initialState() const override { return start_; }
  void derivative(const State& y, State& dydt) const override;
  bool settleBetweenSteps(State& y) override;
  PhysicalState physicalState(const State& y) const override;
  StepInvariants stepInvariants(const State& y, double previousT) const override;
  std::string describe(const State& y) const override;

  long projections() const { return projections_; }

 private:
  void projectPositions(Eigen::Map<Eigen::Matrix2Xd> q);
  void projectVelocities(const Eigen::Matrix2Xd& q, Eigen::Map<Eigen::Matrix2Xd> v);

  Chain chain_;
  AmbientMassMatrix mass_;
  double projectBeyond_;
  long projections_ = 0;
  State start_;
  mutable ConstraintSolver solver_;
  mutable Eigen::Matrix2Xd rods_, relative_, acceleration_;
  mutable Eigen::VectorXd rhs_;
};

// Chart 0's last coordinate t of a configuration, unwrapped near previousT, in O(1): for tracking the
// branch of t step by step (accurate to ~1e-8, not for output).
double chartZeroAngleForUnwrapping(const Chain& chain, const Eigen::Matrix2Xd& hinges, double previousT);

// Hinge velocities to the sphere velocity xdot (tangent at x) by least squares on dPsi.
Eigen::VectorXd sphereVelocityFromHingeVelocities(const Chain& chain, const Eigen::VectorXd& spherePoint,
                                                  const Eigen::Matrix2Xd& hingeVelocities);

}  // namespace sl
