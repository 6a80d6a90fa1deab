#pragma once
// What a geodesic method hands to the integrators: a first-order ODE y' = f(y) on a flat state vector,
// plus the hooks a run needs between steps. Two kinds exist: ChartSystem (coordinates and rates in a
// chart of the sphere) and AmbientSystem (hinge positions and velocities under rod constraints).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "contracts/registry.hpp"

namespace sl {

using State = std::vector<double>;

// Where a state sits physically; the run derives energy, rod-length error and chart-0 coordinates.
struct PhysicalState {
  Eigen::VectorXd spherePoint;
  Eigen::VectorXd sphereVelocity;
  Eigen::Matrix2Xd hinges;
  Eigen::Matrix2Xd hingeVelocities;
  std::optional<Eigen::VectorXd> chartZeroCoords;  // when the state already is in chart 0 (t continuous)
  std::optional<Eigen::VectorXd> chartZeroRates;
};

// What the run watches after every step.
struct StepInvariants {
  double energy = 0;          // (1/2) g(v, v)
  double rodLengthError = 0;  // max_k | |p_k - p_(k-1)| - 1 |
  double chartZeroT = 0;      // chart 0's last coordinate, unwrapped near the previous one
};

struct MethodFailure {
  StopReason reason;
  std::string detail;
};

class GeodesicSystem {
 public:
  virtual ~GeodesicSystem() = default;
  virtual State initialState() const = 0;
  virtual void derivative(const State& y, State& dydt) const = 0;
  // Between steps (never inside one): change chart or project onto the constraints. True when y changed,
  // which restarts the integrator from y.
  virtual bool settleBetweenSteps(State& y) { return false; }
  // A failure the method itself can see in a state (the single chart folding back over a pole).
  virtual std::optional<MethodFailure> methodFailureAt(const State& y) const { return std::nullopt; }
  // Hinges, sphere point and velocities of a state.
  virtual PhysicalState physicalState(const State& y) const = 0;
  // What the watchdogs check after a step (previousT: chart 0's last coordinate before it, for unwrapping).
  virtual StepInvariants stepInvariants(const State& y, double previousT) const = 0;
  // A short description of the state for failure reports ("chart 1, coords (..)").
  virtual std::string describe(const State& y) const = 0;
  // How many leading components of y are the motion itself. The adaptive integrators' step-size control
  // reads only these; what follows (the Jacobi fields) is carried along by the same steps and stages, so the
  // motion is the same, to the bit, with or without it.
  virtual std::size_t motionSize(const State& y) const { return y.size(); }
};

}  // namespace sl
