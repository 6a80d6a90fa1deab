// The geodesic vector fields at single states: exact routes against each other and against independent
// finite differences; the published -fd fields against the exact ones where they are valid.
#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <vector>

#include "fixtures/published_references.hpp"
#include "linkage/chart.hpp"
#include "linkage/kinetic_metric.hpp"
#include "linkage/sphere_coordinates.hpp"
#include "simulation/exact_fields.hpp"
#include "simulation/published_fields.hpp"
#include "simulation/stencil_trig.hpp"

namespace sl {
namespace {

Chain massiveChain(int rods, double L) {
  Chain chain = Chain::uniform(rods, L);
  for (int j = 0; j < rods - 1; ++j) chain.hingeMasses(j) = 0.5 + 0.37 * j;
  for (int k = 0; k < rods; ++k) chain.rodMasses(k) = 0.2 + 0.1 * (k % 3);
  return chain;
}

// Random chart coordinates away from the chart's own singular set (|latitudes| < 1.3).
Eigen::VectorXd randomCoords(std::mt19937& rng, int k) {
  std::uniform_real_distribution<double> latitude(-1.3, 1.3), angle(-M_PI, M_PI);
  Eigen::VectorXd c(k);
  for (int i = 0; i + 1 < k; ++i) c(i) = latitude(rng);
  c(k - 1) = angle(rng);
  return c;
}

TEST(ExactFields, ChristoffelAndEmbeddedAgreeForAnyChainChartAndMasses) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  for (int rods = 3; rods <= 6; ++rods)
    for (const Chain& chain : {Chain::uniform(rods, rods - 0.6), massiveChain(rods, rods - 1.3)})
      for (int chart = 0; chart < sphereChartCount(rods - 1); ++chart)
        for (int trial = 0; trial < 4; ++trial) {
          const std::vector<int> axes = sphereChartAxes(rods - 1, chart);
          const Eigen::VectorXd c = randomCoords(rng, rods - 2);
          Eigen::VectorXd v(rods - 2);
          for (Eigen::Index i = 0; i < v.size(); ++i) v(i) = normal(rng);
          const Eigen::VectorXd a = christoffelAcceleration(ChainConstants(chain), axes, c, v);
          const Eigen::VectorXd b = embeddedAcceleration(ChainConstants(chain), axes, c, v);
          EXPECT_LT((a - b).norm(), 1e-10 * (1 + a.norm())) << "n = " << rods << ", chart " << chart;
        }
}

TEST(ExactFields, ChristoffelSymbolsMatchFiniteDifferencesOfTheMetric) {
  // Independent route: Gamma from central differences (step 1e-4, fourth-order stencil) of the AD pullback.
  const Chain chain = massiveChain(5, 3.6);
  const std::vector<int> axes = sphereChartAxes(4, 1);
  const Eigen::Vector3d c(0.4, -0.7, 2.1);
  const double h = 1e-3;
  std::vector<Eigen::MatrixXd> dh(3);
  for (int a = 0; a < 3; ++a) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(a) * h;
    dh[a] = (8 * (kineticMetricPullback(chain, axes, c + e) - kineticMetricPullback(chain, axes, c - e)) -
             (kineticMetricPullback(chain, axes, c + 2 * e) - kineticMetricPullback(chain, axes, c - 2 * e))) /
            (12 * h);
  }
  const Eigen::MatrixXd inverse = kineticMetricPullback(chain, axes, c).inverse();
  const std::vector<Eigen::MatrixXd> gamma = christoffelSymbols(ChainConstants(chain), axes, c);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        double expected = 0;
        for (int l = 0; l < 3; ++l) expected += 0.5 * inverse(i, l) * (dh[j](l, k) + dh[k](l, j) - dh[l](j, k));
        EXPECT_NEAR(gamma[i](j, k), expected, 1e-8 * (1 + std::abs(expected)));
        EXPECT_EQ(gamma[i](j, k), gamma[i](k, j));
      }
}

TEST(ExactFields, AccelerationIsNormalToTheConfigurationSpace) {
  // The defining property of a geodesic (spec section 5), checked with the finite-difference second
  // derivative of Psi along the path: q'' = J a + q_bc v^b v^c must be M-orthogonal to every q_a.
  const Chain chain = massiveChain(4, 3.2);
  const std::vector<int> axes = sphereChartAxes(3, 0);
  const Eigen::Vector2d c(0.3, 1.1), v(0.8, -0.5);
  const Eigen::VectorXd a = christoffelAcceleration(ChainConstants(chain), axes, c, v);
  const double s = 1e-4;
  auto q = [&](double tau) {
    const Eigen::VectorXd at = c + tau * v + 0.5 * tau * tau * a;
    const Eigen::Matrix2Xd hinges = hingePositionsInChart<double>(chain, axes, at);
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(hinges.data(), hinges.size()));
  };
  const Eigen::VectorXd qdd = (q(s) - 2 * q(0) + q(-s)) / (s * s);
  const Eigen::MatrixXd J = chartJacobian(chain, axes, c);
  const Eigen::VectorXd tangential = J.transpose() * stackedMassMatrix(chain) * qdd;
  EXPECT_LT(tangential.norm(), 1e-6 * qdd.norm());
}

