#include "inverse/method_shooting.hpp"

#include <algorithm>
#include <cmath>

#include "inverse/constrained_model.hpp"
#include "linkage/chart.hpp"
#include "simulation/ambient_system.hpp"
#include "simulation/chart_system.hpp"
#include "simulation/initial_state.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

namespace {

// An orthonormal basis of the tangent space of the unit sphere at x: (n-1) x (n-2).
Eigen::MatrixXd tangentBasisAt(const Eigen::VectorXd& x) {
  const Eigen::Index m = x.size();
  Eigen::MatrixXd frame(m, m);
  frame.col(0) = x;
  frame.rightCols(m - 1) = Eigen::MatrixXd::Identity(m, m - 1);
  // Start from the axes x is least along, so the frame stays well conditioned.
  Eigen::Index largest = 0;
  x.cwiseAbs().maxCoeff(&largest);
  for (Eigen::Index k = 1, axis = 0; k < m; ++k, ++axis) {
    if (axis == largest) ++axis;
    frame.col(k) = Eigen::VectorXd::Unit(m, axis);
  }
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(frame);
  const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(m, m);
  return q.rightCols(m - 1);
}

struct EndPoint {
  Eigen::VectorXd x;
  Eigen::Matrix2Xd hinges;
};

std::optional<EndPoint> endOf(const Chain& chain, const RunConfig& config, const Eigen::VectorXd& x0,
                              const Eigen::VectorXd& xdot) {
  Trajectory run(chain, InitialState(x0, xdot), config);
  const auto end = run.sampleAt(1.0);
  if (!end || run.stop()) return std::nullopt;
  return EndPoint{end->spherePoint, end->hinges};
}

}  // namespace

std::optional<MethodConnection> shootWithMethod(const Chain& chain, Method method, const Eigen::VectorXd& from,
                                                const Eigen::VectorXd& to, const Eigen::VectorXd& hingeVelocity,
                                                double tolerance, bool (*cancelled)()) {
  requireMethodMoves({method, &chain, false, false});
  RunConfig config;
  config.method = method;
  config.integrator = Integrator::Rkf78;
  config.tolerance = traits(method).published ? std::max(tolerance, kPublishedMethodToleranceFloor) : tolerance;
  const Eigen::Matrix2Xd target = ConstrainedModel::unstack(to);
  const Eigen::VectorXd x0 = spherePointFromHinges(chain, ConstrainedModel::unstack(from));
  const Eigen::VectorXd xT = spherePointFromHinges(chain, target);
  const Eigen::MatrixXd startBasis = tangentBasisAt(x0), endBasis = tangentBasisAt(xT);
  Eigen::VectorXd xdot = sphereVelocityFromHingeVelocities(chain, x0, ConstrainedModel::unstack(hingeVelocity));
  xdot -= xdot.dot(x0) * x0;

  double previous = INFINITY;
  int stalled = 0;  // iterations in a row that did not halve the error
  for (int iteration = 1; iteration <= 30; ++iteration) {
    stopIfCancelled(cancelled);
    const auto end = endOf(chain, config, x0, xdot);
    if (!end) return std::nullopt;
    const double error = (end->hinges - target).cwiseAbs().maxCoeff();
    stalled = error >= previous * 0.5 ? stalled + 1 : 0;
    const bool atFloor = stalled >= 2 && error <= kMethodShotEndBound;
    if (error <= 1e-13 || (error <= 1e-12 && error >= previous * 0.5) || atFloor) {
      MethodConnection out;
      out.method = method;
      out.velocity = xdot;
      out.length = std::sqrt(speedSquared(chain, InitialState(x0, xdot)));
      out.endError = error;
      out.newtonIterations = iteration;
      return out;
    }
    if (stalled >= 2) return std::nullopt;  // stalled above the bound: it will not get there
    previous = error;
    // The end point's derivative along each tangent direction of the start velocity, by central differences
    // (step relative to the speed: the flow is smooth in xdot, so the O(h^2) error is far below the residual
    // Newton must remove, and the last steps converge linearly at worst).
    const Eigen::Index k = startBasis.cols();
    const double h = 1e-6 * std::max(1.0, xdot.norm());
    Eigen::MatrixXd jacobian(k, k);
    for (Eigen::Index c = 0; c < k; ++c) {
      stopIfCancelled(cancelled);
      const auto plus = endOf(chain, config, x0, xdot + h * startBasis.col(c));
      const auto minus = endOf(chain, config, x0, xdot - h * startBasis.col(c));
      if (!plus || !minus) return std::nullopt;
      jacobian.col(c) = endBasis.transpose() * (plus->x - minus->x) / (2 * h);
    }
    const Eigen::VectorXd residual = endBasis.transpose() * (end->x - xT);
    const Eigen::VectorXd step = jacobian.fullPivLu().solve(-residual);
    if (!step.allFinite()) return std::nullopt;
    xdot += startBasis * step;
  }
  return std::nullopt;
}

}  // namespace sl
