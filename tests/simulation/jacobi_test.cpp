// Jacobi fields and conjugate points against independent routes: the linearisation against central
// differences of the motion's own vector field; the field against central differences of two geodesics of a
// fan launched +-delta apart; for 4 rods, the field and its zeros against the scalar Jacobi equation
// y'' + K(gamma(t)) y = 0 with the exact Gaussian curvature of geometry/curvature.hpp.
#include <cmath>

#include <gtest/gtest.h>

#include "geometry/curvature.hpp"
#include "simulation/ambient_system.hpp"
#include "simulation/family.hpp"
#include "simulation/jacobi_system.hpp"
#include "simulation/trajectory.hpp"
#include "support.hpp"

namespace sl {
namespace {

using testing::config;
using testing::genericStart;

RunConfig jacobiConfig(double tolerance = 1e-13) {
  RunConfig c = config("ambient", "rkf78", tolerance);
  c.jacobi = true;
  return c;
}

InitialState unitSpeed(const Chain& chain, InitialState start) {
  start.sphereVelocity /= std::sqrt(speedSquared(chain, start));
  return start;
}

Chain massiveChain() {
  Chain chain = Chain::uniform(4, 3.1);
  chain.hingeMasses = Eigen::Vector3d(1.0, 2.0, 0.5);
  chain.rodMasses = Eigen::Vector4d(0.5, 1.0, 0.0, 2.0);
  return chain;
}

// The variation part of the derivative is the derivative of the motion's vector field along the variation.
TEST(JacobiSystem, LinearisationIsTheDerivativeOfTheMotionsVectorField) {
  for (const Chain& chain : {Chain::uniform(4, 3.0), massiveChain(), Chain::uniform(6, 4.6)}) {
    SCOPED_TRACE("n = " + std::to_string(chain.rods) + (chain.rodMasses.sum() > 0 ? ", massive rods" : ""));
    const InitialState start =
        chain.rods == 4 ? genericStart(chain)
                        : initialStateFromChart(chain, Eigen::Vector4d(0.2, -0.3, 0.4, 0.5), Eigen::Vector4d(0.3, 0.1, -0.2, 0.4));
    JacobiSystem jacobi(chain, start, 1e-14);
    AmbientSystem motion(chain, start, 1e-14);
    // A state along the way with non-zero variations: step the combined system a little by Euler.
    State y = jacobi.initialState(), dydt;
    for (int k = 0; k < 50; ++k) {
      jacobi.derivative(y, dydt);
      for (std::size_t i = 0; i < y.size(); ++i) y[i] += 0.01 * dydt[i];
    }
    jacobi.derivative(y, dydt);
    const std::size_t block = static_cast<std::size_t>(4 * chain.hingeCount());
    for (int field = 0; field < jacobi.fieldCount(); ++field) {
      const std::size_t offset = block * static_cast<std::size_t>(field + 1);
      const double eps = 1e-6;
      State plus(y.begin(), y.begin() + long(block)), minus = plus, fPlus, fMinus;
      for (std::size_t i = 0; i < block; ++i) {
        plus[i] += eps * y[offset + i];
        minus[i] -= eps * y[offset + i];
      }
      motion.derivative(plus, fPlus);
      motion.derivative(minus, fMinus);
      double worst = 0, scale = 0;
      for (std::size_t i = 0; i < block; ++i) {
        worst = std::max(worst, std::abs((fPlus[i] - fMinus[i]) / (2 * eps) - dydt[offset + i]));
        scale = std::max(scale, std::abs(dydt[offset + i]));
      }
      EXPECT_LT(worst, 1e-7 * scale) << "field " << field;
    }
  }
}

// Cross-check (1): the field against central differences of two fan members launched +-delta apart.
TEST(JacobiField, EqualsTheSpreadOfAFanToTheDifferencesAccuracy) {
  const Chain chain = massiveChain();
  const InitialState start = unitSpeed(chain, genericStart(chain));
  const double delta = 2e-5;
  const std::vector<InitialState> pair =
      familyStarts(chain, start, {FamilyKind::Fan, 2, 2 * delta}, config("ambient", "rkf78", 1e-14));
  Trajectory withField(chain, start, jacobiConfig());
  Trajectory minus(chain, pair[0], config("ambient", "rkf78", 1e-14)), plus(chain, pair[1], config("ambient", "rkf78", 1e-14));
  const AmbientMassMatrix mass = ambientMassMatrix(chain);
  auto massNorm = [&](const Eigen::Matrix2Xd& a) { return std::sqrt(2.0 * kineticEnergy(mass, a)); };
  double worst = 0;
  for (const double t : testing::evenTimes(8.0, 40)) {
    if (t == 0) continue;
    const Sample s = *withField.sampleAt(t), a = *minus.sampleAt(t), b = *plus.sampleAt(t);
    Eigen::Matrix2Xd spread = (b.hinges - a.hinges) / (2 * delta);  // ~ J(t), J'(0) the g-unit normal
    const double along = mass.innerProduct(spread, s.hingeVelocities);  // <spread, v>_M
    spread -= along / (2.0 * s.energy) * s.hingeVelocities;
    ASSERT_TRUE(s.jacobi);
    worst = std::max(worst, std::abs(*s.jacobi - massNorm(spread)));
  }
  // The difference's own error is (delta^2 / 6) d^3q/d angle^3: 5.7e-7 at delta = 1e-4, 2.3e-8 at 2e-5 (measured).
  EXPECT_LT(worst, 1e-7);
}

// Cross-check (2): for 4 rods J_perp = y N with y'' + K(gamma(t)) y = 0 (unit speed), y(0) = 0, y'(0) = 1. The
// scalar equation is integrated by RK4 (h = 1e-3) along the geodesic with K from the curvature module, and its
// zeros (Hermite interpolation) are the conjugate points.
TEST(JacobiField, FourRodsAgreesWithTheScalarJacobiEquationAndItsZeros) {
  for (const Chain& chain : {Chain::uniform(4, 3.0), massiveChain()}) {
    SCOPED_TRACE(chain.rodMasses.sum() > 0 ? "massive rods" : "unit hinge masses");
    const InitialState start = unitSpeed(chain, genericStart(chain));
    const ConfigurationSurface surface(chain);
    Trajectory geodesic(chain, start, config("ambient", "rkf78", 1e-13));
    Trajectory withField(chain, start, jacobiConfig());
    const double h = 1e-3, end = 7.0;
    auto curvature = [&](double t) {
      return surface.gaussianCurvature(Eigen::Vector3d(geodesic.sampleAt(t)->spherePoint));
    };
    double y = 0, dy = 1, kAt = curvature(0.0), worst = 0, scale = 0;
    std::vector<double> zeros;
    for (int step = 0; step * h < end - 1e-12; ++step) {
      const double t = step * h;
      const double kMid = curvature(t + 0.5 * h), kEnd = curvature(t + h);
      // y'' = -K y as a first-order system, classical RK4.
      const double k1y = dy, k1v = -kAt * y;
      const double k2y = dy + 0.5 * h * k1v, k2v = -kMid * (y + 0.5 * h * k1y);
      const double k3y = dy + 0.5 * h * k2v, k3v = -kMid * (y + 0.5 * h * k2y);
      const double k4y = dy + h * k3v, k4v = -kEnd * (y + h * k3y);
      const double yNext = y + h / 6 * (k1y + 2 * k2y + 2 * k3y + k4y);
      const double dyNext = dy + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
      if (step > 0 && (y > 0) != (yNext > 0)) {  // a zero inside: Newton on the cubic Hermite interpolant
        double s = y / (y - yNext);
        for (int it = 0; it < 20; ++it) {
          const double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
          const double h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
          const double value = h00 * y + h10 * h * dy + h01 * yNext + h11 * h * dyNext;
          const double slope = (6 * s * s - 6 * s) * y + (3 * s * s - 4 * s + 1) * h * dy + (-6 * s * s + 6 * s) * yNext +
                               (3 * s * s - 2 * s) * h * dyNext;
          s -= value / slope;
        }
        zeros.push_back(t + s * h);
      }
      y = yNext, dy = dyNext, kAt = kEnd;
      if ((step + 1) % 250 == 0) {
        const Sample sample = *withField.sampleAt((step + 1) * h);
        worst = std::max(worst, std::abs(*sample.jacobi - std::abs(y)));
        scale = std::max(scale, std::abs(y));
      }
    }
    EXPECT_LT(worst, 1e-9 * std::max(1.0, scale));
    std::vector<double> found;
    for (const double t : withField.conjugateTimes())
      if (t <= end) found.push_back(t);
    ASSERT_EQ(found.size(), zeros.size());
    ASSERT_GE(found.size(), 1u);
    for (std::size_t i = 0; i < zeros.size(); ++i) EXPECT_NEAR(found[i], zeros[i], 1e-8) << "conjugate point " << i;
  }
}

// A conjugate point is accepted only where det G is zero to rounding. At the true zeros a run finds (4 rods, where
// det G = |J_perp|^2), det G is measured far below the acceptance's bound, 1e-12 of its largest value; a dip that
// stays a millionth of that above zero (|J_perp| down to 3e-5 of its largest, a near miss) is not a zero and must
// not be taken for one, nor must a dip to 1e-9, which an acceptance loosened a millionfold would take.
TEST(JacobiField, AcceptsOnlyZerosToRoundingAsConjugatePoints) {
  const Chain chain = Chain::uniform(4, 3.0);
  const InitialState start = unitSpeed(chain, genericStart(chain));
  Trajectory run(chain, start, jacobiConfig());
  double largest = 0;
  for (int k = 1; k <= 700; ++k) largest = std::max(largest, std::pow(*run.sampleAt(0.01 * k)->jacobi, 2));
  std::vector<double> found;
  for (const double t : run.conjugateTimes())
    if (t <= 7.0) found.push_back(t);
  ASSERT_GE(found.size(), 1u);
  Trajectory again(chain, start, jacobiConfig());
  for (const double t : found) {
    const double atZero = std::pow(*again.sampleAt(t)->jacobi, 2);
    EXPECT_LT(atZero, 1e-18 * largest) << "det G at the conjugate point t = " << t;
    EXPECT_TRUE(isConjugateMinimum(atZero, largest));
  }
  EXPECT_TRUE(isConjugateMinimum(0.0, largest));
  EXPECT_TRUE(isConjugateMinimum(1e-13 * largest, largest));
  EXPECT_FALSE(isConjugateMinimum(1e-9 * largest, largest)) << "a near miss taken for a conjugate point";
  EXPECT_FALSE(isConjugateMinimum(1e-11 * largest, largest)) << "a near miss taken for a conjugate point";
  EXPECT_FALSE(isConjugateMinimum(1e-3 * largest, largest));
}

// The motion of a run with Jacobi fields is the run's motion: the same geodesic to the tolerance.
TEST(JacobiField, DoesNotChangeTheMotion) {
  const Chain chain = Chain::uniform(5, 3.7);
  const InitialState start =
      initialStateFromChart(chain, Eigen::Vector3d(0.2, 0.4, -0.3), Eigen::Vector3d(0.5, -0.2, 0.3));
  Trajectory plain(chain, start, config("ambient", "rkf78", 1e-12));
  RunConfig c = config("ambient", "rkf78", 1e-12);
  c.jacobi = true;
  Trajectory withField(chain, start, c);
  EXPECT_LT(testing::maxHingeDistance(plain, withField, testing::evenTimes(10.0, 50)), 1e-9);
  // A matrix Jacobi field (m = 2) is singular at each conjugate point it reports: its size there is a
  // millionth of its size a little before.
  ASSERT_FALSE(withField.conjugateTimes().empty());
  for (const double t : withField.conjugateTimes()) {
    Trajectory again(chain, start, c);
    // Its size is (det G)^(1/4) and det G vanishes quadratically there (rank 1 lost): compare det G itself.
    const double before = *again.sampleAt(t - 0.3)->jacobi, at = *again.sampleAt(t)->jacobi;
    EXPECT_LT(std::pow(at / before, 4), 1e-12) << "t = " << t;
  }
}

// The step control reads the motion only and the fields ride along on its steps: the motion of a run with Jacobi
// fields is the motion of the run alone to the last bit, for every integrator a Jacobi run may use. (Were the
// fields watched too, the steps would differ and so would the motion, in its last digits: this test fails.)
TEST(JacobiField, LeavesTheMotionBitIdenticalForEveryIntegrator) {
  for (const int rods : {4, 6}) {
    const Chain chain = Chain::uniform(rods, rods - 1.0);
    const InitialState start = initialStateFromChart(chain, Eigen::VectorXd::LinSpaced(rods - 2, 0.3, 0.2),
                                                     Eigen::VectorXd::LinSpaced(rods - 2, 0.5, 0.7));
    for (const char* integrator : {"dopri5", "rkf78", "bulirsch-stoer", "rk4"}) {
      SCOPED_TRACE(std::to_string(rods) + " rods, " + integrator);
      const RunConfig alone = config("ambient", integrator, 1e-11);
      RunConfig with = alone;
      with.jacobi = true;
      Trajectory plain(chain, start, alone), withField(chain, start, with);
      int compared = 0;
      for (const double t : testing::evenTimes(6.0, 37)) {
        const std::optional<Sample> a = plain.sampleAt(t), b = withField.sampleAt(t);
        ASSERT_TRUE(a && b);
        ASSERT_TRUE(b->jacobi);
        for (Eigen::Index i = 0; i < a->hinges.size(); ++i) {
          EXPECT_EQ(a->hinges.data()[i], b->hinges.data()[i]) << "t = " << t << ", hinge coordinate " << i;
          EXPECT_EQ(a->hingeVelocities.data()[i], b->hingeVelocities.data()[i]) << "t = " << t << ", velocity " << i;
        }
        ++compared;
      }
      EXPECT_EQ(compared, 38);
      EXPECT_EQ(plain.steps(), withField.steps());
      EXPECT_GT(plain.steps(), 10);
    }
  }
}

TEST(JacobiField, RefusesMethodsWithoutALinearisationAndThreeRods) {
  RunConfig c = config("christoffel");
  c.jacobi = true;
  EXPECT_THROW(Trajectory(Chain::uniform(4, 3.0), genericStart(Chain::uniform(4, 3.0)), c), std::invalid_argument);
  const InitialState onCircle{Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)};
  EXPECT_THROW(Trajectory(Chain::uniform(3, 2.0), onCircle, jacobiConfig()), std::invalid_argument);
}

}  // namespace
}  // namespace sl
