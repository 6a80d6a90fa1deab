// The sphere panel's view of S^(n-2), checked against its geometric meaning.
#include <cmath>

#include <gtest/gtest.h>

#include "frames/sphere_view.hpp"

namespace sl {
namespace {

double norm(const Vec3& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

TEST(SphereView, FourRodsShowThePointItself) {
  const Eigen::Vector3d x = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  const SphereView view(4, Eigen::Vector3d(1, 0, 0));
  const Vec3 p = view.project(x);
  EXPECT_EQ(view.space(), ViewSpace::Sphere);
  EXPECT_DOUBLE_EQ(p.x, x(0));
  EXPECT_DOUBLE_EQ(p.z, x(2));
}

TEST(SphereView, ThreeRodsUseTheEquator) {
  const SphereView view(3, Eigen::Vector2d(1, 0));
  const Vec3 p = view.project(Eigen::Vector2d(0.6, 0.8));
  EXPECT_EQ(view.space(), ViewSpace::Circle);
  EXPECT_DOUBLE_EQ(p.y, 0.8);
  EXPECT_DOUBLE_EQ(p.z, 0.0);
}

// Stereographic projection from the start's antipode: a point at angle theta from the start lands at
// distance tan(theta / 2) from the origin; the start itself at the origin.
TEST(SphereView, FiveRodsStereographicDistanceIsTanHalfAngle) {
  const Eigen::Vector4d start = Eigen::Vector4d(0.2, -0.4, 0.5, 0.7).normalized();
  const SphereView view(5, start);
  EXPECT_EQ(view.space(), ViewSpace::Stereographic);
  EXPECT_NEAR(norm(view.project(start)), 0.0, 1e-15);
  for (const Eigen::Vector4d& raw : {Eigen::Vector4d(1, 0, 0, 0), Eigen::Vector4d(0.1, 0.9, -0.3, 0.2),
                                     Eigen::Vector4d(-0.5, 0.4, -0.5, -0.6)}) {
    const Eigen::Vector4d x = raw.normalized();
    const double theta = std::acos(std::clamp(x.dot(start), -1.0, 1.0));
    EXPECT_NEAR(norm(view.project(x)), std::tan(theta / 2), 1e-12);
  }
}

// One-to-one: distinct points stay distinct (conformal maps preserve angles; here, that two points at
// the same angle from the start but in different directions project apart).
TEST(SphereView, FiveRodsSeparatesDirections) {
  const Eigen::Vector4d start(0, 0, 0, 1);
  const SphereView view(5, start);
  const Vec3 a = view.project(Eigen::Vector4d(0.6, 0, 0, 0.8));
  const Vec3 b = view.project(Eigen::Vector4d(0, 0.6, 0, 0.8));
  EXPECT_GT(std::hypot(a.x - b.x, a.y - b.y, a.z - b.z), 0.4);
  EXPECT_TRUE(std::isfinite(norm(view.project(-start))));  // the pole itself: far, but finite
}

}  // namespace
}  // namespace sl
