// The kinetic metric three ways: stable closed form, AD pullback, central differences.
#include <gtest/gtest.h>

#include <cmath>

#include "linkage/chart.hpp"
#include "linkage/kinetic_metric.hpp"
#include "linkage/sphere_coordinates.hpp"

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
      const Eigen::MatrixXd circle =
          kineticMetricPullback(Chain::uniform(3, d), circleAxes, Eigen::VectorXd::Constant(1, t));
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

namespace sl {
namespace {

TEST(KineticMetric, SecondChartCoversThePoleWithAPositiveDefiniteMetric) {
  // Chart 1 of the atlas is regular where the spec's chart has its poles: its pullback metric exists
  // there (AD and central differences agree) and is positive definite, exactly at the pole too.
  Chain chain = Chain::uniform(4, 3.0);
  const std::vector<int> axes1 = sphereChartAxes(3, 1);
  for (double gap : {0.0, 1e-12, 1e-6, 0.1}) {
    const Eigen::Vector3d x = Eigen::Vector3d(gap, 0.5 * gap, 1.0).normalized();  // near the north pole
    const Eigen::VectorXd c1 = coordinatesInChart(axes1, x);
    const Eigen::MatrixXd ad = kineticMetricPullback(chain, axes1, c1);
    const Eigen::MatrixXd fd = kineticMetricCentralDifferences(chain, axes1, c1);
    EXPECT_LE((fd - ad).cwiseAbs().maxCoeff() / ad.cwiseAbs().maxCoeff(), 1e-8) << "gap " << gap;
    EXPECT_GT(ad.ldlt().vectorD().minCoeff(), 1e-3) << "gap " << gap;
  }
}

TEST(KineticMetric, ChartsAgreeAsTensorsOnTheirOverlap) {
  // h1 = A^T h0 A with A = d c0 / d c1: the same metric seen through two charts.
  for (int n : {4, 5}) {
    Chain chain = Chain::uniform(n, n - 0.8);
    chain.rodMasses.setConstant(0.25);
    const int dim = n - 1;
    const std::vector<int> axes0 = sphereChartAxes(dim, 0), axes1 = sphereChartAxes(dim, 1);
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(dim, 0.4, 1.1).normalized();
    const Eigen::VectorXd c0 = coordinatesInChart(axes0, x), c1 = coordinatesInChart(axes1, x);
    Eigen::MatrixXd A(n - 2, n - 2);
    for (int j = 0; j < n - 2; ++j) {
      const double h = 1e-6;
      const Eigen::VectorXd e = h * Eigen::VectorXd::Unit(n - 2, j);
      const Eigen::VectorXd xp = spherePointInChart<double>(axes1, Eigen::VectorXd(c1 + e));
      const Eigen::VectorXd xm = spherePointInChart<double>(axes1, Eigen::VectorXd(c1 - e));
      A.col(j) = (coordinatesInChart(axes0, xp, c0(n - 3)) - coordinatesInChart(axes0, xm, c0(n - 3))) / (2 * h);
    }
    const Eigen::MatrixXd h0 = kineticMetricPullback(chain, axes0, c0);
    const Eigen::MatrixXd h1 = kineticMetricPullback(chain, axes1, c1);
    EXPECT_LE((A.transpose() * h0 * A - h1).cwiseAbs().maxCoeff() / h1.cwiseAbs().maxCoeff(), 1e-8) << "n=" << n;
  }
}

}  // namespace
}  // namespace sl
