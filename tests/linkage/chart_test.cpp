// The chart Psi^n_L and its inverse: rod lengths, round trips, seams and poles, n = 3..8.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "linkage/chart.hpp"

namespace sl {
namespace {

// Interior points of the valid L range for n rods, including both ends' neighbourhoods.
std::vector<double> baseLengths(int n) { return {n - 2 + 1e-3, n - 2 + 0.3, n - 1.0, n - 0.4, n - 1e-3}; }

Eigen::VectorXd randomUnit(std::mt19937& rng, int size) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd x(size);
  for (int i = 0; i < size; ++i) x(i) = normal(rng);
  return x.normalized();
}

TEST(Chart, RodLengthsAreOneOnDenseGridsIncludingSeamsAndPoles) {
  for (int n = 3; n <= 8; ++n)
    for (double L : baseLengths(n)) {
      const Chain chain = Chain::uniform(n, L);
      const int k = n - 2;
      std::vector<double> samples = {-M_PI / 2, M_PI / 2, -M_PI / 2 + 1e-12, M_PI / 2 - 1e-12, 0.0, 0.3, -1.1,
                                     2.5,       M_PI};
      for (int i = 0; i < 24; ++i) samples.push_back(-M_PI + 2 * M_PI * i / 24.0);
      for (double a : samples)
        for (double b : samples) {
          Eigen::VectorXd c = Eigen::VectorXd::Constant(k, 0.2);
          c(0) = a;
          c(k - 1) = (k == 1) ? a : b;
          const Eigen::Matrix2Xd p = hingePositions(chain, c);
          ASSERT_LE(rodLengthError(chain, p), 1e-14) << "n=" << n << " L=" << L << " c=" << c.transpose();
        }
    }
}

TEST(Chart, RodLengthsAreOneAtRandomSpherePointsAndExactlyAtPoles) {
  std::mt19937 rng(7);
  for (int n = 3; n <= 8; ++n)
    for (double L : baseLengths(n)) {
      const Chain chain = Chain::uniform(n, L);
      for (int i = 0; i < 200; ++i)
        ASSERT_LE(rodLengthError(chain, hingePositionsAt(chain, randomUnit(rng, n - 1))), 1e-14);
      for (int axis = 0; axis < n - 1; ++axis)
        for (double sign : {-1.0, 1.0}) {
          const Eigen::VectorXd x = sign * Eigen::VectorXd::Unit(n - 1, axis);
          const Eigen::Matrix2Xd p = hingePositionsAt(chain, x);
          ASSERT_TRUE(p.allFinite());
          ASSERT_LE(rodLengthError(chain, p), 1e-14) << "n=" << n << " axis " << axis;
        }
    }
}

TEST(Chart, MatchesTheSpecsFourRodFormulas) {
  // p3 = L - e^(i theta), p2 = p3 - p3hat e^(i theta_in), p1 = p2/2 + i nu p2 / (2|p2|), nu ~ sign(cos t).
  const double L = 3.0;
  const Chain chain = Chain::uniform(4, L);
  for (double phi : {-1.2, -0.3, 0.0, 0.7, 1.4})
    for (double t : {-2.8, -1.0, 0.0, 0.4, 1.3, 2.9}) {
      const double alpha = std::acos((L * L - 8) / (2 * L));
      const std::complex<double> p3 = L - std::polar(1.0, alpha * std::sin(phi));
      const double d = std::abs(p3);
      const double alphaIn = std::acos((d * d - 3) / (2 * d));
      const std::complex<double> p2 = p3 - (p3 / d) * std::polar(1.0, alphaIn * std::sin(t));
      const double r = std::abs(p2);
      const double nu = std::copysign(std::sqrt(4 - r * r), std::cos(t));
      const std::complex<double> p1 = p2 / 2.0 + std::complex<double>(0, nu / (2 * r)) * p2;
      const Eigen::Matrix2Xd p = hingePositions(chain, Eigen::Vector2d(phi, t));
      EXPECT_NEAR(p(0, 2), p3.real(), 1e-14);
      EXPECT_NEAR(p(1, 2), p3.imag(), 1e-14);
      EXPECT_NEAR(p(0, 1), p2.real(), 1e-13);
      EXPECT_NEAR(p(1, 1), p2.imag(), 1e-13);
      EXPECT_NEAR(p(0, 0), p1.real(), 1e-12);
      EXPECT_NEAR(p(1, 0), p1.imag(), 1e-12);
    }
}

TEST(Chart, FourRodRoundTripInChartCoordinatesAwayFromPoles) {
  for (double L : baseLengths(4)) {
    const Chain chain = Chain::uniform(4, L);
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; j <= 64; ++j) {
        const double phi = -1.45 + 2.9 * i / 40.0;  // |cos phi| >= 0.12
        const double t = -M_PI + 2 * M_PI * j / 64.0;
        const Eigen::Vector2d c(phi, t);
        const Eigen::VectorXd back = coordinatesFromHinges(chain, hingePositions(chain, c), t);
        ASSERT_NEAR(back(0), phi, 1e-13) << "L=" << L << " t=" << t;
        ASSERT_NEAR(back(1), t, 1e-13) << "L=" << L << " phi=" << phi;
      }
    // Exactly on the seams t = +-pi/2.
    for (double t : {M_PI / 2, -M_PI / 2}) {
      const Eigen::VectorXd back = coordinatesFromHinges(chain, hingePositions(chain, Eigen::Vector2d(0.4, t)), t);
      EXPECT_NEAR(back(0), 0.4, 1e-13);
      EXPECT_NEAR(back(1), t, 1e-13);
    }
  }
}