TEST(PublishedFields, AgreeWithTheExactFieldToTheirDifferenceError) {
  const Chain chain = Chain::uniform(4, 3.0);
  const std::vector<int> axes = sphereChartAxes(3, 0);
  double worstChristoffel = 0, worstEmbedded = 0;
  for (double phi : {-1.2, -0.5, 0.3, 1.0})
    for (double t : {-2.5, -0.4, 0.2, 1.3, 2.9}) {
      const Eigen::Vector2d c(phi, t), v(0.6, -0.9);
      const Eigen::VectorXd exact = christoffelAcceleration(ChainConstants(chain), axes, c, v);
      worstChristoffel = std::max(worstChristoffel,
                                  (christoffelFdAcceleration(PublishedChain(3.0), c, v) - exact).norm() / exact.norm());
      worstEmbedded =
          std::max(worstEmbedded, (embeddedFdAcceleration(PublishedChain(3.0), c, v) - exact).norm() / exact.norm());
    }
  // Central differences: eps^2 truncation plus rounding / eps (1e-5 and 1e-4 steps, second differences).
  EXPECT_LT(worstChristoffel, 1e-7);
  EXPECT_LT(worstEmbedded, 1e-6);
  EXPECT_GT(worstEmbedded, 1e-12);  // they are approximations: a bit-exact match would mean a wiring mistake
}

TEST(PublishedFields, ChristoffelFdFailsOnTheSeamWhereThePublishedMetricDoes) {
  // At t = pi/2 the published metric4 divides by nu_in ~ cos t; its t-differences straddle the seam.
  const Eigen::Vector2d onSeam(0.3, M_PI / 2), v(0.5, 0.7);
  const Eigen::Vector2d published = christoffelFdAcceleration(PublishedChain(3.0), onSeam, v);
  const Eigen::VectorXd exact =
      christoffelAcceleration(ChainConstants(Chain::uniform(4, 3.0)), sphereChartAxes(3, 0), onSeam, v);
  const bool broken = !published.allFinite() || (published - exact).norm() > 1e-3 * exact.norm();
  EXPECT_TRUE(broken) << "published " << published.transpose() << " exact " << exact.transpose();
  // The embedded-fd route never touches nu_in's division: fine on the seam.
  EXPECT_LT((embeddedFdAcceleration(PublishedChain(3.0), onSeam, v) - exact).norm(), 1e-6 * exact.norm());
}

// ---- The shared-work -fd fields against the same stencils evaluated point by point ----------------------
// Both evaluate the same formulas at the same stencil points; they differ only in how the sines, cosines,
// amplitudes and phi-only parts are obtained (angle addition from the stencil centre, reciprocals), which
// keeps every stencil value within an ulp or two. So they must agree to the fields' own roundoff: ulps of
// each stencil value divided by 2 eps = 2e-5 (christoffel-fd) or by eps^2 = 1e-8 (embedded-fd's second
// differences: one ulp of |q| ~ 3 is 4e-8 there). Measured yardstick: moving (phi, t) by one ulp moves the
// stencil-by-stencil fields by up to 2.9e-8 (christoffel-fd) and 8.3e-8 (embedded-fd) on the regular grid
// below, and the shared versions differ from them by the same 2.9e-8 and 8.1e-8. The bounds allow about 3x
// that. Where a formula loses digits the noise grows: christoffel-fd's printed nu_in = cos t
// sqrt((4 - |p2|^2) / cos^2 t) by 1/cos^2 t near the seam, and the chart by 1/cos^2 phi near the poles.

// Scaled difference |a - b| / (1 + |b|): relative for large accelerations, absolute near a = 0, where the
// terms of the geodesic equation cancel and relative noise is meaningless.
double scaledDifference(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return (a - b).norm() / (1 + b.norm()); }

std::vector<double> stateGrid(double from, double to, double step) {
  std::vector<double> grid;
  for (double x = from; x <= to + 1e-12; x += step) grid.push_back(x);
  return grid;
}

std::vector<double> withSeamAndPoleOffsets(std::vector<double> grid, const std::vector<double>& offsets) {
  for (double o : offsets)
    for (double centre : {M_PI / 2, -M_PI / 2}) {
      grid.push_back(centre - o);
      grid.push_back(centre + o);
    }
  return grid;
}

