#pragma once
// How a run is configured and where a motion starts: what the scene says and the simulation takes.

#include <optional>
#include <string>
#include <utility>

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
  // Carry the Jacobi fields along the motion (simulation/jacobi_system.hpp) and find its conjugate points;
  // the ambient method only (its linearisation is the one written out).
  bool jacobi = false;

  // The integrator's accuracy setting: the tolerance if it is adaptive, the step otherwise.
  double accuracySetting() const { return traits(integrator).adaptive ? tolerance : step; }
};

// A family of geodesics around a run: `count` members beside the run itself, sharing its chain,
// method and integrator. Fan: the run's point, directions at angles spread evenly over [-spread/2, spread/2]
// from the run's in a g-orthonormal frame, the run's speed. Parallel: points at geodesic distances evenly over
// [-spread/2, spread/2] along the geodesic orthogonal to the run's velocity, velocities g-orthogonal to it there
// (the run's velocity transported). Cloud: the start's point and velocity each moved by up to `epsilon`
// (relative to the speed for the velocity) in random directions drawn from `seed`.
struct FamilySpec {
  FamilyKind kind = FamilyKind::Fan;
  int count = 16;
  double spread = 0.2;    // radians (fan) or geodesic distance (parallel)
  double epsilon = 1e-6;  // cloud
  unsigned long seed = 1;  // cloud
};

// A configuration of the chain as a scene names it: chart 0 coordinates (n-2) or the n-1 hinge positions.
struct ConfigurationSpec {
  Eigen::VectorXd coords;   // given, or ...
  Eigen::Matrix2Xd hinges;  // ... these (projected onto the rod constraints when resolved)
};

// Which found motion a start names. Connect: the geodesics from `from` to `to` up to `maxLength`, shortest
// first (the list of `linkage connect`); Periodic: the closed geodesics up to `maxLength` (the list of
// `linkage periodic`). `index` counts from 0 in that list.
struct FoundMotionSpec {
  ConfigurationSpec from, to;  // Connect
  int index = 0;
  double maxLength = 0;             // <= 0: the finder's own bound
  std::optional<double> arrival;    // Connect: the time the target is reached (default: the length, unit speed)
};

// A found motion as a run starts it: sphere point and velocity, and what the frames may say of it.
struct FoundMotion {
  Eigen::VectorXd spherePoint, sphereVelocity;
  double length = 0;      // its length (the period of a closed geodesic at unit speed)
  double time = 0;        // when it reaches the target (connect) or closes (periodic)
  std::optional<Stability> stability;  // periodic (not on the 3-rod circle); connect: none
  int found = 0;          // how many motions the list held
};

// The start of the motion as a scene states it; simulation/initial_state.hpp turns it into an InitialState.
struct InitialSpec {
  // Hinges: positions and velocities of the interior hinges (any chain, slack ones included; ambient method),
  // given point by point or as a named shape with a push (long chains).
  // Connect, Periodic: a motion the inverse problems find (a geodesic from one configuration to another, a closed
  // geodesic), named by its place in their lists; the commands resolve it into `motion` before any run starts.
  enum class Kind { ChartCoordinates, Drag, Hinges, Connect, Periodic };
  enum class Shape { Given, Arc };  // Arc: the hinges on the circular arc through both pins, rods as its chords
  Kind kind = Kind::ChartCoordinates;
  Eigen::VectorXd coords;         // chart 0 coordinates, outermost first ((phi, t) for 4 rods)
  Eigen::VectorXd velocity;       // their rates
  Eigen::VectorXd dragPoint;      // a point of R^(n-1), normalised onto S^(n-2)
  Eigen::VectorXd dragDirection;  // projected onto the tangent space at dragPoint
  bool unitSpeed = false;         // rescale the velocity so that g(v, v) = 1
  Shape shape = Shape::Given;
  Eigen::Matrix2Xd hinges;           // Given: p1..p(n-1)
  Eigen::Matrix2Xd hingeVelocities;  // Given: their velocities (zero columns allowed); empty with a push
  int pushHinge = 0;                 // a push: hinge k (1..n-1) gets pushVelocity ...
  Eigen::Vector2d pushVelocity = Eigen::Vector2d::Zero();
  long pushSeed = -1;                // ... or, seed >= 0, every hinge a random velocity of size pushSize
  double pushSize = 1;
  FoundMotionSpec search;  // Connect, Periodic
  std::optional<FoundMotion> motion;  // Connect, Periodic: set once resolved

  bool namesAMotion() const { return kind == Kind::Connect || kind == Kind::Periodic; }
};

// The start of a motion, chart-free: a point x of the unit sphere S^(n-2) in R^(n-1) and a tangent
// vector xdot (x . xdot = 0). Chart coordinates and drag starts are converted into this. A start given by
// hinges (slack or long chains, ambient method) has the hinge positions and velocities instead, on the rod
// constraints, and no sphere point.
struct InitialState {
  InitialState() = default;
  InitialState(Eigen::VectorXd point, Eigen::VectorXd velocity)
      : spherePoint(std::move(point)), sphereVelocity(std::move(velocity)) {}

  Eigen::VectorXd spherePoint;
  Eigen::VectorXd sphereVelocity;
  Eigen::Matrix2Xd hinges;           // a start by hinges: p1..p(n-1), |p_k - p_(k-1)| = 1
  Eigen::Matrix2Xd hingeVelocities;  // tangent to the rod constraints

  bool byHinges() const { return hinges.cols() > 0; }
};

}  // namespace sl