TEST(Chart, RoundTripOfTheSpherePointNearPoles) {
  // Near a pole the chart angle t is ill defined but the sphere point is not: the inverse reads the
  // pole distance off the inner chain's shape.
  const Chain chain = Chain::uniform(4, 3.0);
  for (double gap : {1e-4, 1e-8, 1e-12}) {
    const Eigen::Vector3d x = Eigen::Vector3d(gap * std::cos(0.7), gap * std::sin(0.7), 1.0).normalized();
    const Eigen::VectorXd back = spherePointFromHinges(chain, hingePositionsAt(chain, x));
    EXPECT_LE((back - x).norm(), 1e-13) << "gap " << gap;
  }
}

TEST(Chart, RoundTripInHingePositionsForMoreRods) {
  std::mt19937 rng(11);
  for (int n = 3; n <= 8; ++n)
    for (double L : baseLengths(n)) {
      const Chain chain = Chain::uniform(n, L);
      for (int i = 0; i < 100; ++i) {
        const Eigen::VectorXd x = randomUnit(rng, n - 1);
        const Eigen::Matrix2Xd p = hingePositionsAt(chain, x);
        const Eigen::VectorXd back = spherePointFromHinges(chain, p);
        ASSERT_LE((hingePositionsAt(chain, back) - p).cwiseAbs().maxCoeff(), 1e-12) << "n=" << n << " L=" << L;
        ASSERT_LE((back - x).norm(), 1e-8) << "n=" << n << " L=" << L;
      }
    }
}

TEST(Chart, JacobianByADMatchesCentralDifferences) {
  const Chain chain = Chain::uniform(5, 3.6);
  const std::vector<int> axes = sphereChartAxes(4, 0);
  const Eigen::Vector3d c(0.3, -0.5, 1.2);
  const Eigen::MatrixXd J = chartJacobian(chain, axes, c);
  for (int a = 0; a < 3; ++a) {
    const double h = 1e-6;
    const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(a);
    const Eigen::Matrix2Xd diff = (hingePositionsInChart<double>(chain, axes, Eigen::VectorXd(c + e)) -
                                   hingePositionsInChart<double>(chain, axes, Eigen::VectorXd(c - e))) /
                                  (2 * h);
    for (int r = 0; r < J.rows(); ++r) EXPECT_NEAR(J(r, a), diff(r % 2, r / 2), 1e-8);
  }
}

TEST(Chart, AmplitudeIsAccurateNearTheEndsOfTheRange) {
  for (int n = 3; n <= 8; ++n)
    for (double L : {n - 2 + 0.5, n - 1.0, n - 0.5}) {
      const double c = (L * L + 1 - (n - 1.0) * (n - 1.0)) / (2 * L);
      EXPECT_NEAR(chainAmplitude(n, L), std::acos(c), 1e-14);
    }
  // Near L = n the arccos form loses half the digits; the product form does not.
  const double L = 4 - 1e-12;
  const double exact = std::sqrt((4 - L) * (2 + L) / L);  // alpha ~ sqrt(2(1 - cos alpha)) to O(alpha^3)
  EXPECT_NEAR(chainAmplitude(4, L) / exact, 1.0, 1e-10);
}

}  // namespace
}  // namespace sl

namespace sl {
namespace {

// Long chains' chart rates (level by level, O(k^2)) equal the QR route on the whole Jacobian, and stay finite at
// a pole of the chart.
TEST(ChartRates, LevelByLevelEqualsQrOnTheJacobian) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> angle(-1.2, 1.2);
  const Eigen::Index k = kMaxQrCoordinates + 8;
  Eigen::VectorXd coords(k), rates(k);
  for (Eigen::Index i = 0; i < k; ++i) {
    coords(i) = angle(random);
    rates(i) = angle(random);
  }
  const Eigen::VectorXd xdot = sphereVelocityFromCoordinateRates(coords, rates);
  EXPECT_LT((coordinateRatesByLevels(coords, xdot) - rates).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((coordinateRatesFromSphereVelocity(coords, xdot) - rates).cwiseAbs().maxCoeff(), 1e-9);
  // Small k: both routes on the same input.
  const Eigen::VectorXd few = coords.head(5), fewRates = rates.head(5);
  const Eigen::VectorXd fewXdot = sphereVelocityFromCoordinateRates(few, fewRates);
  EXPECT_LT((coordinateRatesByLevels(few, fewXdot) - coordinateRatesFromSphereVelocity(few, fewXdot)).cwiseAbs().maxCoeff(),
            1e-12);
  coords(0) = M_PI / 2;  // the pole: only c_0 is defined
  const Eigen::VectorXd atPole = coordinateRatesByLevels(coords, sphereVelocityFromCoordinateRates(coords, rates));
  EXPECT_NEAR(atPole(0), rates(0), 1e-12);
  EXPECT_TRUE(atPole.allFinite());
}

}  // namespace
}  // namespace sl
