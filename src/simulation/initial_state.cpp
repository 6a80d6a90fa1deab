#include "simulation/initial_state.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "linkage/chart.hpp"
#include "linkage/sphere_coordinates.hpp"

namespace sl {

namespace {
void requireSize(const Eigen::VectorXd& v, Eigen::Index size, const std::string& what) {
  if (v.size() != size)
    throw std::invalid_argument(what + " needs " + std::to_string(size) + " components, got " +
                                std::to_string(v.size()));
  if (!v.allFinite()) throw std::invalid_argument(what + " has a non-finite component");
}
}  // namespace

InitialState initialStateFromChart(const Chain& chain, const Eigen::VectorXd& coords, const Eigen::VectorXd& rates) {
  requireSize(coords, chain.sphereDimension(), "chart coordinates");
  requireSize(rates, chain.sphereDimension(), "chart rates");
  return {spherePointFromCoordinates<double>(coords), sphereVelocityFromCoordinateRates(coords, rates)};
}

double speedSquared(const Chain& chain, const InitialState& start) {
  const Eigen::VectorXd stacked = sphereJacobian(chain, start.spherePoint) * start.sphereVelocity;
  return 2.0 * kineticEnergy(ambientMassMatrix(chain),
                             Eigen::Map<const Eigen::Matrix2Xd>(stacked.data(), 2, chain.hingeCount()));
}

InitialState initialStateFromDrag(const Chain& chain, const Eigen::VectorXd& point, const Eigen::VectorXd& direction,
                                  bool unitSpeed) {
  requireSize(point, chain.rods - 1, "drag start point");
  requireSize(direction, chain.rods - 1, "drag direction");
  if (point.norm() == 0.0) throw std::invalid_argument("drag start point is zero; it must be a point of the sphere");
  InitialState start;
  start.spherePoint = point.normalized();
  start.sphereVelocity = direction - start.spherePoint * start.spherePoint.dot(direction);
  if (unitSpeed) {
    const double speed2 = speedSquared(chain, start);
    if (!(speed2 > 1e-300))
      throw std::invalid_argument("drag direction has no component tangent to the sphere at the start point");
    start.sphereVelocity /= std::sqrt(speed2);
  }
  return start;
}

void validateInitialState(const Chain& chain, const InitialState& start) {
  requireSize(start.spherePoint, chain.rods - 1, "initial sphere point");
  requireSize(start.sphereVelocity, chain.rods - 1, "initial sphere velocity");
  if (std::abs(start.spherePoint.norm() - 1.0) > 1e-9)
    throw std::invalid_argument("initial sphere point must be a unit vector, |x| = " +
                                std::to_string(start.spherePoint.norm()));
  if (std::abs(start.spherePoint.dot(start.sphereVelocity)) > 1e-9 * (1.0 + start.sphereVelocity.norm()))
    throw std::invalid_argument("initial sphere velocity must be tangent (x . xdot = 0)");
}

InitialState initialStateFromSpec(const Chain& chain, const InitialSpec& spec) {
  if (spec.kind == InitialSpec::Kind::Drag) {
    return initialStateFromDrag(chain, spec.dragPoint, spec.dragDirection, spec.unitSpeed);
  }
  InitialState start = initialStateFromChart(chain, spec.coords, spec.velocity);
  const double speed = std::sqrt(speedSquared(chain, start));
  if (spec.unitSpeed && speed > 0) start.sphereVelocity /= speed;
  return start;
}

}  // namespace sl
