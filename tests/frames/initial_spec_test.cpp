// The start of the motion as a scene states it (simulation/initial_state.hpp, initialStateFromSpec): chart
// coordinates and drags become a point and a tangent vector of the sphere.
#include <gtest/gtest.h>

#include "contracts/run_config.hpp"
#include "linkage/kinetic_metric.hpp"
#include "linkage/sphere_coordinates.hpp"
#include "simulation/initial_state.hpp"

namespace sl {
namespace {

InitialSpec chartSpec(Eigen::VectorXd coords, Eigen::VectorXd velocity, bool unitSpeed) {
  InitialSpec spec;
  spec.coords = std::move(coords);
  spec.velocity = std::move(velocity);
  spec.unitSpeed = unitSpeed;
  return spec;
}

TEST(InitialSpec, ChartVelocityMatchesDifferencesOfTheChart) {
  const Eigen::Vector3d coords(0.2, -0.4, 0.7), rates(0.3, 1.1, -0.5);
  const InitialState start = initialStateFromSpec(Chain::uniform(5, 4.0), chartSpec(coords, rates, false));
  const double h = 1e-6;
  const Eigen::VectorXd forward = spherePointFromCoordinates<double>(Eigen::VectorXd(coords + h * rates));
  const Eigen::VectorXd backward = spherePointFromCoordinates<double>(Eigen::VectorXd(coords - h * rates));
  EXPECT_LT((start.sphereVelocity - (forward - backward) / (2 * h)).norm(), 1e-8);
  EXPECT_NEAR(start.spherePoint.norm(), 1.0, 1e-15);
}

// Unit speed against the chart route: rates^T h rates with h the pullback metric in the chart.
TEST(InitialSpec, UnitSpeedNormalisesTheKineticMetric) {
  Chain chain = Chain::uniform(4, 3.0);
  chain.rodMasses = Eigen::Vector4d(0.5, 1, 0, 2);
  const InitialSpec spec = chartSpec(Eigen::Vector2d(0.3, 0.2), Eigen::Vector2d(0.5, 0.7), true);
  const InitialState start = initialStateFromSpec(chain, spec);
  const Eigen::MatrixXd metric = kineticMetricPullback(chain, sphereChartAxes(3, 0), spec.coords);
  const Eigen::VectorXd rates = coordinateRatesFromSphereVelocity(spec.coords, start.sphereVelocity);
  EXPECT_NEAR(rates.dot(metric * rates), 1.0, 1e-12);
  // Same direction as asked.
  EXPECT_NEAR(rates.normalized().dot(spec.velocity.normalized()), 1.0, 1e-12);
}

TEST(InitialSpec, DragNormalisesThePointAndKeepsTheTangentPart) {
  const Chain chain = Chain::uniform(4, 3.0);
  InitialSpec spec;
  spec.kind = InitialSpec::Kind::Drag;
  spec.dragPoint = Eigen::Vector3d(2, 0, 0);
  spec.dragDirection = Eigen::Vector3d(5, 0.5, -0.25);
  const InitialState start = initialStateFromSpec(chain, spec);
  EXPECT_TRUE(start.spherePoint.isApprox(Eigen::Vector3d(1, 0, 0)));
  EXPECT_TRUE(start.sphereVelocity.isApprox(Eigen::Vector3d(0, 0.5, -0.25)));
  spec.unitSpeed = true;
  const InitialState unit = initialStateFromSpec(chain, spec);
  EXPECT_NEAR(speedSquared(chain, unit), 1.0, 1e-12);
}

}  // namespace
}  // namespace sl
