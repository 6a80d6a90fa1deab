// The sphere panel's view of S^(n-2), checked against its geometric meaning.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "frames/configuration_view.hpp"

namespace sl {
namespace {

double norm(const Vec3& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

TEST(ConfigurationView, FourRodsShowThePointItself) {
  const Eigen::Vector3d x = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  const ConfigurationView view(4, Eigen::Vector3d(1, 0, 0));
  const Vec3 p = view.project(x);
  EXPECT_EQ(view.space(), ViewSpace::Sphere);
  EXPECT_DOUBLE_EQ(p.x, x(0));
  EXPECT_DOUBLE_EQ(p.z, x(2));
}

TEST(ConfigurationView, ThreeRodsUseTheEquator) {
  const ConfigurationView view(3, Eigen::Vector2d(1, 0));
  const Vec3 p = view.project(Eigen::Vector2d(0.6, 0.8));
  EXPECT_EQ(view.space(), ViewSpace::Circle);
  EXPECT_DOUBLE_EQ(p.y, 0.8);
  EXPECT_DOUBLE_EQ(p.z, 0.0);
}

// The azimuthal equidistant view about the start: a point at angle theta from the start lands at distance
// theta / pi from the centre, in the direction of its component orthogonal to the start; the start itself at
// the centre.
TEST(ConfigurationView, FiveRodsDistanceFromTheCentreIsTheAngleOverPi) {
  const Eigen::Vector4d start = Eigen::Vector4d(0.2, -0.4, 0.5, 0.7).normalized();
  const ConfigurationView view(5, start);
  EXPECT_EQ(view.space(), ViewSpace::Ball);
  EXPECT_NEAR(norm(view.project(start)), 0.0, 1e-15);
  for (const Eigen::Vector4d& raw : {Eigen::Vector4d(1, 0, 0, 0), Eigen::Vector4d(0.1, 0.9, -0.3, 0.2),
                                     Eigen::Vector4d(-0.5, 0.4, -0.5, -0.6), Eigen::Vector4d(-0.2, 0.4, -0.5, -0.69)}) {
    const Eigen::Vector4d x = raw.normalized();
    const double theta = std::acos(std::clamp(x.dot(start), -1.0, 1.0));
    EXPECT_NEAR(norm(view.project(x)), theta / std::acos(-1.0), 1e-12);
  }
}

// Every point of S^3 lands inside the unit ball (the panel's glass sphere), the antipode included, and the
// view is one-to-one away from the antipode: two points at the same angle from the start in different
// directions land apart, at the same distance.
TEST(ConfigurationView, FiveRodsStayInsideTheBallAndSeparateDirections) {
  const Eigen::Vector4d start(0, 0, 0, 1);
  const ConfigurationView view(5, start);
  const Vec3 a = view.project(Eigen::Vector4d(0.6, 0, 0, 0.8));
  const Vec3 b = view.project(Eigen::Vector4d(0, 0.6, 0, 0.8));
  EXPECT_GT(std::hypot(a.x - b.x, a.y - b.y, a.z - b.z), 0.2);
  EXPECT_NEAR(norm(a), norm(b), 1e-15);
  EXPECT_NEAR(norm(view.project(-start)), 1.0, 1e-15);
  EXPECT_NEAR(norm(view.project(Eigen::Vector4d(1e-9, 0, 0, -1).normalized())), 1.0, 1e-9);
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  for (int k = 0; k < 1000; ++k) {
    const Eigen::Vector4d x =
        Eigen::Vector4d(normal(random), normal(random), normal(random), normal(random)).normalized();
    EXPECT_LE(norm(view.project(x)), 1.0 + 1e-15);
  }
}

// Near the start the view is the tangent picture, scaled by 1/pi: smooth, no 0/0.
TEST(ConfigurationView, FiveRodsIsSmoothAtTheStart) {
  const ConfigurationView view(5, Eigen::Vector4d(0, 0, 0, 1));
  const Vec3 p = view.project(Eigen::Vector4d(1e-12, 0, 0, 1).normalized());
  EXPECT_NEAR(p.x, 1e-12 / std::acos(-1.0), 1e-27);
  EXPECT_TRUE(std::isfinite(p.y) && p.y == 0.0);
}

}  // namespace
}  // namespace sl
