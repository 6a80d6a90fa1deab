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

namespace {

// Scales a velocity to unit speed without overflow: the direction is brought to size 1 first, so a velocity of
// 1e300 (or 1e-300) keeps its direction instead of becoming inf (or 0) on the way.
void toUnitSpeed(const Chain& chain, InitialState& start, const char* what) {
  const double largest = start.sphereVelocity.cwiseAbs().maxCoeff();
  if (largest > 0) start.sphereVelocity /= largest;
  const double speed2 = speedSquared(chain, start);
  if (!(speed2 > 1e-300)) throw std::invalid_argument(std::string(what) + " moves nothing; unit_speed needs a motion");
  start.sphereVelocity /= std::sqrt(speed2);
}

// Without unit_speed the velocity is used as given: it must move the linkage, at a finite kinetic energy.
void requireFiniteMotion(const Chain& chain, const InitialState& start, const char* what) {
  const double speed2 = speedSquared(chain, start);
  if (!std::isfinite(speed2))
    throw std::invalid_argument(std::string(what) +
                                " is so large that the kinetic energy overflows; expected a smaller velocity (or "
                                "unit_speed)");
  if (!(speed2 > 0)) throw std::invalid_argument(std::string(what) + " is zero: nothing moves");
}

}  // namespace

InitialState initialStateFromDrag(const Chain& chain, const Eigen::VectorXd& point, const Eigen::VectorXd& direction,
                                  bool unitSpeed) {
  requireSize(point, chain.rods - 1, "drag start point");
  requireSize(direction, chain.rods - 1, "drag direction");
  if (point.norm() == 0.0) throw std::invalid_argument("drag start point is zero; it must be a point of the sphere");
  InitialState start;
  start.spherePoint = point.normalized();
  start.sphereVelocity = direction - start.spherePoint * start.spherePoint.dot(direction);
  if (unitSpeed)
    toUnitSpeed(chain, start, "the drag direction, once its part along the point is removed,");
  else
    requireFiniteMotion(chain, start, "the drag direction's part tangent to the sphere");
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
  // Where the chart is singular (phi = +-pi/2 for 4 rods: t is undefined there) a non-zero chart velocity can
  // be zero on the sphere: a frozen linkage, or rounding noise that unit_speed would blow up to any direction.
  const double rates = spec.velocity.cwiseAbs().maxCoeff();
  if (rates > 0 && !(start.sphereVelocity.cwiseAbs().maxCoeff() > 1e-9 * rates))
    throw std::invalid_argument(
        "the chart velocity moves nothing at this point (a pole of the chart, where a coordinate is undefined); "
        "expected a velocity along the other coordinates, or a drag start");
  if (spec.unitSpeed)
    toUnitSpeed(chain, start, "the velocity");
  else
    requireFiniteMotion(chain, start, "the velocity");
  return start;
}

}  // namespace sl
