// Numerical faults through the simulation API: starts on the chart's singular sets (a pole, the seam
// t = +-pi/2), rest and huge speeds, L at the edges of (n-2, n), n = 3 and n = 200, very long durations.
// Each run either keeps its invariants (energy from the hinge velocities, rod lengths recomputed here
// from the hinges) or stops with a named reason at a finite time; every run is bounded (maxSteps) and
// no sample ever holds a non-finite number.
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "contracts/registry.hpp"
#include "simulation/initial_state.hpp"
#include "simulation/trajectory.hpp"

namespace sl {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

struct FaultCase {
  Chain chain;
  InitialState start;
  double duration;
};

FaultCase chartStart(int rods, double baseLength, Eigen::VectorXd coords, Eigen::VectorXd rates, double duration) {
  Chain chain = Chain::uniform(rods, baseLength);
  return {chain, initialStateFromChart(chain, coords, rates), duration};
}

Eigen::VectorXd vec(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double value : values) v(i++) = value;
  return v;
}

RunConfig config(Method method, Integrator integrator, long maxSteps) {
  RunConfig c;
  c.method = method;
  c.integrator = integrator;
  c.tolerance = 1e-10;
  c.step = 0.01;
  c.maxSteps = maxSteps;
  return c;
}

// What one run did, for the tests that pin a particular outcome.
struct Outcome {
  bool completed = false;
  std::optional<StopInfo> stop;
  std::optional<Sample> last;
};

// Samples the run at `count` evenly spaced times and checks every sample and the stop, if any.
Outcome runAndCheck(const FaultCase& fault, const RunConfig& runConfig, int count = 40) {
  SCOPED_TRACE(nameOf(runConfig.method) + " / " + nameOf(runConfig.integrator));
  Trajectory run(fault.chain, fault.start, runConfig);
  // The energy of the start by an independent route: g(v, v) through the chart's Jacobian.
  const double startEnergy = 0.5 * speedSquared(fault.chain, fault.start);
  const AmbientMassMatrix mass = ambientMassMatrix(fault.chain);
  Outcome outcome;
  for (int k = 0; k <= count; ++k) {
    const double t = fault.duration * k / count;
    const std::optional<Sample> sample = run.sampleAt(t);
    if (!sample) {
      EXPECT_TRUE(run.stop().has_value()) << "no sample at t = " << t << " and no stop";
      break;
    }
    EXPECT_TRUE(sample->spherePoint.allFinite() && sample->sphereVelocity.allFinite() && sample->hinges.allFinite() &&
                sample->hingeVelocities.allFinite() && sample->coords.allFinite() && sample->rates.allFinite() &&
                std::isfinite(sample->energy))
        << "non-finite sample at t = " << t;
    EXPECT_NEAR(sample->spherePoint.norm(), 1.0, 1e-9) << "t = " << t;
    // Invariants recomputed from the hinges, not taken from the sample's own fields.
    EXPECT_LE(rodLengthError(fault.chain, sample->hinges), 2 * runConfig.maxRodLengthError) << "t = " << t;
    const double energy = kineticEnergy(mass, sample->hingeVelocities);
    EXPECT_LE(std::abs(energy - startEnergy), 2 * runConfig.maxRelativeEnergyDrift * startEnergy) << "t = " << t;
    outcome.last = sample;
  }
  EXPECT_LE(run.steps(), runConfig.maxSteps);
  outcome.stop = run.stop();
  outcome.completed = !outcome.stop || outcome.stop->time >= fault.duration;
  if (outcome.stop) {
    const auto reason = static_cast<size_t>(outcome.stop->reason);
    EXPECT_LT(reason, kStopReasons.size()) << "unknown stop reason " << reason;
    EXPECT_TRUE(std::isfinite(outcome.stop->time));
    EXPECT_FALSE(outcome.stop->detail().empty()) << nameOf(outcome.stop->reason);
  }
  return outcome;
}

// Every method with a fixed-step and an adaptive integrator: each either keeps its invariants or stops.
void runEveryMethod(const FaultCase& fault, long maxSteps) {
  for (const MethodTraits& method : kMethods) {
    if (fault.chain.rods != 4 && method.published) continue;  // the published methods are 4-rod only
    for (const Integrator integrator : {Integrator::Rk4, Integrator::Dopri5})
      runAndCheck(fault, config(method.kind, integrator, maxSteps));
  }
}

TEST(NumericalFaults, StartExactlyAtThePole) {
  const FaultCase fault = chartStart(4, 3.0, vec({kHalfPi, 0.0}), vec({0.3, 0.5}), 5.0);
  runEveryMethod(fault, 20000);
  // The ambient method has no chart: the pole is an ordinary point for it.
  EXPECT_TRUE(runAndCheck(fault, config(Method::Ambient, Integrator::Rkf78, 20000)).completed);
}

TEST(NumericalFaults, StartExactlyOnTheSeam) {
  for (const double t : {kHalfPi, -kHalfPi}) {
    SCOPED_TRACE(t);
    const FaultCase fault = chartStart(4, 3.0, vec({0.3, t}), vec({0.2, 0.7}), 5.0);
    runEveryMethod(fault, 20000);
    EXPECT_TRUE(runAndCheck(fault, config(Method::Christoffel, Integrator::Rkf78, 20000)).completed);
  }
}

