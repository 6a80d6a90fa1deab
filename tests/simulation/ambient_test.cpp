// The chart-free ambient method: its O(n) constraint algebra against dense linear algebra, and its runs
// against the intrinsic methods for other n, other masses and through a pole.
#include <gtest/gtest.h>

#include <iostream>
#include <random>

#include "linkage/chart.hpp"
#include "linkage/kinetic_metric.hpp"
#include "linkage/sphere_coordinates.hpp"
#include "simulation/ambient_system.hpp"
#include "simulation/constraint_solver.hpp"
#include "simulation/initial_state.hpp"
#include "simulation/trajectory.hpp"
#include "support.hpp"

namespace sl {
namespace {

Chain massiveChain(int rods, double L) {
  Chain chain = Chain::uniform(rods, L);
  for (int j = 0; j < rods - 1; ++j) chain.hingeMasses(j) = 0.6 + 0.45 * j;
  for (int k = 0; k < rods; ++k) chain.rodMasses(k) = 0.3 + 0.2 * (k % 2);
  return chain;
}

// x = M^-1 G^T (G M^-1 G^T)^-1 r with dense matrices.
Eigen::VectorXd denseCorrection(const Chain& chain, const Eigen::Matrix2Xd& hinges, const Eigen::VectorXd& r) {
  const int n = chain.rods;
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(n, 2 * (n - 1));
  for (int k = 0; k < n; ++k) {  // rod k joins p_k and p_(k+1) (0-based), p_0 = 0, p_n = (L, 0)
    const Eigen::Vector2d start = k == 0 ? Eigen::Vector2d::Zero() : Eigen::Vector2d(hinges.col(k - 1));
    const Eigen::Vector2d end = k == n - 1 ? Eigen::Vector2d(chain.baseLength, 0) : Eigen::Vector2d(hinges.col(k));
    const Eigen::Vector2d d = end - start;
    if (k < n - 1) G.block<1, 2>(k, 2 * k) = d.transpose();
    if (k > 0) G.block<1, 2>(k, 2 * (k - 1)) = -d.transpose();
  }
  const Eigen::MatrixXd Minv = stackedMassMatrix(chain).inverse();
  return Minv * G.transpose() * (G * Minv * G.transpose()).ldlt().solve(r);
}

TEST(ConstraintSolver, MatchesDenseLinearAlgebraWithAndWithoutRodMasses) {
  std::mt19937 rng(3);
  std::normal_distribution<double> normal;
  for (int rods : {3, 4, 7})
    for (const Chain& chain : {Chain::uniform(rods, rods - 0.5), massiveChain(rods, rods - 0.5)}) {
      Eigen::VectorXd x(rods - 1), r(rods);
      for (Eigen::Index i = 0; i < x.size(); ++i) x(i) = normal(rng);
      for (Eigen::Index i = 0; i < r.size(); ++i) r(i) = normal(rng);
      const Eigen::Matrix2Xd hinges = hingePositionsAt(chain, x.normalized());
      ConstraintSolver solver(chain);
      Eigen::Matrix2Xd correction;
      solver.solve(hinges, r, correction);
      const Eigen::VectorXd expected = denseCorrection(chain, hinges, r);
      EXPECT_LT((Eigen::Map<const Eigen::VectorXd>(correction.data(), correction.size()) - expected).norm(),
                1e-12 * (1 + expected.norm()))
          << rods << " rods, rod masses " << chain.hasRodMass();
    }
}

// Class 5 of the fourth hostile round: a step that overflowed handed the solver non-finite hinges, whose NaN pivots
// read as "every rod on one line" for a chain nowhere near a line. Non-finite input is its own failure now.
TEST(ConstraintSolver, NonFiniteInputIsNotALossOfRank) {
  const Chain chain = Chain::uniform(4, 3.0);
  Eigen::VectorXd x(3);
  x << 0.3, 0.5, 0.8;
  const Eigen::Matrix2Xd hinges = hingePositionsAt(chain, x.normalized());
  ConstraintSolver solver(chain);
  Eigen::Matrix2Xd correction;
  EXPECT_NO_THROW(solver.solve(hinges, Eigen::VectorXd::Ones(4), correction));
  Eigen::Matrix2Xd overflowed = hinges;
  overflowed(0, 1) = INFINITY;
  EXPECT_THROW(solver.solve(overflowed, Eigen::VectorXd::Ones(4), correction), NonFiniteConstraintData);
  EXPECT_THROW(solver.solve(hinges, Eigen::VectorXd::Constant(4, NAN), correction), NonFiniteConstraintData);
}

// Runs every exact method from one start and compares hinge positions over [0, T].
void crossCheck(const Chain& chain, const InitialState& start, double T, double tolerance, double allowed) {
  Trajectory ambient(chain, start, testing::config("ambient", "bulirsch-stoer", 1e-13));
  Trajectory christoffel(chain, start, testing::config("christoffel", "dopri5", tolerance));
  Trajectory embedded(chain, start, testing::config("embedded", "dopri5", tolerance));
  const std::vector<double> times = testing::evenTimes(T, 40);
  double worst = 0, drift = 0, rod = 0;
  for (double t : times) {
    const auto a = ambient.sampleAt(t), c = christoffel.sampleAt(t), e = embedded.sampleAt(t);
    ASSERT_TRUE(a && c && e) << "a run stopped before t = " << t;
    worst =
        std::max({worst, (a->hinges - c->hinges).cwiseAbs().maxCoeff(), (a->hinges - e->hinges).cwiseAbs().maxCoeff()});
    drift = std::max({drift, a->relativeEnergyDrift, c->relativeEnergyDrift, e->relativeEnergyDrift});
    rod = std::max({rod, a->rodLengthError, c->rodLengthError, e->rodLengthError});
  }
  std::cout << chain.rods << " rods, rod masses " << chain.hasRodMass() << ": max hinge difference " << worst
            << ", energy drift " << drift << ", rod error " << rod << "\n";
  EXPECT_LT(worst, allowed);
  EXPECT_LT(drift, 1e-9);
  EXPECT_LT(rod, 1e-11);
}

TEST(Ambient, AgreesWithIntrinsicMethodsWithRodMassesAndUnequalHingeMasses) {
  const Chain chain = massiveChain(4, 3.1);
  crossCheck(chain, testing::genericStart(chain), 20.0, 1e-12, 1e-9);
}

TEST(Ambient, AgreesWithIntrinsicMethodsForThreeFiveAndSixRods) {
  for (int rods : {3, 5, 6}) {
    const Chain chain = rods == 5 ? massiveChain(5, 3.7) : Chain::uniform(rods, rods - 0.7);
    Eigen::VectorXd point = Eigen::VectorXd::LinSpaced(rods - 1, 0.3, 1.1), direction(rods - 1);
    for (int i = 0; i < rods - 1; ++i) direction(i) = std::cos(1.7 * i + 0.4);
    crossCheck(chain, initialStateFromDrag(chain, point, direction, true), rods == 6 ? 8.0 : 20.0, 1e-12, 1e-9);
  }
}

TEST(Ambient, AllExactMethodsPassThroughThePoleOfTheSpecsChart) {
  const Chain chain = Chain::uniform(4, 3.0);
  const InitialState start = testing::poleCrossingStart(chain, 2.0, Eigen::Vector3d(1.0, 0.4, 0.0));
  {  // the construction really reaches the pole of chart 0
    Trajectory check(chain, start, testing::config("ambient", "bulirsch-stoer", 1e-13));
    EXPECT_LT(sphereChartRegularity(check.sampleAt(2.0)->spherePoint, 0), 1e-9);
  }
  crossCheck(chain, start, 20.0, 1e-12, 1e-9);
}

TEST(Ambient, SamplesExactlyAtThePoleAreFinite) {
  const Chain chain = Chain::uniform(4, 3.0);
  InitialState atPole{Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0.6, -0.8, 0)};
  Trajectory run(chain, atPole, testing::config("ambient"));
  const auto s = run.sampleAt(0.0);
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->coords.allFinite() && s->rates.allFinite() && s->hinges.allFinite() && s->sphereVelocity.allFinite());
  EXPECT_NEAR(std::abs(s->coords(0)), M_PI / 2, 1e-15);
}

}  // namespace
}  // namespace sl

