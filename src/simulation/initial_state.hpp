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

// The start a scene states (chart coordinates and rates of chart 0, or a drag), as the chart-free
// InitialState of its runs; unit_speed rescales the velocity so that g(v, v) = 1.
InitialState initialStateFromSpec(const Chain& chain, const InitialSpec& spec);

// g(v, v) of a start: |dPsi(xdot)|^2 in the ambient kinetic metric M.
double speedSquared(const Chain& chain, const InitialState& start);

// Checks sizes (n-1), finiteness, |x| = 1 and x . xdot = 0 to 1e-9; the message names what is wrong.
void validateInitialState(const Chain& chain, const InitialState& start);

}  // namespace sl
