#pragma once
// Geodesics of a ConstrainedModel and their linearisation, chart-free (the constrained system of spec
// section 1 for any quadratic constraints): M a = -G^T mu with G a = -(v^T A_i v)_i, and for a variation
// (dq, dv) of the state, differentiating both equations exactly,
//   M da + G^T dmu = -sum_i mu_i A_i dq,   G da = -2 (v^T A_i dv)_i - (dq^T A_i a)_i,
// the same KKT matrix with other right-hand sides. A variation with dq(0) = 0 is a Jacobi field through the
// start; the columns carried together give the derivative of the end state with respect to the start (the
// shooting derivative, and over one period the monodromy). Integrated by Runge-Kutta-Fehlberg 7(8)
// (Boost.Odeint), the state projected back onto the constraints (positions, velocities, variations)
// between steps once they drift.
// Vectors W parallel transported along the geodesic ride along too (inverse/parallel_transport.hpp): W stays tangent,
// G W = 0, and its derivative is normal (M-orthogonal to the tangent space), so M W' + G^T nu = 0 with
// G W' = -(v^T A_i W)_i: once more the same KKT matrix.
#include <functional>

#include <Eigen/Dense>

#include "inverse/constrained_model.hpp"

namespace sl {

struct FlowState {
  Eigen::VectorXd q, v;
  Eigen::MatrixXd dq, dv;  // variations, one column each (may have no columns)
  Eigen::MatrixXd transported = {};  // parallel transported vectors, one column each (usually none)
};

class GeodesicFlow {
 public:
  explicit GeodesicFlow(const ConstrainedModel& model, double tolerance = 1e-12);

  // Advances `state` by `duration` (>= 0). The observer, if given, sees (time, state) after every step
  // (and at time 0) and may return false to stop early; the return value says whether the whole
  // duration was integrated. Throws std::runtime_error if the step size collapses.
  bool advance(FlowState& state, double duration,
               const std::function<bool(double, const FlowState&)>& observer = {}) const;

  // The geodesic acceleration at (q, v) and its multipliers.
  Eigen::VectorXd acceleration(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const;

  const ConstrainedModel& model() const { return model_; }
  long evaluations() const { return evaluations_; }

  // The derivative of the packed state y = (q, v, dq columns, dv columns, transported columns).
  void derivative(const std::vector<double>& y, std::vector<double>& dydt, int columns, int transported = 0) const;

 private:
  const ConstrainedModel& model_;
  double tolerance_;
  mutable long evaluations_ = 0;
};

}  // namespace sl
