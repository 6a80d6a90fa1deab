// The exact extremes of the directional stiffness S(a) against dense sampling, and its degenerate cases.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry/curvature.hpp"
#include "geometry/stiffness.hpp"
#include "geometry_support.hpp"

namespace sl {
namespace {

struct Sampled {
  double max = -INFINITY, min = INFINITY;
};

// max and min of S over `count` equally spaced angles of a half turn (S has period pi).
Sampled sampleStiffness(const Eigen::Matrix3d& gram, int count) {
  Sampled out;
  for (int k = 0; k < count; ++k) {
    const double s = directionalStiffness(gram, M_PI * k / count);
    out.max = std::max(out.max, s);
    out.min = std::min(out.min, s);
  }
  return out;
}

// Checks the exact extremes against 10^5 samples: no sample beyond them, and the samples reach them to the
// sampling resolution ((pi/10^5)^2 / 2 times |S''| <= 16 (|P| + |Q| + |R|)^2).
void expectExtremesMatchSampling(const Eigen::Matrix3d& gram, const std::string& what) {
  const StiffnessExtremes exact = stiffnessExtremes(gram);
  const Sampled sampled = sampleStiffness(gram, 100000);
  const double scale = gram.diagonal().sum() + 1e-300;
  EXPECT_GE(exact.max, exact.min) << what;
  EXPECT_GE(exact.min, 0.0) << what;
  EXPECT_LE(sampled.max, exact.max + 1e-13 * scale) << what;
  EXPECT_GE(sampled.min, exact.min - 1e-13 * scale) << what;
  EXPECT_LE(exact.max - sampled.max, 1e-8 * scale) << what;
  EXPECT_LE(sampled.min - exact.min, 1e-8 * scale) << what;
  // The angles returned attain the extremes and lie in (-pi/2, pi/2].
  EXPECT_NEAR(directionalStiffness(gram, exact.angleOfMax), exact.max, 1e-12 * scale) << what;
  EXPECT_NEAR(directionalStiffness(gram, exact.angleOfMin), exact.min, 1e-12 * scale) << what;
  EXPECT_GT(exact.angleOfMax, -M_PI / 2);
  EXPECT_LE(exact.angleOfMax, M_PI / 2);
  EXPECT_LE(exact.iterations, 40) << what;
}

// Gram matrix of A, B, C given as the columns of X (vectors of the normal space).
Eigen::Matrix3d gramOf(const Eigen::MatrixXd& X) { return X.transpose() * X; }

TEST(Stiffness, ExactExtremesMatchDenseSamplingOnTheConfigurationSphere) {
  for (double L : {2.2, 3.0, 3.9})
    for (const auto& setting : testing::massSettings(L)) {
      const ConfigurationSurface surface(setting.chain);
      const std::vector<Eigen::Vector3d> points = testing::testPoints(6);
      for (size_t k = 0; k < points.size(); k += 3) {  // a third of them: 10^5 samples each
        const Eigen::Vector3d& x = points[k];
        const CurvatureSample s = surface.curvatureAt(x);
        expectExtremesMatchSampling(s.frameGram, setting.name + " L=" + std::to_string(L));
        EXPECT_EQ(stiffnessExtremes(s.frameGram).max, s.stiffnessMax);
        EXPECT_EQ(stiffnessExtremes(s.frameGram).angleOfMax, s.stiffnessAngle);
      }
    }
}

TEST(Stiffness, ExactExtremesMatchDenseSamplingForRandomNormalVectors) {
  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  for (int k = 0; k < 60; ++k) {
    Eigen::MatrixXd X(4, 3);  // the normal space of the sphere in R^6 is 4-dimensional
    for (int i = 0; i < 12; ++i) X.data()[i] = normal(rng) * (k % 3 == 0 ? 1e-3 : 1.0);
    expectExtremesMatchSampling(gramOf(X), "random " + std::to_string(k));
  }
}

TEST(Stiffness, SecularIterationsStayFewOnRandomGramMatrices) {
  // Cases where rounding makes F - 1 alternate in sign between neighbouring doubles once ran into the cap.
  std::mt19937 rng(1);
  std::normal_distribution<double> normal;
  int worst = 0;
  for (int k = 0; k < 100000; ++k) {
    Eigen::Matrix<double, 4, 3> X;
    for (int i = 0; i < 12; ++i) X.data()[i] = normal(rng);
    const Eigen::Matrix3d gram = X.transpose() * X;
    const StiffnessExtremes e = stiffnessExtremes(gram);
    worst = std::max(worst, e.iterations);
    ASSERT_LE(e.iterations, 20) << "case " << k;
    ASSERT_GE(e.max, e.min);
    ASSERT_NEAR(directionalStiffness(gram, e.angleOfMax), e.max, 1e-12 * gram.trace());
    ASSERT_NEAR(directionalStiffness(gram, e.angleOfMin), e.min, 1e-12 * gram.trace());
  }
  RecordProperty("worst_iterations", std::to_string(worst));
}

TEST(Stiffness, DegenerateCases) {
  Eigen::MatrixXd X = Eigen::MatrixXd::Zero(4, 3);
  // A = C, B = 0: II(v, v) = A for every v, S constant.
  X.col(0) << 1, 2, 0, 0;
  X.col(2) = X.col(0);
  {
    const StiffnessExtremes e = stiffnessExtremes(gramOf(X));
    EXPECT_NEAR(e.max, 5.0, 1e-14);
    EXPECT_NEAR(e.min, 5.0, 1e-14);
  }
  // II = 0: S = 0.
  expectExtremesMatchSampling(Eigen::Matrix3d::Zero(), "zero");
  // A = -C, B = 0 (P = 0): the curvature ellipse centred at the origin; min and max on its axes.
  X.col(2) = -X.col(0);
  X.col(1) << 0, 0, 3, 0;
  expectExtremesMatchSampling(gramOf(X), "centred ellipse");
  {
    const StiffnessExtremes e = stiffnessExtremes(gramOf(X));
    EXPECT_NEAR(e.max, 9.0, 1e-13);
    EXPECT_NEAR(e.min, 5.0, 1e-13);
    EXPECT_NEAR(std::abs(e.angleOfMax), M_PI / 4, 1e-12);  // II(v, v) = 2 sin a cos a B: a = +-pi/4
  }
  // The "hard case": P orthogonal to the major axis, the ellipse's maximum on its axis ends.
  X.col(0) << 1, 0, 0.1, 0;  // A = P + Q, C = P - Q with P = (0, 0, 0.1, 0), Q = (1, 0, 0, 0)
  X.col(2) << -1, 0, 0.1, 0;
  X.col(1) << 0, 0.2, 0, 0;
  expectExtremesMatchSampling(gramOf(X), "hard case");
  // Collinear A, B, C (a segment, not an ellipse), and nearly so.
  X.col(0) << 1, 1, 0, 0;
  X.col(1) << 0.5, 0.5, 0, 0;
  X.col(2) << -2, -2, 0, 0;
  expectExtremesMatchSampling(gramOf(X), "segment");
  X(3, 1) = 1e-9;
  expectExtremesMatchSampling(gramOf(X), "nearly a segment");
}

}  // namespace
}  // namespace sl
