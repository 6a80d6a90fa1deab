#pragma once
// Ways to say where a motion starts, all converted to the chart-free InitialState (x, xdot).

#include <Eigen/Dense>

#include "contracts/run_config.hpp"
#include "linkage/chain.hpp"

namespace sl {

// From chart-0 coordinates and rates: (phi, t) and (phidot, tdot) for 4 rods (spec section 4's start).
InitialState initialStateFromChart(const Chain& chain, const Eigen::VectorXd& coords, const Eigen::VectorXd& rates);

// From a drag on the sphere (the spec's demo): a start point (normalised) and a release direction, projected
// onto the tangent plane at the point. With unitSpeed the velocity is scaled so that g(v, v) = 1.
// Throws std::invalid_argument for wrong sizes, non-finite input, a zero point or (with unitSpeed) a
// direction with no tangential part.
InitialState initialStateFromDrag(const Chain& chain, const Eigen::VectorXd& point, const Eigen::VectorXd& direction,
                                  bool unitSpeed);

// The start a scene states (chart coordinates and rates of chart 0, a drag, or hinges), as the chart-free
// InitialState of its runs; unit_speed rescales the velocity so that g(v, v) = 1. For a start by hinges,
// `adjustment` (if given) receives how far the start had to move onto the rod constraints.
struct StartAdjustment {
  double positions = 0;   // the largest hinge displacement, in rod lengths
  double velocities = 0;  // the largest hinge velocity change, relative to the largest velocity given
};
InitialState initialStateFromSpec(const Chain& chain, const InitialSpec& spec, StartAdjustment* adjustment = nullptr);

// A start by hinge positions and velocities (InitialSpec::Kind::Hinges; any chain, slack ones included):
// the named shape or the given points, the push or the given velocities, then positions projected onto the
// rod constraints (Newton, mass-orthogonal) and velocities onto their tangent space, as the ambient method's
// own projections do. Throws std::invalid_argument if the hinges cannot be placed or nothing moves.
InitialState initialStateFromHinges(const Chain& chain, const InitialSpec& spec, StartAdjustment& adjustment);

// The hinges of the named shape Arc: on the circular arc through both pins (sagging below them), the rods its
// equal chords.
Eigen::Matrix2Xd arcHinges(int rods, double baseLength);

// Chains up to this many rods take dPsi from the whole Jacobian (sphereJacobian: forward AD in every direction,
// O(n^3)); longer ones by one forward-AD pass along the velocity (O(n^2)), equal to rounding.
inline constexpr int kWholeJacobianRods = 64;

// dPsi(x) xdot: the hinge velocities of a sphere velocity (xdot tangent at x).
Eigen::Matrix2Xd hingeVelocitiesOnSphere(const Chain& chain, const Eigen::VectorXd& x, const Eigen::VectorXd& xdot);

// g(v, v) of a start: |dPsi(xdot)|^2 in the ambient kinetic metric M.
double speedSquared(const Chain& chain, const InitialState& start);

// Checks sizes (n-1), finiteness, |x| = 1 and x . xdot = 0 to 1e-9; the message names what is wrong.
void validateInitialState(const Chain& chain, const InitialState& start);

// A geodesic keeps its speed: over `duration` the hinges travel (mass-weighted RMS) speed x duration / sqrt(total
// mass) rod lengths, and an integrator needs steps in proportion. Throws std::invalid_argument when that exceeds
// limits::kMaxHingeTravel, naming the speed: a huge start speed is refused before any work instead of ending at
// t = 0 with a reason that is not true.
void requireCoverableMotion(const Chain& chain, const InitialState& start, double duration);

}  // namespace sl
