// The kinetic metric three ways: stable closed form, AD pullback, central differences.
#include <gtest/gtest.h>

#include <cmath>

#include "linkage/chart.hpp"
#include "linkage/kinetic_metric.hpp"

namespace sl {
namespace {

double relativeDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

std::vector<double> seamAndGenericTimes() {
  std::vector<double> ts = {M_PI / 2, -M_PI / 2, M_PI / 2 + 1e-4, M_PI / 2 - 1e-7, -M_PI / 2 + 1e-9, 0.0, M_PI};
  for (int j = 0; j < 48; ++j) ts.push_back(-M_PI + 2 * M_PI * j / 48.0 + 0.01);
  return ts;
}

TEST(KineticMetric, ClosedFormAgreesWithADPullbackEverywhereIncludingTheSeam) {
  const std::vector<int> axes = sphereChartAxes(3, 0);
  double worst = 0;
  for (double L : {2.001, 2.4, 3.0, 3.6, 3.999}) {
    const Chain chain = Chain::uniform(4, L);
    for (int i = 0; i <= 30; ++i) {
      const double phi = -1.5 + 3.0 * i / 30.0;
      for (double t : seamAndGenericTimes()) {
        const Eigen::Matrix2d closed = kineticMetricClosedForm(L, phi, t);
        const Eigen::MatrixXd pullback = kineticMetricPullback(chain, axes, Eigen::Vector2d(phi, t));
        const double rel = relativeDifference(closed, pullback);
        worst = std::max(worst, rel);
        ASSERT_LE(rel, 1e-12) << "L=" << L << " phi=" << phi << " t=" << t;
      }
    }
  }
  RecordProperty("worst_relative_difference", std::to_string(worst));
}

TEST(KineticMetric, PublishedFormBreaksDownAtTheSeam) {
  // As printed, metric4 divides d|p2| by nu_in: near cos t = 0 it loses digits and at t = pi/2 it is
  // far off. This pins the published behaviour that the stable form fixes.
  const double L = 3.0, phi = 0.3;
  const Eigen::Matrix2d good = kineticMetricClosedForm(L, phi, M_PI / 2);
  const Eigen::Matrix2d published = kineticMetricPublished(L, phi, M_PI / 2);
  EXPECT_GT(relativeDifference(published, good), 1e-2);
  double nearSeam = 0;
  for (double offset : {1e-5, 3e-5, 1e-4})
    nearSeam = std::max(nearSeam, relativeDifference(kineticMetricPublished(L, phi, M_PI / 2 - offset),
                                                     kineticMetricClosedForm(L, phi, M_PI / 2 - offset)));
  EXPECT_GT(nearSeam, 1e-9);
  // Away from the seam it is right.
  EXPECT_LE(relativeDifference(kineticMetricPublished(L, phi, 0.4), kineticMetricClosedForm(L, phi, 0.4)), 1e-12);
}

TEST(KineticMetric, CentralDifferencesAgreeWithPullbackForAnyN) {
  for (int n = 3; n <= 8; ++n) {
    Chain chain = Chain::uniform(n, n - 0.7);
    chain.rodMasses.setConstant(0.5);
    chain.hingeMasses(0) = 2.0;
    const std::vector<int> axes = sphereChartAxes(n - 1, 0);
    Eigen::VectorXd c = Eigen::VectorXd::LinSpaced(n - 2, -0.6, 0.9);
    const Eigen::MatrixXd ad = kineticMetricPullback(chain, axes, c);
    const Eigen::MatrixXd fd = kineticMetricCentralDifferences(chain, axes, c);
    EXPECT_LE(relativeDifference(fd, ad), 1e-8) << "n=" << n;
    EXPECT_LE((ad - ad.transpose()).norm(), 1e-14);
    EXPECT_GT(ad.ldlt().vectorD().minCoeff(), 0.0) << "positive definite, n=" << n;
  }
}

TEST(KineticMetric, TimeComponentIsTheInnerCircleMetric) {
  // Spec section 3: h_tt(phi, t) = h_tt^(3)(t; d(phi)), the 3-rod circle metric at the sub-base d.
  const double L = 3.0;
  const std::vector<int> circleAxes = sphereChartAxes(2, 0);
  for (double phi : {-1.2, 0.0, 0.5, 1.3})
    for (double t : {-2.0, 0.3, M_PI / 2, 2.5}) {
      const double alpha = chainAmplitude(4, L);
      const double d = std::abs(L - std::polar(1.0, alpha * std::sin(phi)));
      const Eigen::MatrixXd circle = kineticMetricPullback(Chain::uniform(3, d), circleAxes, Eigen::VectorXd::Constant(1, t));
      EXPECT_NEAR(kineticMetricClosedForm(L, phi, t)(1, 1), circle(0, 0), 1e-12 * circle(0, 0));
    }
}

TEST(KineticMetric, MassMatrixIsBlockTridiagonalAsInSectionOne) {
  Chain chain = Chain::uniform(4, 3.0);
  chain.rodMasses << 0.3, 0.6, 0.9, 1.2;
  const AmbientMassMatrix mass = ambientMassMatrix(chain);
  EXPECT_NEAR(mass.diagonal(0), 1 + (0.3 + 0.6) / 3, 1e-15);
  EXPECT_NEAR(mass.coupling(0), 0.6 / 6, 1e-15);
  EXPECT_NEAR(mass.coupling(1), 0.9 / 6, 1e-15);
  // Direct integration of a rod's kinetic energy with Simpson's rule (exact for quadratics).
  Eigen::Matrix2Xd v(2, 3);
  v << 0.3, -1.0, 0.7, 0.2, 0.5, -0.4;
  double T = 0.5 * v.colwise().squaredNorm().sum();
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d a = k == 0 ? Eigen::Vector2d::Zero() : Eigen::Vector2d(v.col(k - 1));
    const Eigen::Vector2d b = k == 3 ? Eigen::Vector2d::Zero() : Eigen::Vector2d(v.col(k));
    const double simpson = (a.squaredNorm() + 4 * (0.5 * (a + b)).squaredNorm() + b.squaredNorm()) / 6;
    T += 0.5 * chain.rodMasses(k) * simpson;
  }
  EXPECT_NEAR(kineticEnergy(mass, v), T, 1e-14);
}

}  // namespace
}  // namespace sl
