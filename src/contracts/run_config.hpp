#pragma once
// How a run is configured and where a motion starts: what the scene says and the simulation takes.

#include <Eigen/Dense>

#include "contracts/registry.hpp"

namespace sl {

struct RunConfig {
  // Default: the chart-free ambient method with RKF 7(8) at 1e-14: hinge positions within 1e-10 of the
  // reference starts over T = 20, poles included, and relative energy drift below 1e-12 (docs/methods.md).
  Method method = Method::Ambient;
  Integrator integrator = Integrator::Rkf78;
  double tolerance = 1e-14;              // adaptive integrators: relative and absolute
  double step = 0.01;                    // fixed-step integrators
  double maxRelativeEnergyDrift = 1e-2;  // watchdog: |E - E0| / E0 beyond this stops the run
  double maxRodLengthError = 1e-6;       // watchdog
  long maxSteps = 50'000'000;            // watchdog: bounds the work of any run

  // The integrator's accuracy setting: the tolerance if it is adaptive, the step otherwise.
  double accuracySetting() const { return traits(integrator).adaptive ? tolerance : step; }
};

// The start of the motion as a scene states it; simulation/initial_state.hpp turns it into an InitialState.
struct InitialSpec {
  enum class Kind { ChartCoordinates, Drag };
  Kind kind = Kind::ChartCoordinates;
  Eigen::VectorXd coords;         // chart 0 coordinates, outermost first ((phi, t) for 4 rods)
  Eigen::VectorXd velocity;       // their rates
  Eigen::VectorXd dragPoint;      // a point of R^(n-1), normalised onto S^(n-2)
  Eigen::VectorXd dragDirection;  // projected onto the tangent space at dragPoint
  bool unitSpeed = false;         // rescale the velocity so that g(v, v) = 1
};

// The start of a motion, chart-free: a point x of the unit sphere S^(n-2) in R^(n-1) and a tangent
// vector xdot (x . xdot = 0). Chart coordinates and drag starts are converted into this.
struct InitialState {
  Eigen::VectorXd spherePoint;
  Eigen::VectorXd sphereVelocity;
};

}  // namespace sl
