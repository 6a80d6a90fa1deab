// Families of geodesics: the members' starts against their definitions in the kinetic metric, the
// invariants of every member's motion, and a fan launched at a pole of the chart integrated through it.
#include <cmath>

#include <gtest/gtest.h>

#include "simulation/family.hpp"
#include "simulation/initial_state.hpp"
#include "simulation/trajectory.hpp"
#include "support.hpp"

namespace sl {
namespace {

using testing::config;
using testing::genericStart;

// A chain whose metric is far from the round one, so a Euclidean frame would fail every check below.
Chain massiveChain() {
  Chain chain = Chain::uniform(4, 3.2);
  chain.hingeMasses = Eigen::Vector3d(1.0, 3.0, 0.5);
  chain.rodMasses = Eigen::Vector4d(0.5, 2.0, 0.0, 1.0);
  return chain;
}

double gAngle(const Chain& chain, const Eigen::VectorXd& x, const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  const double uu = kineticInner(chain, x, u, u), vv = kineticInner(chain, x, v, v);
  return std::acos(std::clamp(kineticInner(chain, x, u, v) / std::sqrt(uu * vv), -1.0, 1.0));
}

TEST(KineticInner, IsTheMetricOfTheRunsAndSymmetric) {
  const Chain chain = massiveChain();
  const InitialState start = genericStart(chain);
  const Eigen::VectorXd& x = start.spherePoint;
  Eigen::VectorXd w = Eigen::Vector3d(0.3, -1.0, 0.4);
  w -= x * x.dot(w);
  EXPECT_NEAR(kineticInner(chain, x, start.sphereVelocity, start.sphereVelocity), speedSquared(chain, start), 1e-13);
  EXPECT_NEAR(kineticInner(chain, x, start.sphereVelocity, w), kineticInner(chain, x, w, start.sphereVelocity), 1e-13);
  const std::vector<Eigen::VectorXd> frame = orthonormalTangentFrame(chain, x, start.sphereVelocity);
  ASSERT_EQ(frame.size(), 2u);
  EXPECT_NEAR(kineticInner(chain, x, frame[0], frame[0]), 1.0, 1e-13);
  EXPECT_NEAR(kineticInner(chain, x, frame[1], frame[1]), 1.0, 1e-13);
  EXPECT_NEAR(kineticInner(chain, x, frame[0], frame[1]), 0.0, 1e-13);
  EXPECT_NEAR(gAngle(chain, x, frame[0], start.sphereVelocity), 0.0, 1e-7);
  // The Euclidean frame is not g-orthonormal on this chain: the check above is not vacuous.
  EXPECT_GT(std::abs(kineticInner(chain, x, w / w.norm(), w / w.norm()) - 1.0), 0.1);
}

TEST(Family, FanMembersShareThePointAndSpeedAndSpreadEvenlyInTheMetric) {
  const Chain chain = massiveChain();
  const InitialState start = genericStart(chain);
  FamilySpec fan{FamilyKind::Fan, 9, 0.8};
  const std::vector<InitialState> members = familyStarts(chain, start, fan, config("ambient"));
  ASSERT_EQ(members.size(), 9u);
  const double speed2 = speedSquared(chain, start);
  for (std::size_t k = 0; k < members.size(); ++k) {
    EXPECT_EQ(members[k].spherePoint, start.spherePoint);
    EXPECT_NEAR(speedSquared(chain, members[k]), speed2, 1e-12 * speed2);
    // Angle from the run's direction: -0.4 .. 0.4 in steps of 0.1, in the kinetic metric.
    EXPECT_NEAR(gAngle(chain, start.spherePoint, members[k].sphereVelocity, start.sphereVelocity),
                std::abs(-0.4 + 0.1 * double(k)), 1e-7);
    if (k > 0) {
      EXPECT_NEAR(gAngle(chain, start.spherePoint, members[k - 1].sphereVelocity, members[k].sphereVelocity), 0.1, 1e-7);
    }
  }
  EXPECT_NEAR((members[4].sphereVelocity - start.sphereVelocity).norm(), 0.0, 1e-12);  // the middle one is the run
}

TEST(Family, ParallelMembersLieOnTheOrthogonalGeodesicAndMoveOrthogonallyToIt) {
  const Chain chain = massiveChain();
  const InitialState start = genericStart(chain);
  const RunConfig exact = config("ambient", "rkf78", 1e-13);
  FamilySpec family{FamilyKind::Parallel, 5, 0.6};
  const std::vector<InitialState> members = familyStarts(chain, start, family, exact);
  ASSERT_EQ(members.size(), 5u);
  EXPECT_NEAR((members[2].spherePoint - start.spherePoint).norm(), 0.0, 1e-15);
  const std::vector<Eigen::VectorXd> frame = orthonormalTangentFrame(chain, start.spherePoint, start.sphereVelocity);
  const double speed2 = speedSquared(chain, start);
  for (std::size_t k = 0; k < members.size(); ++k) {
    const double offset = -0.3 + 0.15 * double(k);
    // Independently: the unit-speed geodesic across, integrated by another method, reaches the member's point.
    Trajectory across(chain, {start.spherePoint, offset < 0 ? Eigen::VectorXd(-frame[1]) : frame[1]},
                      config("christoffel", "rkf78", 1e-13));
    const Sample at = *across.sampleAt(std::abs(offset));
    EXPECT_NEAR((at.spherePoint - members[k].spherePoint).norm(), 0.0, 1e-9) << "member " << k;
    EXPECT_NEAR(kineticInner(chain, at.spherePoint, at.sphereVelocity, members[k].sphereVelocity), 0.0, 1e-8);
    EXPECT_NEAR(speedSquared(chain, members[k]), speed2, 1e-12 * speed2);
  }
}

TEST(Family, CloudIsSmallDeterministicAndDependsOnTheSeed) {
  const Chain chain = Chain::uniform(5, 4.0);
  const InitialState start =
      initialStateFromChart(chain, Eigen::Vector3d(0.2, 0.4, -0.3), Eigen::Vector3d(0.5, -0.2, 0.3));
  FamilySpec cloud{FamilyKind::Cloud, 12, 0.2, 1e-6, 42};
  const std::vector<InitialState> a = familyStarts(chain, start, cloud, config("ambient"));
  const std::vector<InitialState> again = familyStarts(chain, start, cloud, config("ambient"));
  cloud.seed = 43;
  const std::vector<InitialState> other = familyStarts(chain, start, cloud, config("ambient"));
  ASSERT_EQ(a.size(), 12u);
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].spherePoint, again[k].spherePoint);
    EXPECT_EQ(a[k].sphereVelocity, again[k].sphereVelocity);
    EXPECT_NE(a[k].spherePoint, other[k].spherePoint);
    const double moved = (a[k].spherePoint - start.spherePoint).norm();
    EXPECT_GT(moved, 1e-8);
    EXPECT_LT(moved, 1.01e-6);
    EXPECT_LT((a[k].sphereVelocity - start.sphereVelocity).norm(), 3e-6 * start.sphereVelocity.norm());
  }
}

