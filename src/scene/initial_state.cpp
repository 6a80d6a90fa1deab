#include "scene/initial_state.hpp"

#include <cmath>

#include "linkage/chart.hpp"
#include "linkage/kinetic_metric.hpp"
#include "linkage/sphere_coordinates.hpp"

namespace sl {

double kineticSpeedSquared(const Chain& chain, const Eigen::VectorXd& spherePoint, const Eigen::VectorXd& sphereVelocity) {
  const Eigen::VectorXd hingeVelocity = sphereJacobian(chain, spherePoint) * sphereVelocity;
  return hingeVelocity.dot(stackedMassMatrix(chain) * hingeVelocity);
}

InitialState initialStateFromScene(const Scene& scene) {
  const InitialSpec& spec = scene.initial;
  InitialState state;
  if (spec.kind == InitialSpec::Kind::ChartCoordinates) {
    state.spherePoint = spherePointFromCoordinates<double>(spec.coords);
    state.sphereVelocity = sphereVelocityFromCoordinateRates(spec.coords, spec.velocity);
  } else {
    state.spherePoint = spec.dragPoint.normalized();
    const Eigen::VectorXd& x = state.spherePoint;
    state.sphereVelocity = spec.dragDirection - x * x.dot(spec.dragDirection);
  }
  if (spec.unitSpeed) {
    const double speed = std::sqrt(kineticSpeedSquared(scene.chain, state.spherePoint, state.sphereVelocity));
    if (speed > 0) state.sphereVelocity /= speed;
  }
  return state;
}

}  // namespace sl