const Eigen::Vector2d gridRates(0.6, -0.9);

TEST(PublishedFields, SharedStencilMatchesStencilByStencilAwayFromSeamAndPoles) {
  for (double L : {2.2, 3.0, 3.3, 3.9})
    for (double phi : stateGrid(-1.4, 1.4, 0.1))
      for (double t : stateGrid(-3.1, 3.1, 0.1)) {
        if (std::abs(std::cos(t)) < 0.2) continue;  // the seam band has its own test
        const Eigen::Vector2d c(phi, t);
        EXPECT_LT(scaledDifference(christoffelFdAcceleration(PublishedChain(L), c, gridRates),
                                   christoffelFdAccelerationStencilByStencil(L, c, gridRates)),
                  1e-7)
            << "L " << L << " phi " << phi << " t " << t;
        EXPECT_LT(scaledDifference(embeddedFdAcceleration(PublishedChain(L), c, gridRates),
                                   embeddedFdAccelerationStencilByStencil(L, c, gridRates)),
                  3e-7)
            << "L " << L << " phi " << phi << " t " << t;
      }
}

TEST(PublishedFields, SharedStencilMatchesStencilByStencilNearAndOnTheSeam) {
  // t down to 1e-7 from the seam and on it: embedded-fd (sinc form, smooth there) to 3e-7; christoffel-fd,
  // whose printed metric loses digits as 1/cos^2 t, to 1e-8 / cos^2 t while cos t >= 5e-3 (closer in, the
  // published metric itself is wrong: ChristoffelFdFailsOnTheSeamWhereThePublishedMetricDoes).
  const std::vector<double> ts =
      withSeamAndPoleOffsets(stateGrid(-1.8, -1.35, 0.05), {0.03, 0.01, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 0});
  for (double L : {2.2, 3.0, 3.3, 3.9})
    for (double phi : stateGrid(-1.4, 1.4, 0.2))
      for (double t : ts) {
        const Eigen::Vector2d c(phi, t);
        EXPECT_LT(scaledDifference(embeddedFdAcceleration(PublishedChain(L), c, gridRates),
                                   embeddedFdAccelerationStencilByStencil(L, c, gridRates)),
                  3e-7)
            << "L " << L << " phi " << phi << " t " << t;
        const double cosT = std::abs(std::cos(t));
        if (cosT < 5e-3) continue;
        EXPECT_LT(scaledDifference(christoffelFdAcceleration(PublishedChain(L), c, gridRates),
                                   christoffelFdAccelerationStencilByStencil(L, c, gridRates)),
                  1e-8 / (cosT * cosT))
            << "L " << L << " phi " << phi << " t " << t;
      }
}

TEST(PublishedFields, SharedStencilMatchesStencilByStencilNearThePoles) {
  // phi down to 1e-7 from the poles (embedded-fd, bound 1e-8 / cos^2 phi) and to 1e-3 (christoffel-fd,
  // whose printed metric is singular at the poles faster, bound 1e-5 / cos^2 phi).
  const std::vector<double> phis = withSeamAndPoleOffsets({}, {0.1, 0.03, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7});
  for (double L : {2.2, 3.0, 3.3, 3.9})
    for (double phi : phis)
      for (double t : stateGrid(-3.0, 3.0, 0.25)) {
        if (std::abs(std::cos(phi)) > 1 || std::abs(std::cos(t)) < 0.2) continue;
        const Eigen::Vector2d c(phi, t);
        const double cosPhi2 = std::cos(phi) * std::cos(phi);
        EXPECT_LT(scaledDifference(embeddedFdAcceleration(PublishedChain(L), c, gridRates),
                                   embeddedFdAccelerationStencilByStencil(L, c, gridRates)),
                  1e-8 / cosPhi2)
            << "L " << L << " phi " << phi << " t " << t;
        if (std::abs(std::cos(phi)) < 1e-3) continue;
        EXPECT_LT(scaledDifference(christoffelFdAcceleration(PublishedChain(L), c, gridRates),
                                   christoffelFdAccelerationStencilByStencil(L, c, gridRates)),
                  1e-5 / cosPhi2)
            << "L " << L << " phi " << phi << " t " << t;
      }
}

