// The start of the motion: chart coordinates and drags become a point and a tangent vector of the sphere.
#include <gtest/gtest.h>

#include "frames/scene_start.hpp"
#include "linkage/kinetic_metric.hpp"
#include "linkage/sphere_coordinates.hpp"
#include "simulation/initial_state.hpp"

namespace sl {
namespace {

Scene chartStart(int rods, double base, Eigen::VectorXd coords, Eigen::VectorXd velocity, bool unitSpeed) {
  Scene scene;
  scene.chain = Chain::uniform(rods, base);
  scene.initial.coords = std::move(coords);
  scene.initial.velocity = std::move(velocity);
  scene.initial.unitSpeed = unitSpeed;
  return scene;
}

TEST(SceneStart, ChartVelocityMatchesDifferencesOfTheChart) {
  const Eigen::Vector3d coords(0.2, -0.4, 0.7), rates(0.3, 1.1, -0.5);
  const InitialState start = sceneStart(chartStart(5, 4.0, coords, rates, false));
  const double h = 1e-6;
  const Eigen::VectorXd forward = spherePointFromCoordinates<double>(Eigen::VectorXd(coords + h * rates));
  const Eigen::VectorXd backward = spherePointFromCoordinates<double>(Eigen::VectorXd(coords - h * rates));
  EXPECT_LT((start.sphereVelocity - (forward - backward) / (2 * h)).norm(), 1e-8);
  EXPECT_NEAR(start.spherePoint.norm(), 1.0, 1e-15);
}

// Unit speed against the chart route: rates^T h rates with h the pullback metric in the chart.
TEST(SceneStart, UnitSpeedNormalisesTheKineticMetric) {
  Scene scene = chartStart(4, 3.0, Eigen::Vector2d(0.3, 0.2), Eigen::Vector2d(0.5, 0.7), true);
  scene.chain.rodMasses = Eigen::Vector4d(0.5, 1, 0, 2);
  const InitialState start = sceneStart(scene);
  const Eigen::MatrixXd metric = kineticMetricPullback(scene.chain, sphereChartAxes(3, 0), scene.initial.coords);
  const Eigen::VectorXd rates = coordinateRatesFromSphereVelocity(scene.initial.coords, start.sphereVelocity);
  EXPECT_NEAR(rates.dot(metric * rates), 1.0, 1e-12);
  // Same direction as asked.
  EXPECT_NEAR(rates.normalized().dot(scene.initial.velocity.normalized()), 1.0, 1e-12);
}

TEST(SceneStart, DragNormalisesThePointAndKeepsTheTangentPart) {
  Scene scene;
  scene.chain = Chain::uniform(4, 3.0);
  scene.initial.kind = InitialSpec::Kind::Drag;
  scene.initial.dragPoint = Eigen::Vector3d(2, 0, 0);
  scene.initial.dragDirection = Eigen::Vector3d(5, 0.5, -0.25);
  const InitialState start = sceneStart(scene);
  EXPECT_TRUE(start.spherePoint.isApprox(Eigen::Vector3d(1, 0, 0)));
  EXPECT_TRUE(start.sphereVelocity.isApprox(Eigen::Vector3d(0, 0.5, -0.25)));
  scene.initial.unitSpeed = true;
  const InitialState unit = sceneStart(scene);
  EXPECT_NEAR(speedSquared(scene.chain, unit), 1.0, 1e-12);
}

}  // namespace
}  // namespace sl
