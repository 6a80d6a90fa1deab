#pragma once
// The trajectory of one run: a geodesic method integrated from an initial state by an integrator, watched
// for failure (the watchdogs of RunConfig), sampled on demand. Used by frames/, analysis/ and cli/.

#include <memory>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "contracts/registry.hpp"
#include "contracts/run_control.hpp"
#include "contracts/run_config.hpp"
#include "linkage/chain.hpp"

namespace sl {

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
  // With RunConfig::jacobi: the size of the Jacobi field across the motion, (det G)^(1/2m) (|J_perp| for 4
  // rods; simulation/jacobi_system.hpp), zero at conjugate points.
  std::optional<double> jacobi;
};

// Why and when a run stopped, as numbers: the integrator loop records them and formats nothing; detail() and
// reading() make the words where they are shown (run reports, CSV and event files, the frames' text panel).
struct StopInfo {
  StopReason reason = StopReason::NonFinite;
  double time = 0;  // last good time
  // When the failed check was made: the failed step's end (a watchdog's reading, a method's own failure).
  double checkedAt = std::numeric_limits<double>::quiet_NaN();
  // A watchdog's reading and its limit: energy drift, rod-length error, step size (no limit), the step budget
  // (max-steps: the limit only). NaN where there is none.
  double measured = std::numeric_limits<double>::quiet_NaN();
  double limit = std::numeric_limits<double>::quiet_NaN();
  // What a lower layer said, in its words: a method's failure, the integrator's error, the constraint's rank loss,
  // the last good state of a non-finite step. Empty for a watchdog's stop.
  std::string cause;

  // Where and what, numbers in full, e.g. "relative energy drift 2.1253323570632361 at t = 19.760000000000002".
  std::string detail() const;
  // A watchdog's reading against its limit in a few digits, e.g. "energy drift 2.13 > limit 1"; empty for other stops.
  std::string reading() const;
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
  // Whether sampleAt(t) would give a state (integrating up to t as it does), without computing that state.
  bool reaches(double t);

  // Asked before every integration step (so a long sampleAt answers within one step), e.g. "was SIGTERM
  // received?"; empty = never cancelled.
  void setCancellation(std::function<bool()> cancelled);

  const std::optional<StopInfo>& stop() const;
  // With RunConfig::jacobi: the conjugate points found so far (times t > 0 where the Jacobi fields across the
  // motion are singular), increasing, each located to ~1e-12 in time on the integrator's dense output. The
  // integration may run one step ahead of the last sample: callers keep those up to the time they sampled.
  const std::vector<double>& conjugateTimes() const;
  const InvariantExtremes& invariantExtremes() const;  // over the steps integrated so far
  long vectorFieldEvaluations() const;
  long steps() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sl