namespace sl {
namespace {

TEST(Ambient, CheapChartAngleMatchesTheChartInverse) {
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  for (int rods : {3, 4, 5, 8})
    for (int trial = 0; trial < 50; ++trial) {
      const Chain chain = Chain::uniform(rods, rods - 0.4 - 0.05 * (trial % 3));
      Eigen::VectorXd x(rods - 1);
      for (Eigen::Index i = 0; i < x.size(); ++i) x(i) = normal(rng);
      x.normalize();
      const double expected = coordinatesFromSpherePoint(x, 0.0)(rods - 3);
      EXPECT_NEAR(chartZeroAngleForUnwrapping(chain, hingePositionsAt(chain, x), 0.0), expected, 1e-7)
          << rods << " rods";
    }
}

}  // namespace
}  // namespace sl

// Long and slack chains: starts by hinges, the arc shape, the projection onto the constraints, the
// invariants of a slack chain's motion, and the stop where the rod constraints lose rank.
namespace sl {
namespace {

TEST(HingeStarts, TheArcPutsEveryRodAtLengthOneBetweenThePins) {
  for (const auto& [rods, L] : {std::pair{4, 3.5}, std::pair{10, 5.0}, std::pair{200, 150.0}, std::pair{1000, 990.0}}) {
    const Eigen::Matrix2Xd hinges = arcHinges(rods, L);
    Chain chain = Chain::uniform(rods, L);
    EXPECT_LT(rodLengthError(chain, hinges), 1e-9) << rods;
    EXPECT_LT(hinges.row(1).maxCoeff(), 0.0) << "sags below the pins";
  }
}

TEST(HingeStarts, GivenPointsAreMovedOntoTheConstraintsAndTheMoveIsReported) {
  const Chain chain = Chain::uniform(5, 2.5);  // slack: L <= n-2
  InitialSpec spec;
  spec.kind = InitialSpec::Kind::Hinges;
  spec.hinges = arcHinges(5, 2.5);
  spec.hinges(1, 2) += 0.01;  // off the constraints
  spec.pushHinge = 2;
  spec.pushVelocity = Eigen::Vector2d(0.0, 1.0);
  StartAdjustment moved;
  const InitialState start = initialStateFromHinges(chain, spec, moved);
  EXPECT_LT(rodLengthError(chain, start.hinges), 1e-13);
  EXPECT_GT(moved.positions, 1e-3);
  EXPECT_LT(moved.positions, 0.02);
  // Velocities tangent to the constraints: each rod's length does not change to first order.
  Eigen::Matrix2Xd rods, relative;
  ConstraintSolver(chain).rodVectors(start.hinges, rods);
  ConstraintSolver::relativeVelocities(start.hingeVelocities, relative);
  EXPECT_LT(rods.cwiseProduct(relative).colwise().sum().cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_GT(moved.velocities, 0.0);  // the push had a part along the rods
  // Exactly on the arc with a tangent push nothing moves.
  InitialSpec arc = spec;
  arc.shape = InitialSpec::Shape::Arc;
  StartAdjustment first, none;
  arc.hingeVelocities = initialStateFromHinges(chain, arc, first).hingeVelocities;
  initialStateFromHinges(chain, arc, none);
  EXPECT_LT(none.positions, 1e-12);
  EXPECT_LT(none.velocities, 1e-12);
}

TEST(SlackChains, KeepEnergyAndRodLengthsAndHaveNoSphere) {
  for (const int rods : {6, 50}) {
    const Chain chain = Chain::uniform(rods, rods / 2.0);
    InitialSpec spec;
    spec.kind = InitialSpec::Kind::Hinges;
    spec.shape = InitialSpec::Shape::Arc;
    spec.pushSeed = 3;
    StartAdjustment moved;
    const InitialState start = initialStateFromHinges(chain, spec, moved);
    RunConfig config = testing::config("ambient", "rkf78", 1e-12);
    Trajectory run(chain, start, config);
    for (const double t : testing::evenTimes(5.0, 10)) {
      const std::optional<Sample> s = run.sampleAt(t);
      ASSERT_TRUE(s) << run.stop()->detail();
      EXPECT_EQ(s->spherePoint.size(), 0);
      EXPECT_EQ(s->coords.size(), 0);
      EXPECT_LT(s->relativeEnergyDrift, 1e-9);
      EXPECT_LT(s->rodLengthError, 1e-10);
    }
    EXPECT_THROW(Trajectory(chain, start, testing::config("christoffel")), std::invalid_argument);
  }
}

TEST(SlackChains, ConstraintsLoseRankWhereEveryRodLiesOnOneLine) {
  // 4 rods, L = 2, folded flat: (0,0) (1,0) (2,0) (1,0) (2,0).
  const Chain chain = Chain::uniform(4, 2.0);
  Eigen::Matrix2Xd flat(2, 3), correction;
  flat << 1, 2, 1, 0, 0, 0;
  ConstraintSolver solver(chain);
  EXPECT_THROW(solver.solve(flat, Eigen::VectorXd::Ones(4), correction), ConstraintRankLoss);
  Eigen::Matrix2Xd bent = flat;
  bent(1, 1) = 1e-3;  // lifted a little: solvable
  EXPECT_NO_THROW(solver.solve(bent, Eigen::VectorXd::Ones(4), correction));
  // A start there is refused as a start, with the reason.
  InitialSpec spec;
  spec.kind = InitialSpec::Kind::Hinges;
  spec.hinges = flat;
  spec.pushHinge = 2;
  spec.pushVelocity = Eigen::Vector2d(0, 1);
  StartAdjustment moved;
  try {
    initialStateFromHinges(chain, spec, moved);
    ADD_FAILURE() << "a start on a fold was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("one line"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace sl
