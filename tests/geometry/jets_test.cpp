// The two Taylor jets against each other, against Eigen's AutoDiff Jacobian and against central differences.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/second_order_jet.hpp"
#include "geometry/taylor_jet.hpp"
#include "geometry_support.hpp"
#include "linkage/chart.hpp"
#include "linkage/sphere_coordinates.hpp"

namespace sl {
namespace {

using testing::chartZeroPoint;

template <class Jet>
HingeMatrix<Jet> hingeJets(const Chain& chain, int chart, const Eigen::Vector2d& coords) {
  VectorX<Jet> c(2);
  c(0) = Jet::variable(coords(0), 0);
  c(1) = Jet::variable(coords(1), 1);
  return hingePositionsInChart<Jet>(chain, sphereChartAxes(3, chart), c);
}

// Coordinates of well-conditioned points in both charts, seams of chart 0 included.
std::vector<std::pair<int, Eigen::Vector2d>> chartPoints() {
  std::vector<std::pair<int, Eigen::Vector2d>> points;
  for (int chart = 0; chart < 2; ++chart)
    for (double a : {-1.1, -0.4, 0.0, 0.25, 0.9})
      for (double b : {-M_PI, -M_PI / 2, -1.0, 0.0, 0.3, M_PI / 2, 2.4})
        points.push_back({chart, Eigen::Vector2d(a, b)});
  return points;
}

TEST(Jets, SecondOrderJetAgreesWithTheGenericTaylorJet) {
  {
    for (double L : testing::issueBaseLengths()) {  // the chart does not see masses
      const Chain chain = Chain::uniform(4, L);
      for (const auto& [chart, c] : chartPoints()) {
        const HingeMatrix<SecondOrderJet> fast = hingeJets<SecondOrderJet>(chain, chart, c);
        const HingeMatrix<TaylorJet<2>> generic = hingeJets<TaylorJet<2>>(chain, chart, c);
        for (int k = 0; k < 3; ++k)
          for (int xy = 0; xy < 2; ++xy) {
            const SecondOrderJet& a = fast(xy, k);
            const TaylorJet<2>& b = generic(xy, k);
            const double scale = 1.0 + std::abs(a.h00) + std::abs(a.h11);
            EXPECT_NEAR(a.v, b.partial(0, 0), 1e-14);
            EXPECT_NEAR(a.g0, b.partial(1, 0), 1e-13 * scale);
            EXPECT_NEAR(a.g1, b.partial(0, 1), 1e-13 * scale);
            EXPECT_NEAR(a.h00, b.partial(2, 0), 1e-12 * scale)
                << "L=" << L << " chart " << chart << " c=" << c.transpose();
            EXPECT_NEAR(a.h01, b.partial(1, 1), 1e-12 * scale);
            EXPECT_NEAR(a.h11, b.partial(0, 2), 1e-12 * scale);
          }
      }
    }
  }
}

TEST(Jets, GradientIsTheAutoDiffJacobianAndHessianItsCentralDifference) {
  const double h = 1e-5;
  for (double L : testing::issueBaseLengths()) {
    const Chain chain = Chain::uniform(4, L);
    for (const auto& [chart, c] : chartPoints()) {
      const std::vector<int> axes = sphereChartAxes(3, chart);
      const HingeMatrix<SecondOrderJet> jet = hingeJets<SecondOrderJet>(chain, chart, c);
      const Eigen::MatrixXd J = chartJacobian(chain, axes, c);
      const Eigen::MatrixXd J0 = (chartJacobian(chain, axes, c + Eigen::Vector2d(h, 0)) -
                                  chartJacobian(chain, axes, c - Eigen::Vector2d(h, 0))) /
                                 (2 * h);
      const Eigen::MatrixXd J1 = (chartJacobian(chain, axes, c + Eigen::Vector2d(0, h)) -
                                  chartJacobian(chain, axes, c - Eigen::Vector2d(0, h))) /
                                 (2 * h);
      for (int k = 0; k < 3; ++k)
        for (int xy = 0; xy < 2; ++xy) {
          const int r = 2 * k + xy;
          const SecondOrderJet& q = jet(xy, k);
          EXPECT_NEAR(q.g0, J(r, 0), 1e-13);
          EXPECT_NEAR(q.g1, J(r, 1), 1e-13);
          // Central differences of step 1e-5: truncation ~1e-10 times the fourth derivatives.
          const double tolerance = 1e-7 * (1.0 + std::abs(q.h00) + std::abs(q.h01) + std::abs(q.h11));
          EXPECT_NEAR(q.h00, J0(r, 0), tolerance) << "L=" << L << " chart " << chart << " c=" << c.transpose();
          EXPECT_NEAR(q.h01, J0(r, 1), tolerance);
          EXPECT_NEAR(q.h01, J1(r, 0), tolerance);
          EXPECT_NEAR(q.h11, J1(r, 1), tolerance);
        }
    }
  }
}

TEST(Jets, ThirdOrderTermsAreCentralDifferencesOfTheSecondOrder) {
  const double h = 1e-5;
  const Chain chain = Chain::uniform(4, 3.0);
  for (const auto& [chart, c] : chartPoints()) {
    const HingeMatrix<TaylorJet<3>> jet = hingeJets<TaylorJet<3>>(chain, chart, c);
    const HingeMatrix<SecondOrderJet> up = hingeJets<SecondOrderJet>(chain, chart, c + Eigen::Vector2d(h, 0));
    const HingeMatrix<SecondOrderJet> down = hingeJets<SecondOrderJet>(chain, chart, c - Eigen::Vector2d(h, 0));
    const HingeMatrix<SecondOrderJet> right = hingeJets<SecondOrderJet>(chain, chart, c + Eigen::Vector2d(0, h));
    const HingeMatrix<SecondOrderJet> left = hingeJets<SecondOrderJet>(chain, chart, c - Eigen::Vector2d(0, h));
    for (int k = 0; k < 3; ++k)
      for (int xy = 0; xy < 2; ++xy) {
        const TaylorJet<3>& q = jet(xy, k);
        EXPECT_NEAR(q.partial(3, 0), (up(xy, k).h00 - down(xy, k).h00) / (2 * h), 1e-6);
        EXPECT_NEAR(q.partial(2, 1), (up(xy, k).h01 - down(xy, k).h01) / (2 * h), 1e-6);
        EXPECT_NEAR(q.partial(2, 1), (right(xy, k).h00 - left(xy, k).h00) / (2 * h), 1e-6);
        EXPECT_NEAR(q.partial(1, 2), (right(xy, k).h01 - left(xy, k).h01) / (2 * h), 1e-6);
        EXPECT_NEAR(q.partial(0, 3), (right(xy, k).h11 - left(xy, k).h11) / (2 * h), 1e-6);
      }
  }
}

TEST(Jets, ElementaryFunctionsMatchClosedForms) {
  // f(u, v) at (0.3, -0.2) for u = c0, v = c1, each checked against its hand-differentiated derivatives.
  const double u = 0.3, v = -0.2;
  const SecondOrderJet U = SecondOrderJet::variable(u, 0), V = SecondOrderJet::variable(v, 1);
  const TaylorJet<3> U3 = TaylorJet<3>::variable(u, 0), V3 = TaylorJet<3>::variable(v, 1);
  {  // sin(u v)
    const SecondOrderJet f = sin(U * V);
    const double w = u * v, c = std::cos(w), s = std::sin(w);
    EXPECT_NEAR(f.v, s, 1e-16);
    EXPECT_NEAR(f.g0, v * c, 1e-16);
    EXPECT_NEAR(f.h00, -v * v * s, 1e-16);
    EXPECT_NEAR(f.h01, c - u * v * s, 1e-16);
    EXPECT_NEAR(sin(U3 * V3).partial(1, 2), -2 * u * s - u * u * v * c, 1e-15);  // d/du d2/dv2
  }
  {  // u / (1 + v^2) and sqrt(1 + u^2)
    const SecondOrderJet q = U / (1.0 + V * V);
    const double d = 1 + v * v;
    EXPECT_NEAR(q.g1, -2 * u * v / (d * d), 1e-16);
    EXPECT_NEAR(q.h11, u * (6 * v * v - 2) / (d * d * d), 1e-15);
    EXPECT_NEAR(q.h01, -2 * v / (d * d), 1e-16);
    const SecondOrderJet r = sqrt(1.0 + U * U);
    EXPECT_NEAR(r.h00, std::pow(1 + u * u, -1.5), 1e-15);
    EXPECT_NEAR(sqrt(1.0 + U3 * U3).partial(3, 0), -3 * u * std::pow(1 + u * u, -2.5), 1e-15);
  }
  {  // asin(u + v), cos(u - v)
    const SecondOrderJet a = asin(U + V);
    const double w = u + v;
    EXPECT_NEAR(a.g0, 1 / std::sqrt(1 - w * w), 1e-15);
    EXPECT_NEAR(a.h01, w * std::pow(1 - w * w, -1.5), 1e-15);
    EXPECT_NEAR(asin(U3 + V3).partial(0, 3), (1 + 2 * w * w) * std::pow(1 - w * w, -2.5), 1e-14);
    const SecondOrderJet c = cos(U - V);
    EXPECT_NEAR(c.h01, std::cos(u - v), 1e-16);
  }
}

}  // namespace
}  // namespace sl
