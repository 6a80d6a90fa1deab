#pragma once
// Starts for the sweeps: a chain, an initial state on the sphere and a span of time, with a name.
// The shipped set covers the places where chart-based methods are known to struggle (spec sections
// 3-4: the seam t = pi/2 of the published metric, the poles phi = +-pi/2 of the chart (phi, t), and
// base lengths L near the ends of the regime n-2 < L < n).

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "contracts/run_config.hpp"
#include "linkage/chain.hpp"

namespace sl {

struct NamedStart {
  std::string name;
  std::string description;
  Chain chain;
  InitialState state;
  double duration = 20;
};

// A start that reaches `point` with velocity `velocity` after `arrivalTime`: geodesics run backwards
// under v -> -v, so the chart-free reference (ambient, tight tolerance) is run from (point, -velocity)
// and its end state reversed. Throws std::runtime_error if that run stops.
InitialState stateArrivingAt(const Chain& chain, const InitialState& arrival, double arrivalTime);

// The point at angular distance `distance` from the north pole x_last = 1 of the chart at azimuth
// `azimuth` (in the (x1, x2) plane), moving along the circle of constant distance with round-sphere
// speed `speed`: the height x_last is stationary there, so along the geodesic this is the closest
// approach to the pole (for small distances).
InitialState closestApproachToPole(int sphereAmbientDimension, double distance, double azimuth, double speed);

// The shipped 4-rod starts: generic, seam-crossing, near-pole, through-pole, L-near-2, L-near-4.
std::vector<NamedStart> shippedStarts();

}  // namespace sl
