#pragma once
// A third route for two-point motions: a geodesic found by findConnections (connect.hpp) shot again with one of
// the simulation's methods, the chart methods of spec sections 4 and 5 among them. The unknown is the start's
// sphere velocity xdot (tangent at x(0)); Newton on the end point x(1), projected onto the tangent space at the
// target, with the derivative by central differences of the method's own flow (the chart methods carry no
// variations). Different equations of motion (Christoffel symbols or the normal acceleration in a chart), so
// agreement with route 1 checks both.
#include <optional>

#include <Eigen/Dense>

#include "contracts/registry.hpp"
#include "linkage/chain.hpp"

namespace sl {

struct MethodConnection {
  Method method = Method::Ambient;
  double length = 0;          // sqrt(g(xdot, xdot)) of the converged start over time 1
  Eigen::VectorXd velocity;   // the converged xdot
  double endError = 0;        // max |hinges at t = 1 - the target's| (the target as route 1 reached it)
  int newtonIterations = 0;
};

// From the chain's stacked hinges `from` towards `to`, seeded with route 1's stacked hinge velocity (time 1).
// Throws std::invalid_argument when the method cannot move the chain (simulation/chart_system.hpp's rules);
// nothing when Newton does not reach the target to 1e-12.
std::optional<MethodConnection> shootWithMethod(const Chain& chain, Method method, const Eigen::VectorXd& from,
                                                const Eigen::VectorXd& to, const Eigen::VectorXd& hingeVelocity,
                                                double tolerance = 1e-13);

}  // namespace sl