// Cross-check: every member of a fan keeps its energy and its rod lengths.
TEST(Family, EveryMemberKeepsItsEnergyAndRodLengths) {
  const Chain chain = massiveChain();
  const InitialState start = genericStart(chain);
  for (const RunConfig& run : {config("ambient", "rkf78", 1e-12), config("christoffel", "dopri5", 1e-11)}) {
    SCOPED_TRACE(nameOf(run.method));
    for (const InitialState& member : familyStarts(chain, start, {FamilyKind::Fan, 8, 1.2}, run)) {
      Trajectory motion(chain, member, run);
      for (const double t : testing::evenTimes(10.0, 20)) {
        const std::optional<Sample> sample = motion.sampleAt(t);
        ASSERT_TRUE(sample) << "stopped at " << t;
        EXPECT_LT(std::abs(sample->relativeEnergyDrift), 1e-8);
        EXPECT_LT(sample->rodLengthError, 1e-10);
      }
    }
  }
}

// Cross-check (4): a fan launched at a pole of the spec's chart (phi = pi/2, where every member starts on the
// chart's singular point) is integrated through it by the chart-switching and the chart-free methods, and the
// two agree member by member.
TEST(Family, FanAtAChartPoleIsIntegratedThroughItByTheExactAndAmbientMethods) {
  const Chain chain = Chain::uniform(4, 3.0);
  const InitialState start{Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0.6, 0.3, 0)};
  const FamilySpec fan{FamilyKind::Fan, 7, 2.0};
  const RunConfig exact = config("christoffel", "rkf78", 1e-13), ambient = config("ambient", "rkf78", 1e-13);
  const std::vector<InitialState> members = familyStarts(chain, start, fan, ambient);
  for (std::size_t k = 0; k < members.size(); ++k) {
    Trajectory a(chain, members[k], exact), b(chain, members[k], ambient);
    EXPECT_LT(testing::maxHingeDistance(a, b, testing::evenTimes(6.0, 30)), 1e-8) << "member " << k;
  }
}

TEST(Family, MembersShareTheRunsSettingsButNotItsJacobiFields) {
  const Chain chain = Chain::uniform(4, 3.0);
  RunConfig run = config("ambient", "rkf78", 1e-12);
  run.jacobi = true;
  std::vector<Trajectory> members = familyMembers(chain, genericStart(chain), {FamilyKind::Fan, 3, 0.4}, run);
  ASSERT_EQ(members.size(), 3u);
  Trajectory alone(chain, familyStarts(chain, genericStart(chain), {FamilyKind::Fan, 3, 0.4}, run)[0],
                   config("ambient", "rkf78", 1e-12));
  const Sample member = *members[0].sampleAt(2.0);
  EXPECT_FALSE(member.jacobi);
  EXPECT_EQ(member.hinges, alone.sampleAt(2.0)->hinges);  // the same integration, step for step
}

TEST(Family, RefusesWhatCannotBeAFamily) {
  const Chain chain = Chain::uniform(4, 3.0);
  const InitialState start = genericStart(chain);
  EXPECT_THROW(familyStarts(chain, start, {FamilyKind::Fan, 1, 0.2}, config("ambient")), std::invalid_argument);
  const Chain three = Chain::uniform(3, 2.0);
  const InitialState onCircle{Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)};
  EXPECT_THROW(familyStarts(three, onCircle, {FamilyKind::Fan, 4, 0.2}, config("ambient")), std::invalid_argument);
  EXPECT_EQ(familyStarts(three, onCircle, {FamilyKind::Cloud, 4, 0.2, 1e-3, 1}, config("ambient")).size(), 4u);
}

}  // namespace
}  // namespace sl