TEST(PublishedFields, SharedStencilIsStillAnApproximationNotACopy) {
  // Guards the comparison tests above against comparing a function with itself: the two evaluations round
  // differently, so somewhere on a small grid they differ in the last bits.
  double largest = 0;
  for (double phi : stateGrid(-1.0, 1.0, 0.5))
    for (double t : stateGrid(-2.0, 2.0, 0.5)) {
      const Eigen::Vector2d c(phi, t);
      largest = std::max(largest, scaledDifference(christoffelFdAcceleration(PublishedChain(3.3), c, gridRates),
                                                   christoffelFdAccelerationStencilByStencil(3.3, c, gridRates)));
      largest = std::max(largest, scaledDifference(embeddedFdAcceleration(PublishedChain(3.3), c, gridRates),
                                                   embeddedFdAccelerationStencilByStencil(3.3, c, gridRates)));
    }
  EXPECT_GT(largest, 0.0);
}

// ---- The stencil trigonometry the shared fields rely on (simulation/stencil_trig.hpp) -------------------

TEST(StencilTrig, TurnedSinesAndCosinesAreThoseOfTheSameDouble) {
  // Within two ulps of std::cos / std::sin of the same double, for steps up to the 1e-3 cut-off, and with
  // absolute error ~1e-21 where the result itself is ~delta (the centre at -delta: cancellation).
  double worst = 0, worstNearZero = 0;
  for (double centre = -4.0; centre <= 4.0; centre += 0.0137)
    for (double step : {1e-5, -1e-5, 1e-4, -1e-4, 3e-4, 0.999e-3, -0.999e-3, 2.5e-6}) {  // inside the 1e-3 cut-off
      const double angle = centre + step;
      const Turn turned = turnAt(angle, turnOf(centre), centre);
      const double scale = std::numeric_limits<double>::epsilon();
      worst =
          std::max(worst, std::abs(turned.c - std::cos(angle)) / (scale * std::max(std::abs(std::cos(angle)), 0.5)));
      worst =
          std::max(worst, std::abs(turned.s - std::sin(angle)) / (scale * std::max(std::abs(std::sin(angle)), 0.5)));
      const Turn throughZero = turnAt(step * 1e-3, turnOf(-step), -step);  // result ~ step / 1000
      worstNearZero = std::max(worstNearZero, std::abs(throughZero.s - std::sin(step * 1e-3)) / std::abs(step));
    }
  EXPECT_LT(worst, 2.0);
  EXPECT_LT(worstNearZero, 4 * std::numeric_limits<double>::epsilon());  // an ulp or so of delta's terms
  // Beyond the cut-off (or NaN) it evaluates directly.
  EXPECT_EQ(turnAt(1.0, turnOf(0.0), 0.0).s, std::sin(1.0));
  EXPECT_TRUE(std::isnan(turnAt(std::nan(""), turnOf(0.0), 0.0).c));
}

TEST(StencilTrig, SincFromSineMatchesSinc) {
  double worst = 0;
  for (double x = -3.0; x <= 3.0; x += 0.00731)
    worst = std::max(worst, std::abs(sincFromSine(x, std::sin(x)) - sinc(x)) / sinc(x));
  for (double x : {0.4999999, 0.5, -0.5, 0.1, 1e-9, 0.0})
    worst = std::max(worst, std::abs(sincFromSine(x, std::sin(x)) - sinc(x)) / sinc(x));
  EXPECT_LT(worst, 3 * std::numeric_limits<double>::epsilon());
  double worstProduct = 0;
  for (double a : {-2.0, -0.3, 0.0, 0.2, 0.5, 1.1, 2.9})
    for (double b : {-1.7, 1e-8, 0.4999, 0.7, 3.0}) {
      const double expected = sinc(a) * sinc(b);
      worstProduct =
          std::max(worstProduct, std::abs(sincProductFromSines(a, std::sin(a), b, std::sin(b)) - expected) / expected);
    }
  EXPECT_LT(worstProduct, 4 * std::numeric_limits<double>::epsilon());
}

TEST(StencilTrig, AngleFromTheCentreMatchesAtan2) {
  double worst = 0;
  for (double a = -3.0; a <= 3.0; a += 0.0173)
    for (double step : {1e-5, -1e-4, 5e-4, -9e-4}) {
      const double r0 = 1.7, r = 1.7 + 0.3 * step;  // lengths need not agree
      const double x0 = r0 * std::cos(a), y0 = r0 * std::sin(a), x = r * std::cos(a + step), y = r * std::sin(a + step);
      const double expected = std::atan2(y, x);
      worst =
          std::max(worst, std::abs(angleAt(y, x, y0, x0, std::atan2(y0, x0)) - expected) / (1 + std::abs(expected)));
    }
  EXPECT_LT(worst, 4 * std::numeric_limits<double>::epsilon());
  // Opposite directions have a zero cross product too: no shortcut there.
  EXPECT_EQ(angleAt(-std::sin(1.2), -std::cos(1.2), std::sin(1.2), std::cos(1.2), 1.2),
            std::atan2(-std::sin(1.2), -std::cos(1.2)));
}

}  // namespace
}  // namespace sl
