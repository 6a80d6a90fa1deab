#pragma once
// The scene's start (chart coordinates or a drag on the sphere) as the chart-free InitialState of a run.

#include "scene/scene.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

// Chart coordinates: x = S(coords), xdot = dS(coords) velocity (chart 0, the spec's chart).
// Drag (the spec's demo): x = point / |point|, xdot = the direction's component tangent at x.
// unit_speed rescales xdot so that the kinetic metric gives g(xdot, xdot) = 1.
InitialState initialStateFromScene(const Scene& scene);

// g(xdot, xdot) = <J xdot, M J xdot> with J the Jacobian of Psi at x and M the ambient mass matrix.
double kineticSpeedSquared(const Chain& chain, const Eigen::VectorXd& spherePoint, const Eigen::VectorXd& sphereVelocity);

}  // namespace sl