TEST(NumericalFaults, ZeroVelocityIsRefusedWithAReason) {
  const Chain chain = Chain::uniform(4, 3.0);
  const InitialState start = initialStateFromChart(chain, vec({0.3, 0.2}), vec({0.0, 0.0}));
  for (const MethodTraits& method : kMethods) {
    try {
      Trajectory run(chain, start, config(method.kind, Integrator::Dopri5, 1000));
      ADD_FAILURE() << method.name << ": a start at rest was accepted";
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find("zero"), std::string::npos) << error.what();
    }
  }
}

// A geodesic's path does not depend on its speed: at speed 1e6 for 1e-5 time units the chain is where
// the same start at speed 1 is after 10 (an independent reference for the huge-velocity run).
TEST(NumericalFaults, HugeVelocityFollowsTheSamePath) {
  const Eigen::VectorXd coords = vec({0.3, 0.2}), rates = vec({0.5, 0.7});
  const FaultCase slow = chartStart(4, 3.0, coords, rates, 10.0);
  const FaultCase fast = chartStart(4, 3.0, coords, 1e6 * rates, 1e-5);
  const Outcome reference = runAndCheck(slow, config(Method::Ambient, Integrator::Rkf78, 200000));
  const Outcome huge = runAndCheck(fast, config(Method::Ambient, Integrator::Rkf78, 200000));
  ASSERT_TRUE(reference.completed && huge.completed);
  EXPECT_LT((huge.last->hinges - reference.last->hinges).norm(), 1e-6);
  runEveryMethod(fast, 20000);
}

// Fixed steps far too large for the speed: the run must stop (bounded), not produce garbage.
TEST(NumericalFaults, HugeVelocityWithHugeStepsStops) {
  const FaultCase fault = chartStart(4, 3.0, vec({0.3, 0.2}), vec({5e5, 7e5}), 1.0);
  for (const MethodTraits& method : kMethods) {
    const Outcome outcome = runAndCheck(fault, config(method.kind, Integrator::Rk4, 20000));
    EXPECT_FALSE(outcome.completed) << method.name << " claims to have integrated speed 1e6 with steps of 0.01";
  }
}

TEST(NumericalFaults, BaseLengthAtTheEdgesOfTheSphereRange) {
  for (const int rods : {3, 4, 5}) {
    for (const double baseLength : {rods - 2 + 1e-12, rods - 1e-12}) {
      SCOPED_TRACE("n = " + std::to_string(rods) + ", L - n = " + std::to_string(baseLength - rods));
      const Eigen::VectorXd coords = Eigen::VectorXd::Constant(rods - 2, 0.3);
      const Eigen::VectorXd rates = Eigen::VectorXd::Constant(rods - 2, 0.5);
      runEveryMethod(chartStart(rods, baseLength, coords, rates, 2.0), 20000);
    }
  }
}

TEST(NumericalFaults, ThreeRods) {
  const FaultCase fault = chartStart(3, 1.5, vec({0.4}), vec({1.0}), 10.0);
  runEveryMethod(fault, 20000);
  EXPECT_TRUE(runAndCheck(fault, config(Method::Ambient, Integrator::Rkf78, 20000)).completed);
}

// n = 200: the ambient method is O(n) per step; the chart methods are allowed to stop at maxSteps
// (or on a watchdog) but never to run unbounded or produce non-finite numbers.
TEST(NumericalFaults, TwoHundredRods) {
  const int rods = 200;
  const Eigen::VectorXd coords = Eigen::VectorXd::LinSpaced(rods - 2, 0.1, 0.4);
  const Eigen::VectorXd rates = Eigen::VectorXd::LinSpaced(rods - 2, 0.05, -0.05);
  const FaultCase fault = chartStart(rods, rods - 1.0, coords, rates, 0.5);
  EXPECT_TRUE(runAndCheck(fault, config(Method::Ambient, Integrator::Dopri5, 2000), 5).completed);
  runAndCheck(fault, config(Method::Ambient, Integrator::Rk4, 200), 5);
}

// T = 1e5: a fixed step of 1e4 (ten steps) must fail cleanly; an adaptive run must end at maxSteps.
TEST(NumericalFaults, VeryLongDurationIsBounded) {
  const FaultCase fault = chartStart(4, 3.0, vec({0.3, 0.2}), vec({0.5, 0.7}), 1e5);
  for (const MethodTraits& method : kMethods) {
    RunConfig huge = config(method.kind, Integrator::Rk4, 1000);
    huge.step = 1e4;
    EXPECT_FALSE(runAndCheck(fault, huge).completed) << method.name;
    const Outcome adaptive = runAndCheck(fault, config(method.kind, Integrator::Dopri5, 3000));
    ASSERT_TRUE(adaptive.stop.has_value()) << method.name << " integrated T = 1e5 in 3000 steps";
  }
}

}  // namespace
}  // namespace sl
