// Runs as objects: sampling never changes the motion, RK4's order, watchdogs and clean stops, bad input.
#include <gtest/gtest.h>

#include <cstdio>

#include <cmath>
#include <iostream>
#include <limits>

#include "contracts/limits.hpp"
#include "support.hpp"

namespace sl {
namespace {

const Chain specChain = Chain::uniform(4, 3.0);

void expectBitwiseEqual(const Sample& a, const Sample& b) {
  EXPECT_EQ(a.time, b.time);
  for (Eigen::Index i = 0; i < a.hinges.size(); ++i) EXPECT_EQ(a.hinges.data()[i], b.hinges.data()[i]);
  for (Eigen::Index i = 0; i < a.coords.size(); ++i) EXPECT_EQ(a.coords(i), b.coords(i));
  for (Eigen::Index i = 0; i < a.rates.size(); ++i) EXPECT_EQ(a.rates(i), b.rates(i));
  EXPECT_EQ(a.energy, b.energy);
}

TEST(Trajectory, SamplingPatternDoesNotChangeTheMotion) {
  // Every frame at 30 fps against frame 500 alone (t = 500/30, after a pole switch for the atlas methods).
  for (const std::string method : {"ambient", "christoffel", "embedded-fd"})
    for (const std::string integrator : {"rk4", "dopri5", "bulirsch-stoer"}) {
      const RunConfig c = testing::config(method, integrator, 1e-10);
      Trajectory everyFrame(specChain, testing::genericStart(specChain), c);
      std::optional<Sample> frame500;
      for (int frame = 0; frame <= 500; ++frame) frame500 = everyFrame.sampleAt(frame / 30.0);
      Trajectory once(specChain, testing::genericStart(specChain), c);
      const std::optional<Sample> alone = once.sampleAt(500 / 30.0);
      ASSERT_TRUE(frame500 && alone) << method << "/" << integrator;
      expectBitwiseEqual(*frame500, *alone);
      EXPECT_EQ(everyFrame.steps(), once.steps());
    }
}

TEST(Trajectory, RepeatedSamplingOfOneTimeIsStable) {
  Trajectory run(specChain, testing::seamStart(specChain), testing::config("christoffel"));
  const auto a = run.sampleAt(3.0), b = run.sampleAt(3.0);
  ASSERT_TRUE(a && b);
  expectBitwiseEqual(*a, *b);
}

TEST(Trajectory, Rk4IsFourthOrder) {
  // Errors at T = 4 against the ambient method at 1e-13 (a different method, not a self-check).
  Trajectory reference(specChain, testing::genericStart(specChain),
                       testing::config("ambient", "bulirsch-stoer", 1e-13));
  const Eigen::Matrix2Xd target = reference.sampleAt(4.0)->hinges;
  for (const std::string method : {"christoffel", "embedded"}) {
    std::vector<double> errors;
    for (double h : {0.02, 0.01, 0.005}) {
      RunConfig c = testing::config(method, "rk4");
      c.step = h;
      Trajectory run(specChain, testing::genericStart(specChain), c);
      const std::optional<Sample> s = run.sampleAt(4.0);
      ASSERT_TRUE(s) << nameOf(run.stop()->reason);
      errors.push_back((s->hinges - target).cwiseAbs().maxCoeff());
    }
    const double ratio1 = errors[0] / errors[1], ratio2 = errors[1] / errors[2];
    std::cout << method << " rk4 errors " << errors[0] << " " << errors[1] << " " << errors[2] << ", ratios " << ratio1
              << " " << ratio2 << "\n";
    EXPECT_NEAR(ratio1, 16.0, 3.0) << method;
    EXPECT_NEAR(ratio2, 16.0, 3.0) << method;
  }
}

TEST(Trajectory, HermiteSamplingBetweenRk4StepsKeepsTheStepAccuracy) {
  // Samples between steps come from cubic Hermite: error O(h^4) locally, so well below the step error.
  RunConfig c = testing::config("christoffel", "rk4");
  c.step = 0.01;
  Trajectory run(specChain, testing::genericStart(specChain), c);
  Trajectory reference(specChain, testing::genericStart(specChain),
                       testing::config("ambient", "bulirsch-stoer", 1e-13));
  double worst = 0;
  for (double t = 0.0; t < 2.0; t += 0.0037)
    worst = std::max(worst, (run.sampleAt(t)->hinges - reference.sampleAt(t)->hinges).cwiseAbs().maxCoeff());
  EXPECT_LT(worst, 3e-8);  // the RK4 steps themselves are ~1e-8 off here
}

TEST(Trajectory, StopsCleanlyAndSaysWhy) {
  RunConfig c = testing::config("ambient");
  c.maxSteps = 10;
  Trajectory run(specChain, testing::genericStart(specChain), c);
  EXPECT_TRUE(run.sampleAt(0.0));
  EXPECT_FALSE(run.sampleAt(15.0));
  ASSERT_TRUE(run.stop());
  EXPECT_EQ(run.stop()->reason, StopReason::MaxSteps);
  EXPECT_GT(run.stop()->time, 0.0);
  EXPECT_EQ(run.steps(), 10);
  EXPECT_FALSE(run.sampleAt(16.0));
}

// reaches(t) answers what sampleAt(t) would, up to the stop time itself (which can still be sampled), and past it.
TEST(Trajectory, ReachesAgreesWithSampleAtAboutTheStop) {
  RunConfig c = testing::config("ambient");
  c.maxSteps = 10;
  Trajectory probe(specChain, testing::genericStart(specChain), c);
  EXPECT_FALSE(probe.reaches(15.0));
  ASSERT_TRUE(probe.stop());
  const double stopTime = probe.stop()->time;
  for (double t : {0.0, 0.5 * stopTime, stopTime, stopTime + 1e-9, stopTime + 1.0}) {
    Trajectory a(specChain, testing::genericStart(specChain), c), b(specChain, testing::genericStart(specChain), c);
    EXPECT_EQ(a.reaches(t), b.sampleAt(t).has_value()) << "t = " << t;
    EXPECT_EQ(a.reaches(t), t <= stopTime) << "t = " << t;
  }
  EXPECT_THROW(probe.reaches(-1.0), std::invalid_argument);
}

TEST(Trajectory, EnergyWatchdogCatchesAnUnstableStepSize) {
  RunConfig c = testing::config("christoffel", "rk4");
  c.step = 0.7;
  Trajectory run(specChain, testing::genericStart(specChain), c);
  std::optional<Sample> last;
  for (double t = 0; t <= 20; t += 0.1) {
    auto s = run.sampleAt(t);
    if (!s) break;
    EXPECT_TRUE(s->hinges.allFinite() && s->coords.allFinite() && s->rates.allFinite());
    last = s;
  }
  ASSERT_TRUE(run.stop());
  EXPECT_EQ(run.stop()->reason, StopReason::EnergyBlowUp);
  EXPECT_LE(last->relativeEnergyDrift, c.maxRelativeEnergyDrift);
  // The frames say what tripped the watchdog: its reading against its limit, a drift beyond the limit.
  const std::string measured = run.stop()->reading();
  EXPECT_EQ(measured.rfind("energy drift ", 0), 0u) << measured;
  double drift = 0, limit = 0;
  ASSERT_EQ(std::sscanf(measured.c_str(), "energy drift %lf > limit %lf", &drift, &limit), 2) << measured;
  EXPECT_GT(drift, limit);
  EXPECT_DOUBLE_EQ(limit, c.maxRelativeEnergyDrift);
}

// A stop is recorded as numbers; its words are made where they are shown, the same words as when the integrator
// loop wrote them (run reports, CSV and event files, the frames' text panel all show these).
TEST(Trajectory, StopWordsAreMadeFromTheRecordedNumbers) {
  StopInfo energy;
  energy.reason = StopReason::EnergyBlowUp;
  energy.time = 19.74;
  energy.checkedAt = 19.760000000000002;
  energy.measured = 2.1253323570632361;
  energy.limit = 1;
  EXPECT_EQ(energy.detail(), "relative energy drift 2.1253323570632361 at t = 19.760000000000002");
  EXPECT_EQ(energy.reading(), "energy drift 2.13 > limit 1");
  StopInfo rods = energy;
  rods.reason = StopReason::RodLength;
  rods.measured = 0.00123456;
  rods.limit = 1e-3;
  EXPECT_EQ(rods.detail(), "rod-length error 0.00123456 at t = 19.760000000000002");
  EXPECT_EQ(rods.reading(), "rod-length error 0.00123 > limit 0.001");
  StopInfo budget;
  budget.reason = StopReason::MaxSteps;
  budget.limit = 5000000;
  EXPECT_EQ(budget.detail(), "reached maxSteps = 5000000");
  EXPECT_EQ(budget.reading(), "");
  StopInfo collapse;
  collapse.reason = StopReason::StepSizeCollapse;
  collapse.time = 2.5;
  collapse.measured = 1e-300;
  EXPECT_EQ(collapse.detail(), "step size 1e-300 at t = 2.5");
  collapse.measured = std::numeric_limits<double>::quiet_NaN();
  collapse.cause = "step too small";
  EXPECT_EQ(collapse.detail(), "integrator gave up: step too small");
  StopInfo pole;
  pole.reason = StopReason::PoleFoldBack;
  pole.checkedAt = 0.5;
  pole.cause = "phi crossed the pole";
  EXPECT_EQ(pole.detail(), "phi crossed the pole at t = 0.5");
  StopInfo rank;
  rank.reason = StopReason::ConstraintRankLoss;
  rank.time = 1.25;
  rank.cause = "the constraint lost rank";
  EXPECT_EQ(rank.detail(), "the constraint lost rank in the step from t = 1.25");
  StopInfo nan;
  nan.time = 3;
  nan.cause = "(phi, t) = (0.1, 0.2)";
  EXPECT_EQ(nan.detail(), "state became non-finite in the step from t = 3; last good state (phi, t) = (0.1, 0.2)");
}

// The extremes the run tracks at its step ends equal the invariants of samples taken at those very times
// (rk4 with step 0.02: every multiple of the step is a step end), recomputed from the hinges by sample().
TEST(Trajectory, InvariantExtremesAreTheWorstOverTheStepEnds) {
  RunConfig c = testing::config("christoffel", "rk4");
  c.step = 0.02;
  Trajectory run(specChain, testing::genericStart(specChain), c);
  EXPECT_EQ(run.invariantExtremes().maxRelativeEnergyDrift, 0.0);
  double drift = 0, rodLength = 0;
  for (int k = 1; k <= 200; ++k) {
    const std::optional<Sample> s = run.sampleAt(k * 0.02);
    ASSERT_TRUE(s) << nameOf(run.stop()->reason);
    drift = std::max(drift, s->relativeEnergyDrift);
    rodLength = std::max(rodLength, s->rodLengthError);
  }
  EXPECT_GT(drift, 1e-9);  // rk4 at this step drifts visibly: the check is not vacuous
  EXPECT_NEAR(run.invariantExtremes().maxRelativeEnergyDrift, drift, 1e-9 * drift);
  EXPECT_NEAR(run.invariantExtremes().maxRodLengthError, rodLength, 1e-15);
}

// The chart methods' rod limit holds for runs built in code, not only for scenes: the same rule
// (linkage/method_rules.hpp) refuses a 20-rod chain moved with christoffel, and admits it up to the limit.
TEST(Trajectory, ChartMethodsAreRefusedBeyondTheirRodLimitWhenBuiltInCode) {
  const auto startOf = [](const Chain& chain) {
    const Eigen::VectorXd coords = Eigen::VectorXd::Constant(chain.sphereDimension(), 0.1);
    Eigen::VectorXd rates = Eigen::VectorXd::Zero(chain.sphereDimension());
    rates(0) = 0.5;
    return initialStateFromChart(chain, coords, rates);
  };
  const Chain twenty = Chain::uniform(20, 19.0);
  EXPECT_NO_THROW(Trajectory(twenty, startOf(twenty), testing::config("ambient")));
  try {
    Trajectory(twenty, startOf(twenty), testing::config("christoffel"));
    ADD_FAILURE() << "christoffel moved 20 rods";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("limited to 12 rods"), std::string::npos) << error.what();
  }
  for (const int rods : {limits::kMaxRods, limits::kMaxRods + 1}) {
    const Chain chain = Chain::uniform(rods, rods - 1.0);
    if (rods <= limits::kMaxRods)
      EXPECT_NO_THROW(Trajectory(chain, startOf(chain), testing::config("embedded")));
    else
      EXPECT_THROW(Trajectory(chain, startOf(chain), testing::config("embedded")), std::invalid_argument);
  }
}

TEST(Trajectory, RejectsBadConfigurationAndStartsWithClearErrors) {
  auto message = [](auto&& make) {
    try {
      make();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const InitialState start = testing::genericStart(specChain);
  EXPECT_NE(message([&] { Trajectory(specChain, start, testing::config("verlet")); }).find("unknown method"),
            std::string::npos);
  EXPECT_NE(
      message([&] { Trajectory(specChain, start, testing::config("ambient", "euler")); }).find("unknown integrator"),
      std::string::npos);
  EXPECT_NE(message([&] { Trajectory(specChain, start, testing::config("ambient", "dopri5", 0.0)); }).find("tolerance"),
            std::string::npos);
  EXPECT_NE(message([&] { Trajectory(Chain::uniform(4, 4.5), start, testing::config("ambient")); }).find("L must lie"),
            std::string::npos);
  InitialState wrongSize{Eigen::Vector4d(1, 0, 0, 0), Eigen::Vector4d(0, 1, 0, 0)};
  EXPECT_NE(message([&] { Trajectory(specChain, wrongSize, testing::config("ambient")); }).find("needs 3 components"),
            std::string::npos);
  InitialState notTangent{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 1, 0)};
  EXPECT_NE(message([&] { Trajectory(specChain, notTangent, testing::config("ambient")); }).find("tangent"),
            std::string::npos);
  InitialState resting{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d::Zero()};
  EXPECT_NE(message([&] { Trajectory(specChain, resting, testing::config("christoffel")); }).find("zero"),
            std::string::npos);
  Trajectory run(specChain, start, testing::config("ambient"));
  run.sampleAt(1.0);
  EXPECT_THROW(run.sampleAt(0.5), std::invalid_argument);
  EXPECT_THROW(run.sampleAt(std::nan("")), std::invalid_argument);
}

TEST(InitialState, ChartAndDragStartsAgree) {
  const InitialState chart = testing::genericStart(specChain);
  const InitialState drag =
      initialStateFromDrag(specChain, 2.0 * chart.spherePoint, chart.sphereVelocity + 0.3 * chart.spherePoint, false);
  EXPECT_LT((drag.spherePoint - chart.spherePoint).norm(), 1e-15);
  EXPECT_LT((drag.sphereVelocity - chart.sphereVelocity).norm(), 1e-15);
  const InitialState unit = initialStateFromDrag(specChain, chart.spherePoint, chart.sphereVelocity, true);
  EXPECT_NEAR(speedSquared(specChain, unit), 1.0, 1e-14);
  // The spec's reference start has g(v, v) = speed2_0 of generic_L3.json.
  EXPECT_NEAR(speedSquared(specChain, chart), 3.24497480972659, 1e-13);
  EXPECT_THROW(initialStateFromDrag(specChain, chart.spherePoint, chart.spherePoint, true), std::invalid_argument);
}

}  // namespace
}  // namespace sl
