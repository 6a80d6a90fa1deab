#pragma once
// A run: one geodesic method integrated from an initial state, watched for failure, sampled on demand.
// Contract shared with frames/, cli/ and bench; simulation/ owns the implementation.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "linkage/chain.hpp"

namespace sl {

// The start of a motion, chart-free: a point x of the unit sphere S^(n-2) in R^(n-1) and a tangent
// vector xdot (x . xdot = 0). Chart coordinates and drag starts are converted into this.
struct InitialState {
  Eigen::VectorXd spherePoint;
  Eigen::VectorXd sphereVelocity;
};

struct RunConfig {
  // Default: the chart-free ambient method with RKF 7(8) at 1e-14: hinge positions within 1e-10 of the
  // reference starts over T = 20, poles included, and relative energy drift below 1e-12 (at 1e-13 the
  // drift is 2.5e-12), for about 1.3x the steps of 1e-13 (docs/methods.md).
  std::string method = "ambient";        // christoffel-fd | embedded-fd | christoffel | embedded | ambient
  std::string integrator = "rkf78";      // rk4 | dopri5 | rkf78 | bulirsch-stoer
  double tolerance = 1e-14;              // adaptive integrators: relative and absolute
  double step = 0.01;                    // fixed-step integrators
  double maxRelativeEnergyDrift = 1e-2;  // watchdog: |E - E0| / E0 beyond this stops the run
  double maxRodLengthError = 1e-6;       // watchdog
  long maxSteps = 50'000'000;            // watchdog: bounds the work of any run
};

struct Sample {
  double time = 0;
  Eigen::VectorXd coords;          // chart coordinates of the spec's chart, outermost first; t unwrapped
  Eigen::VectorXd rates;           // their time derivatives (may be non-finite at a pole of the chart)
  Eigen::VectorXd spherePoint;     // x in S^(n-2), R^(n-1)
  Eigen::VectorXd sphereVelocity;  // xdot, tangent at x (chart-free velocity: restarts a run exactly)
  Eigen::Matrix2Xd hinges;         // interior hinges p1..p(n-1)
  Eigen::Matrix2Xd hingeVelocities;
  double energy = 0;  // (1/2) g(v, v)
  double relativeEnergyDrift = 0;
  double rodLengthError = 0;  // max_k | |p_k - p_(k-1)| - 1 |
};

struct StopInfo {
  std::string reason;  // non-finite | pole-fold-back | pole-singularity | energy-blow-up | step-size-collapse |
                       // rod-length | max-steps
  double time = 0;     // last good time
  std::string detail;  // human-readable: where and what
};

// The invariants' worst values over every accepted step so far (the watchdogs evaluate them at each step's
// end anyway): a run's drift is known without sampling it densely.
struct InvariantExtremes {
  double maxRelativeEnergyDrift = 0;  // max |E - E0| / E0
  double maxRodLengthError = 0;       // max_k | |p_k - p_(k-1)| - 1 |
};

class Trajectory {
 public:
  Trajectory(const Chain& chain, const InitialState& start, const RunConfig& config);
  ~Trajectory();
  Trajectory(Trajectory&&) noexcept;
  Trajectory& operator=(Trajectory&&) noexcept;

  // The state at time t (calls with non-decreasing t). Integration steps never depend on which times
  // are asked for, so every sampling of the same run sees the same motion. Empty once the run has
  // stopped before t; stop() then says why and when.
  std::optional<Sample> sampleAt(double t);

  const std::optional<StopInfo>& stop() const;
  const InvariantExtremes& invariantExtremes() const;  // over the steps integrated so far
  long vectorFieldEvaluations() const;
  long steps() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Names accepted in RunConfig, for validation and help texts.
std::vector<std::string> methodNames();
std::vector<std::string> integratorNames();
bool integratorIsAdaptive(const std::string& integrator);

}  // namespace sl
