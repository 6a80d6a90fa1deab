// The spec's published methods (christoffel-fd, embedded-fd) as runs: where they work, and where they
// break, pinned.
#include <gtest/gtest.h>

#include <iostream>

#include "support.hpp"

namespace sl {
namespace {

const Chain specChain = Chain::uniform(4, 3.0);

double maxErrorAgainstReference(Trajectory& run, const std::string& file) {
  double worst = 0;
  for (const testing::ReferenceRow& row : testing::loadReference(file)) {
    const auto s = run.sampleAt(row.time);
    if (!s) throw std::runtime_error("stopped: " + nameOf(run.stop()->reason) + " " + run.stop()->detail());
    worst = std::max(worst, (s->hinges - row.hinges).cwiseAbs().maxCoeff());
  }
  return worst;
}

TEST(PublishedMethods, FollowTheReferenceAwayFromThePoles) {
  // The spec's demo setting, RK4 with h = 0.01, and dopri5 at a moderate tolerance. seam_crossings_L3 stays
  // at |cos phi| >= 0.29 but crosses the seam t = pi/2 + k pi seven times.
  for (const std::string method : {"christoffel-fd", "embedded-fd"}) {
    RunConfig rk4 = testing::config(method, "rk4");
    rk4.step = 0.01;
    Trajectory demo(specChain, testing::seamStart(specChain), rk4);
    const double demoError = maxErrorAgainstReference(demo, "seam_crossings_L3.csv");
    Trajectory adaptive(specChain, testing::seamStart(specChain), testing::config(method, "dopri5", 1e-8));
    const double adaptiveError = maxErrorAgainstReference(adaptive, "seam_crossings_L3.csv");
    std::cout << method << ": rk4 h = 0.01 max hinge error " << demoError << ", dopri5 1e-8 " << adaptiveError << "\n";
    EXPECT_LT(demoError, 5e-6);  // difference-quotient error (eps^2, rounding / eps^2) accumulated over T = 20
    EXPECT_LT(adaptiveError, 1e-5);
  }
}

TEST(PublishedMethods, ChristoffelFdCannotCrossTheSeamAtTightTolerance) {
  // Near t = pi/2 the published metric4 loses digits (4 - |p2|^2 cancels, then nu_in divides); its
  // difference quotients turn to noise and an adaptive integrator at 1e-11 shrinks its steps to nothing
  // at the first seam crossing (t = 0.48 in seam_crossings_L3). embedded-fd (sinc-form Psi) crosses.
  Trajectory published(specChain, testing::seamStart(specChain), testing::config("christoffel-fd", "dopri5", 1e-11));
  EXPECT_FALSE(published.sampleAt(1.0));
  ASSERT_TRUE(published.stop());
  EXPECT_EQ(published.stop()->reason, StopReason::StepSizeCollapse);
  EXPECT_NEAR(published.stop()->time, 0.475, 0.01);
  Trajectory embedded(specChain, testing::seamStart(specChain), testing::config("embedded-fd", "dopri5", 1e-11));
  EXPECT_TRUE(embedded.sampleAt(1.0));
}

TEST(PublishedMethods, RefuseChainsTheyDoNotCover) {
  Chain five = Chain::uniform(5, 3.5);
  const InitialState start =
      initialStateFromDrag(five, Eigen::Vector4d(1, 0.2, 0.3, 0.1), Eigen::Vector4d(0, 1, 0, 0), true);
  for (const std::string method : {"christoffel-fd", "embedded-fd"}) {
    try {
      Trajectory run(five, start, testing::config(method));
      FAIL() << method << " accepted a 5-rod chain";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("4-rod"), std::string::npos) << e.what();
    }
  }
  Chain massive = Chain::uniform(4, 3.0);
  massive.rodMasses(1) = 0.5;
  EXPECT_THROW(Trajectory(massive, testing::genericStart(massive), testing::config("embedded-fd")),
               std::invalid_argument);
}

TEST(PublishedMethods, StopWithPoleFoldBackOnAPolePassage) {
  const InitialState start = testing::poleCrossingStart(specChain, 2.0, Eigen::Vector3d(1.0, 0.4, 0.0));
  for (const std::string method : {"christoffel-fd", "embedded-fd"})
    for (const std::string integrator : {"rk4", "dopri5"}) {
      Trajectory run(specChain, start, testing::config(method, integrator, 1e-10));
      std::optional<Sample> last;
      for (double t : testing::evenTimes(4.0, 400))
        if (auto s = run.sampleAt(t))
          last = s;
        else
          break;
      ASSERT_TRUE(run.stop()) << method << "/" << integrator << " ran through the pole";
      std::cout << method << "/" << integrator << ": " << nameOf(run.stop()->reason) << " at t = " << run.stop()->time
                << " (" << run.stop()->detail() << ")\n";
      // Pinned: all stop at the pole; christoffel-fd under dopri5 first sees its difference quotients turn to
      // noise at |cos phi| ~ 1.5e-3 and collapses its step there.
      const bool collapses = method == "christoffel-fd" && integrator == "dopri5";
      EXPECT_EQ(run.stop()->reason, collapses ? StopReason::StepSizeCollapse : StopReason::PoleFoldBack);
      EXPECT_NEAR(run.stop()->time, 2.0, 0.015);
      ASSERT_TRUE(last);
      EXPECT_TRUE(last->coords.allFinite() && last->rates.allFinite());
      EXPECT_FALSE(run.sampleAt(4.0));
    }
}

TEST(PublishedMethods, StartOnTheSeamWherePublishedMetricFails) {
  // metric4 as printed switches branches at |cos t| < 1e-6 and divides by nu_in ~ cos t (spec section 3).
  // Starting exactly at t = pi/2 the difference quotients straddle that branch: pinned outcomes.
  const InitialState start =
      initialStateFromChart(specChain, Eigen::Vector2d(0.3, M_PI / 2), Eigen::Vector2d(0.5, 0.7));
  Trajectory adaptive(specChain, start, testing::config("christoffel-fd", "dopri5", 1e-10));
  EXPECT_FALSE(adaptive.sampleAt(1.0));
  ASSERT_TRUE(adaptive.stop());
  EXPECT_EQ(adaptive.stop()->reason, StopReason::StepSizeCollapse);
  EXPECT_EQ(adaptive.stop()->time, 0.0);

  RunConfig rk4 = testing::config("christoffel-fd", "rk4");
  rk4.step = 0.01;
  Trajectory demo(specChain, start, rk4);
  EXPECT_FALSE(demo.sampleAt(1.0));
  ASSERT_TRUE(demo.stop());
  EXPECT_EQ(demo.stop()->reason, StopReason::EnergyBlowUp);  // the first RK4 step multiplies the energy ~3000-fold
  EXPECT_EQ(demo.stop()->time, 0.0);

  // The same start is harmless for the exact method and for embedded-fd.
  for (const std::string method : {"christoffel", "embedded-fd"}) {
    Trajectory fine(specChain, start, testing::config(method, "dopri5", 1e-10));
    EXPECT_TRUE(fine.sampleAt(5.0)) << method;
  }
}

}  // namespace
}  // namespace sl
