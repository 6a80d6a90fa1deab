// Pointwise geometry of the configuration sphere: the Gauss-equation route against Brioschi's
// formula, the Gauss equation in an orthonormal frame, symmetries, scaling, poles and seams, and the printed
// metric of the spec differenced as the author's demo does.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/curvature.hpp"
#include "geometry_support.hpp"
#include "linkage/kinetic_metric.hpp"
#include "linkage/sphere_coordinates.hpp"

namespace sl {
namespace {

using testing::chartZeroPoint;

// a - b reduced to (-pi/2, pi/2]: stiffness angles are directions.
double directionDifference(double a, double b) { return std::remainder(a - b, M_PI); }

TEST(Curvature, GaussEquationAgreesWithBrioschiOnManyPointsLengthsAndMasses) {
  double worst = 0;
  int compared = 0;
  for (double L : testing::issueBaseLengths())
    for (const auto& setting : testing::massSettings(L)) {
      const ConfigurationSurface surface(setting.chain);
      for (const Eigen::Vector3d& x : testing::testPoints(60)) {
        const double extrinsic = surface.gaussianCurvature(x);
        const double intrinsic = gaussianCurvatureIntrinsic(setting.chain, x);
        if (std::abs(intrinsic) < 1e-6) continue;  // relative agreement is meaningless where K ~ 0
        const double rel = std::abs(extrinsic - intrinsic) / std::abs(intrinsic);
        worst = std::max(worst, rel);
        ++compared;
        ASSERT_LE(rel, 1e-10) << setting.name << " L=" << L << " x=" << x.transpose() << " K=" << intrinsic;
      }
    }
  EXPECT_GT(compared, 1000);
  RecordProperty("worst_relative_difference", testing::scientific(worst));
}

TEST(Curvature, RoutesAgreeInBothChartsWhereBothAreRegular) {
  // K is a property of the point: chart 0 and chart 1 give the same value on their overlap.
  for (const auto& setting : testing::massSettings(3.0)) {
    const ConfigurationSurface surface(setting.chain);
    for (double phi : {-0.6, -0.2, 0.1, 0.5})
      for (double t : {-2.5, -1.2, 0.4, 1.0, 2.2}) {
        const Eigen::Vector3d x = chartZeroPoint(phi, t);
        const double k0 = gaussianCurvature(surface.secondFundamentalForm(0, Eigen::Vector2d(phi, t)));
        const Eigen::VectorXd c1 = coordinatesInChart(sphereChartAxes(3, 1), x);
        const double k1 = gaussianCurvature(surface.secondFundamentalForm(1, Eigen::Vector2d(c1(0), c1(1))));
        EXPECT_NEAR(k0, k1, 1e-12 * (1 + std::abs(k0))) << setting.name << " phi=" << phi << " t=" << t;
        const double b0 = bending(surface.secondFundamentalForm(0, Eigen::Vector2d(phi, t)));
        const double b1 = bending(surface.secondFundamentalForm(1, Eigen::Vector2d(c1(0), c1(1))));
        EXPECT_NEAR(b0, b1, 1e-12 * b0);
      }
  }
}

TEST(Curvature, ChartChoiceIsTheAtlasBestChart) {
  const ConfigurationSurface surface(Chain::uniform(4, 3.0));
  for (const Eigen::Vector3d& x : testing::testPoints(200)) {
    const SecondFundamentalForm form = surface.secondFundamentalFormAt(x);
    ASSERT_EQ(form.chart, bestSphereChart(x));
    const Eigen::VectorXd c = coordinatesInChart(sphereChartAxes(3, form.chart), x);
    EXPECT_NEAR(form.coords(0), c(0), 1e-15);
    EXPECT_NEAR(std::remainder(form.coords(1) - c(1), 2 * M_PI), 0.0, 1e-15);
    EXPECT_LE((form.spherePoint - x).norm(), 1e-15);
  }
}

TEST(Curvature, GaussEquationInTheOrthonormalFrame) {
  // K = <A, C> - |B|^2 and |II|^2 = |A|^2 + 2|B|^2 + |C|^2 in any g-orthonormal frame.
  for (double L : testing::issueBaseLengths())
    for (const auto& setting : testing::massSettings(L)) {
      const ConfigurationSurface surface(setting.chain);
      for (const Eigen::Vector3d& x : testing::testPoints(20)) {
        const CurvatureSample s = surface.curvatureAt(x);
        const double scale = s.bending;
        EXPECT_NEAR(s.frameGram(0, 2) - s.frameGram(1, 1), s.gaussianCurvature, 1e-12 * scale);
        EXPECT_NEAR(s.bending, surface.bending(x), 1e-12 * scale);
        // Another frame, its first vector a fixed axis crossed with x.
        const SecondFundamentalForm form = surface.secondFundamentalFormAt(x);
        Eigen::Vector3d other = x.cross(Eigen::Vector3d(0.3, -0.5, 0.8));
        if (other.norm() < 0.1) other = x.cross(Eigen::Vector3d::UnitX());
        const OrthonormalFrameForm frame = orthonormalFrameForm(form, other);
        EXPECT_NEAR(frame.gram(0, 2) - frame.gram(1, 1), s.gaussianCurvature, 1e-12 * scale) << setting.name;
        EXPECT_NEAR(frame.gram(0, 0) + 2 * frame.gram(1, 1) + frame.gram(2, 2), s.bending, 1e-12 * scale);
        // The frame is g-orthonormal.
        EXPECT_NEAR(frame.e1.dot(form.metric * frame.e1), 1.0, 1e-13);
        EXPECT_NEAR(frame.e2.dot(form.metric * frame.e2), 1.0, 1e-13);
        EXPECT_NEAR(frame.e1.dot(form.metric * frame.e2), 0.0, 1e-13);
        // Stiffness extremes do not depend on the frame; the maximising direction turns with it.
        const StiffnessExtremes turned = stiffnessExtremes(frame.gram);
        EXPECT_NEAR(turned.max, s.stiffnessMax, 1e-11 * scale);
        EXPECT_NEAR(turned.min, s.stiffnessMin, 1e-11 * scale);
        const OrthonormalFrameForm base = orthonormalFrameForm(form, chartZeroPhiDirection(s.phi, s.t));
        const double turn = std::atan2(frame.e1.dot(form.metric * base.e2), frame.e1.dot(form.metric * base.e1));
        if (s.stiffnessMax - s.stiffnessMin > 1e-6 * s.stiffnessMax) {
          EXPECT_NEAR(directionDifference(turned.angleOfMax + turn, s.stiffnessAngle), 0.0, 1e-7);
        }
      }
    }
}

TEST(Curvature, StiffnessFrameIsBuiltFromDPhiOnTheSideOfDtInEveryChart) {
  // e1 = d/dphi / |d/dphi|_g and e2 on the side of d/dt: the same tangent vectors (in R^3) whichever chart the
  // derivatives were taken in, so the stiffness angle is a property of the point and of chart 0's d/dphi.
  for (const auto& setting : testing::massSettings(3.0)) {
    const ConfigurationSurface surface(setting.chain);
    for (double phi : {-0.6, -0.1, 0.3, 0.7})
      for (double t : {-2.9, -1.3, 0.2, 1.5, 2.6}) {
        const Eigen::Vector3d x = chartZeroPoint(phi, t);
        const SecondFundamentalForm form0 = surface.secondFundamentalForm(0, Eigen::Vector2d(phi, t));
        const Eigen::VectorXd c1 = coordinatesInChart(sphereChartAxes(3, 1), x);
        const SecondFundamentalForm form1 = surface.secondFundamentalForm(1, Eigen::Vector2d(c1(0), c1(1)));
        const OrthonormalFrameForm frame0 = orthonormalFrameForm(form0, chartZeroPhiDirection(phi, t));
        const OrthonormalFrameForm frame1 = orthonormalFrameForm(form1, chartZeroPhiDirection(phi, t));
        // In chart 0's own rates: e1 along (1, 0), e2 with a positive dt component.
        EXPECT_GT(frame0.e1(0), 0.0);
        EXPECT_NEAR(frame0.e1(1), 0.0, 1e-15);
        EXPECT_GT(frame0.e2(1), 0.0);
        // As vectors of R^3, the same in chart 1.
        EXPECT_LE((form0.sphereTangent * frame0.e1 - form1.sphereTangent * frame1.e1).norm(), 1e-12);
        EXPECT_LE((form0.sphereTangent * frame0.e2 - form1.sphereTangent * frame1.e2).norm(), 1e-12);
        EXPECT_LE((frame0.gram - frame1.gram).norm(), 1e-11 * frame0.gram.norm()) << setting.name;
        // The maximising direction as a vector: g-unit, tangent, and S there is the maximum.
        const CurvatureSample s = surface.curvatureAtCoordinates(phi, t);
        const Eigen::Vector2d rates(
            form0.sphereTangent.col(0).dot(s.stiffnessDirection) / form0.sphereTangent.col(0).squaredNorm(),
            form0.sphereTangent.col(1).dot(s.stiffnessDirection) / form0.sphereTangent.col(1).squaredNorm());
        EXPECT_NEAR(s.stiffnessDirection.dot(x), 0.0, 1e-14);
        EXPECT_NEAR(rates.dot(form0.metric * rates), 1.0, 1e-12);
        const Eigen::Vector3d coefficients(rates(0) * rates(0), 2 * rates(0) * rates(1), rates(1) * rates(1));
        EXPECT_NEAR(coefficients.dot(form0.gram * coefficients), s.stiffnessMax, 1e-11 * s.bending);
      }
  }
}

TEST(Curvature, MirrorSymmetryOfTheChartIsTheAntipodalMap) {
  // Reflecting the whole linkage in the base line (y -> -y) is an isometry of the ambient mass metric for any
  // masses; it sends the sphere point x to -x, i.e. (phi, t) to (-phi, t + pi). It reverses orientation, so the
  // stiffness angle (measured from d/dphi towards d/dt) changes sign.
  for (double L : testing::issueBaseLengths())
    for (const auto& setting : testing::massSettings(L)) {
      const ConfigurationSurface surface(setting.chain);
      for (double phi : {-1.4, -0.9, -0.2, 0.0, 0.39, 1.1, 1.5})
        for (double t : {-3.0, -1.6, -0.5, 0.3, 1.34, 2.9}) {
          const CurvatureSample a = surface.curvatureAtCoordinates(phi, t);
          const CurvatureSample b = surface.curvatureAtCoordinates(-phi, t + M_PI);
          const double scale = a.bending;
          ASSERT_NEAR(a.gaussianCurvature, b.gaussianCurvature, 1e-12 * scale) << setting.name << " L=" << L;
          EXPECT_NEAR(a.bending, b.bending, 1e-12 * scale);
          EXPECT_NEAR(a.stiffnessMax, b.stiffnessMax, 1e-12 * scale);
          EXPECT_NEAR(a.stiffnessMin, b.stiffnessMin, 1e-11 * scale);
          EXPECT_NEAR(a.areaDensity, b.areaDensity, 1e-12 * a.areaDensity);
          if (a.stiffnessMax - a.stiffnessMin > 1e-6 * a.stiffnessMax) {
            EXPECT_NEAR(directionDifference(a.stiffnessAngle, -b.stiffnessAngle), 0.0, 1e-8);
          }
        }
    }
}

TEST(Curvature, ScalingEveryMassBySScalesCurvatureBendingAndStiffnessByOneOverS) {
  for (const auto& setting : testing::massSettings(3.0)) {
    const ConfigurationSurface surface(setting.chain);
    for (double s : {0.25, 3.0}) {
      Chain scaled = setting.chain;
      scaled.hingeMasses *= s;
      scaled.rodMasses *= s;
      const ConfigurationSurface scaledSurface(scaled);
      for (const Eigen::Vector3d& x : testing::testPoints(10)) {
        const CurvatureSample a = surface.curvatureAt(x), b = scaledSurface.curvatureAt(x);
        EXPECT_NEAR(b.gaussianCurvature * s, a.gaussianCurvature, 1e-12 * a.bending) << setting.name;
        EXPECT_NEAR(b.bending * s, a.bending, 1e-12 * a.bending);
        EXPECT_NEAR(b.stiffnessMax * s, a.stiffnessMax, 1e-12 * a.bending);
        EXPECT_NEAR(b.stiffnessMin * s, a.stiffnessMin, 1e-11 * a.bending);
        EXPECT_NEAR(b.areaDensity, a.areaDensity * s, 1e-12 * b.areaDensity);  // sqrt(det(s g)) = s sqrt(det g)
        if (a.stiffnessMax - a.stiffnessMin > 1e-6 * a.stiffnessMax) {
          EXPECT_NEAR(directionDifference(a.stiffnessAngle, b.stiffnessAngle), 0.0, 1e-9);
        }
      }
    }
  }
}

TEST(Curvature, ChartZeroPolesAreOrdinaryPoints) {
  // At phi = +-pi/2 chart 0 is singular; the values come from chart 1 and are continuous with nearby points.
  for (double L : testing::issueBaseLengths())
    for (const auto& setting : testing::massSettings(L)) {
      const ConfigurationSurface surface(setting.chain);
      for (double pole : {M_PI / 2, -M_PI / 2})
        for (double t : {-2.0, 0.0, 0.7, M_PI / 2}) {
          const CurvatureSample at = surface.curvatureAtCoordinates(pole, t);
          const CurvatureSample near = surface.curvatureAtCoordinates(pole - std::copysign(1e-8, pole), t);
          EXPECT_EQ(at.chart, 1);
          ASSERT_TRUE(std::isfinite(at.gaussianCurvature) && std::isfinite(at.stiffnessAngle));
          const double scale = at.bending;
          EXPECT_NEAR(at.gaussianCurvature, near.gaussianCurvature, 1e-7 * scale) << setting.name << " L=" << L;
          EXPECT_NEAR(at.bending, near.bending, 1e-7 * scale);
          EXPECT_NEAR(at.stiffnessMax, near.stiffnessMax, 1e-7 * scale);
          EXPECT_NEAR(at.stiffnessMin, near.stiffnessMin, 1e-7 * scale);
          EXPECT_NEAR(directionDifference(at.stiffnessAngle, near.stiffnessAngle), 0.0, 1e-6);
          // The x overload agrees with the coordinate one (its t at the pole is 0, its d/dphi another vector).
          const CurvatureSample fromX = surface.curvatureAt(at.spherePoint);
          EXPECT_EQ(fromX.gaussianCurvature, at.gaussianCurvature);
          EXPECT_NEAR(fromX.stiffnessMax, at.stiffnessMax, 1e-12 * scale);
        }
      // Near a pole chart 0 itself still works, ill-conditioned as 1/cos(phi): it agrees with chart 1.
      for (double gap : {1e-1, 1e-2, 1e-3}) {
        const double phi = M_PI / 2 - gap, t = 0.4;
        const double viaChartZero = gaussianCurvature(surface.secondFundamentalForm(0, Eigen::Vector2d(phi, t)));
        const CurvatureSample viaBest = surface.curvatureAtCoordinates(phi, t);
        EXPECT_EQ(viaBest.chart, 1);
        EXPECT_NEAR(viaChartZero, viaBest.gaussianCurvature, 1e-13 / (gap * gap) * viaBest.bending)
            << setting.name << " gap " << gap;
      }
    }
}

TEST(Curvature, SeamsOfChartZeroAreOrdinaryPoints) {
  // On t = +-pi/2 the published metric breaks down; here the values are smooth across it.
  for (const auto& setting : testing::massSettings(3.0)) {
    const ConfigurationSurface surface(setting.chain);
    for (double phi : {-1.0, -0.3, 0.2, 0.8})
      for (double seam : {M_PI / 2, -M_PI / 2}) {
        const CurvatureSample on = surface.curvatureAtCoordinates(phi, seam);
        const CurvatureSample below = surface.curvatureAtCoordinates(phi, seam - 1e-7);
        const CurvatureSample above = surface.curvatureAtCoordinates(phi, seam + 1e-7);
        const double scale = on.bending;
        EXPECT_NEAR(on.gaussianCurvature, 0.5 * (below.gaussianCurvature + above.gaussianCurvature), 1e-10 * scale);
        EXPECT_NEAR(on.stiffnessMax, 0.5 * (below.stiffnessMax + above.stiffnessMax), 1e-10 * scale);
        EXPECT_NEAR(gaussianCurvatureIntrinsic(setting.chain, on.spherePoint), on.gaussianCurvature, 1e-10 * scale);
      }
  }
}

// The spec's printed metric (metric4), Brioschi's formula with central differences of step 1e-4.
MetricJet publishedMetricDifferences(double L, double phi, double t, double h) {
  const auto g = [&](double du, double dv) { return kineticMetricPublished(L, phi + du, t + dv); };
  const Eigen::Matrix2d g0 = g(0, 0), gu = g(h, 0), gd = g(-h, 0), gr = g(0, h), gl = g(0, -h);
  MetricJet m;
  m.g = g0;
  m.d0 = (gu - gd) / (2 * h);
  m.d1 = (gr - gl) / (2 * h);
  m.d00 = (gu - 2 * g0 + gd) / (h * h);
  m.d11 = (gr - 2 * g0 + gl) / (h * h);
  m.d01 = (g(h, h) - g(h, -h) - g(-h, h) + g(-h, -h)) / (4 * h * h);
  return m;
}

TEST(Curvature, PrintedMetricDifferencedAgreesAwayFromPolesAndSeams) {
  double worst = 0;
  for (double L : testing::issueBaseLengths()) {
    const ConfigurationSurface surface(Chain::uniform(4, L));
    for (double phi : {-1.2, -0.7, -0.1, 0.39, 0.9, 1.3})
      for (double t : {-2.8, -2.0, -1.0, 0.2, 1.0, 1.34, 2.4}) {
        const double exact = surface.curvatureAtCoordinates(phi, t).gaussianCurvature;
        const double differenced = brioschiCurvature(publishedMetricDifferences(L, phi, t, 1e-4));
        const double error = std::abs(differenced - exact) / std::max(1.0, std::abs(exact));
        worst = std::max(worst, error);
        EXPECT_LE(error, 1e-4) << "L=" << L << " phi=" << phi << " t=" << t;
      }
  }
  RecordProperty("worst_error", testing::scientific(worst));
}

TEST(Curvature, ValuesAtLThreeUnitHingeMasses) {
  // docs/geometry.md: min K ~ -0.272 near (0.39, 1.34) and its mirror; max K ~ 4.15; K at the pole 143/35.
  const ConfigurationSurface surface(Chain::uniform(4, 3.0));
  EXPECT_NEAR(surface.curvatureAtCoordinates(0.3869716820, 1.3386317898).gaussianCurvature, -0.271846, 1e-6);
  EXPECT_NEAR(surface.curvatureAtCoordinates(-0.3869716820, 1.3386317898 - M_PI).gaussianCurvature, -0.271846, 1e-6);
  EXPECT_NEAR(surface.curvatureAtCoordinates(1.5058249100, -1.3836475165).gaussianCurvature, 4.152120, 1e-6);
  EXPECT_NEAR(surface.gaussianCurvature(Eigen::Vector3d::UnitZ()), 4.0857142857142857, 1e-12);
}

TEST(Curvature, RejectsChainsThatAreNotFourRods) {
  EXPECT_THROW(ConfigurationSurface(Chain::uniform(5, 4.0)), std::invalid_argument);
  EXPECT_THROW(ConfigurationSurface(Chain::uniform(4, 4.5)), std::invalid_argument);
  Chain massless = Chain::uniform(4, 3.0);
  massless.hingeMasses.setZero();
  EXPECT_THROW(ConfigurationSurface{massless}, std::invalid_argument);
  EXPECT_THROW(ConfigurationSurface(Chain::uniform(4, 3.0)).secondFundamentalForm(2, Eigen::Vector2d(0, 0)),
               std::invalid_argument);
  EXPECT_THROW(kineticMetricJet(Chain::uniform(5, 4.0), 0, Eigen::Vector2d(0, 0)), std::invalid_argument);
}

}  // namespace
}  // namespace sl
