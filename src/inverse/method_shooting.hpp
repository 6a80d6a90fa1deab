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

// Newton aims at 1e-12. A method whose forces are finite differences (the `-fd` ones) has a noise floor above
// that: Newton stops once its error no longer halves, and the shot counts when it came within this bound (its
// end error is reported with it). Before, such shots ran all 30 iterations of 5 runs each and were then dropped:
// `connect --method embedded-fd` took 713 s to print "-" for every motion.
inline constexpr double kMethodShotEndBound = 1e-8;
// The published methods' finite differences are noisy at about 1e-11: a tighter step control collapses on that
// noise (step 9e-10 at t = 0.76 for christoffel-fd at 1e-13), so they integrate at this floor. Measured at L = 3
// from (0.5, 0.3) to (-0.6, 2.2): embedded-fd reaches all four motions in 1.9 s (0.8 s at 1e-10 reaches one,
// 42 s at 1e-13), end errors 2e-9 to 6e-9, lengths within 4e-8 of route 1.
inline constexpr double kPublishedMethodToleranceFloor = 1e-11;

// From the chain's stacked hinges `from` towards `to`, seeded with route 1's stacked hinge velocity (time 1).
// Throws std::invalid_argument when the method cannot move the chain (simulation/chart_system.hpp's rules);
// nothing when Newton does not reach the target within kMethodShotEndBound. `cancelled`: asked between runs
// (RunCancelled, as the searches).
std::optional<MethodConnection> shootWithMethod(const Chain& chain, Method method, const Eigen::VectorXd& from,
                                                const Eigen::VectorXd& to, const Eigen::VectorXd& hingeVelocity,
                                                double tolerance = 1e-13, bool (*cancelled)() = nullptr);

}  // namespace sl
