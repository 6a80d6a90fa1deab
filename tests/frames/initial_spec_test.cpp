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

InitialSpec dragSpec(Eigen::Vector3d point, Eigen::Vector3d direction, bool unitSpeed) {
  InitialSpec spec;
  spec.kind = InitialSpec::Kind::Drag;
  spec.dragPoint = point;
  spec.dragDirection = direction;
  spec.unitSpeed = unitSpeed;
  return spec;
}

// A drag direction's scale never decides whether the start moves. With unit_speed, huge and tiny
// directions give the same unit-speed start as a plain one; without it, a huge one is refused for its
// overflowing energy and a tiny one for its underflowing energy, each with the reason.
TEST(InitialSpec, DragDirectionsOfAnyScale) {
  const Chain chain = Chain::uniform(4, 3.0);
  const Eigen::Vector3d point(0.3, 0.4, 0.8), across(1, -1, 0.2);
  const InitialState plain = initialStateFromSpec(chain, dragSpec(point, across, true));
  for (const double scale : {1e308, 1e-300}) {  // (subnormal inputs carry fewer digits themselves)
    SCOPED_TRACE(scale);
    const InitialState scaled = initialStateFromSpec(chain, dragSpec(point, scale * across, true));
    ASSERT_TRUE(scaled.sphereVelocity.allFinite());
    EXPECT_LT((scaled.sphereVelocity - plain.sphereVelocity).norm(), 1e-12);
  }
  const Eigen::Vector3d huge(1e308, 1e308, 1e308);
  EXPECT_NEAR(speedSquared(chain, initialStateFromSpec(chain, dragSpec(point, huge, true))), 1.0, 1e-12);
  try {
    initialStateFromSpec(chain, dragSpec(point, huge, false));
    FAIL() << "a drag whose kinetic energy overflows was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("overflows"), std::string::npos) << error.what();
  }
  try {
    initialStateFromSpec(chain, dragSpec(point, 1e-300 * across, false));
    FAIL() << "a drag whose kinetic energy underflows to zero was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("underflows"), std::string::npos) << error.what();
  }
}

// A direction along the point leaves only rounding noise across the sphere: refused with and without
// unit_speed (a frozen linkage, or noise blown up to an arbitrary direction), whatever its scale.
TEST(InitialSpec, DragAlongThePointIsRefused) {
  const Chain chain = Chain::uniform(4, 3.0);
  const Eigen::Vector3d point(0.3, 0.4, 0.8);
  for (const double scale : {1.0, -7.0, 1e-300, 1e300})
    for (const bool unitSpeed : {false, true}) {
      SCOPED_TRACE(std::to_string(scale) + (unitSpeed ? " unit_speed" : ""));
      try {
        initialStateFromSpec(chain, dragSpec(point, scale * point, unitSpeed));
        FAIL() << "a drag along the point was accepted";
      } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("no component tangent"), std::string::npos) << error.what();
      }
    }
}

}  // namespace
}  // namespace sl
