#include "simulation/initial_state.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "contracts/limits.hpp"
#include "linkage/chart.hpp"
#include "linkage/sphere_coordinates.hpp"
#include "simulation/constraint_solver.hpp"
#include "simulation/normal_draws.hpp"

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

Eigen::Matrix2Xd hingeVelocitiesOnSphere(const Chain& chain, const Eigen::VectorXd& x, const Eigen::VectorXd& xdot) {
  if (chain.rods <= kWholeJacobianRods) {
    const Eigen::VectorXd stacked = sphereJacobian(chain, x) * xdot;
    return Eigen::Map<const Eigen::Matrix2Xd>(stacked.data(), 2, chain.hingeCount());
  }
  using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;
  VectorX<Dual> dual(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) dual(i) = Dual(x(i), Eigen::Matrix<double, 1, 1>(xdot(i)));
  const HingeMatrix<Dual> moving = hingePositionsOnSphere<Dual>(chain, dual);
  Eigen::Matrix2Xd velocities(2, chain.hingeCount());
  for (Eigen::Index h = 0; h < velocities.cols(); ++h)
    for (int xy = 0; xy < 2; ++xy)
      velocities(xy, h) = moving(xy, h).derivatives().size() ? moving(xy, h).derivatives()(0) : 0.0;
  return velocities;
}

double speedSquared(const Chain& chain, const InitialState& start) {
  if (start.byHinges()) return 2.0 * kineticEnergy(ambientMassMatrix(chain), start.hingeVelocities);
  return 2.0 * kineticEnergy(ambientMassMatrix(chain),
                             hingeVelocitiesOnSphere(chain, start.spherePoint, start.sphereVelocity));
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
// `given`: whether the velocity as given was non-zero (a tiny one can underflow to zero on the way).
void requireFiniteMotion(const Chain& chain, const InitialState& start, const char* what, bool given) {
  const double speed2 = speedSquared(chain, start);
  if (!std::isfinite(speed2))
    throw std::invalid_argument(std::string(what) +
                                " is so large that the kinetic energy overflows; expected a smaller velocity (or "
                                "unit_speed)");
  if (!(speed2 > 0))
    throw std::invalid_argument(std::string(what) +
                                (given ? " is so small that the kinetic energy underflows to zero; expected a larger "
                                         "velocity (or unit_speed)"
                                       : " is zero: nothing moves"));
}

}  // namespace

InitialState initialStateFromDrag(const Chain& chain, const Eigen::VectorXd& point, const Eigen::VectorXd& direction,
                                  bool unitSpeed) {
  requireSize(point, chain.rods - 1, "drag start point");
  requireSize(direction, chain.rods - 1, "drag direction");
  if ((point.array() == 0).all())
    throw std::invalid_argument("drag start point is zero; it must be a point of the sphere");
  InitialState start;
  start.spherePoint = point.stableNormalized();
  // The tangent part is taken of the direction brought to size 1 first (its largest component), so that
  // [1e308, 1e308, 1e308] does not overflow on the way and [1e-300, 0, 0] does not vanish. A direction along the
  // point leaves only rounding noise, which would be a frozen linkage or, with unit_speed, noise blown up to an
  // arbitrary direction: refused at a relative threshold.
  const double largest = direction.cwiseAbs().maxCoeff();
  const Eigen::VectorXd unit = largest > 0 ? Eigen::VectorXd(direction / largest) : direction;
  const Eigen::VectorXd tangent = unit - start.spherePoint * start.spherePoint.dot(unit);
  if (!(tangent.stableNorm() > 1e-12 * unit.stableNorm()))
    throw std::invalid_argument(
        "the drag direction has no component tangent to the sphere at the point (it is zero or along the point); "
        "expected a release direction across it");
  if (unitSpeed) {
    start.sphereVelocity = tangent;
    toUnitSpeed(chain, start, "the drag direction, once its part along the point is removed,");
  } else {
    start.sphereVelocity = tangent * largest;  // may overflow to inf: refused next, with the reason
    requireFiniteMotion(chain, start, "the drag direction's part tangent to the sphere", largest > 0);
  }
  return start;
}

void validateInitialState(const Chain& chain, const InitialState& start) {
  if (start.byHinges()) {
    if (start.hinges.cols() != chain.hingeCount() || start.hingeVelocities.cols() != chain.hingeCount())
      throw std::invalid_argument("a start by hinges needs n-1 = " + std::to_string(chain.hingeCount()) +
                                  " hinge positions and velocities");
    if (!start.hinges.allFinite() || !start.hingeVelocities.allFinite())
      throw std::invalid_argument("a start by hinges has a non-finite component");
    if (rodLengthError(chain, start.hinges) > 1e-9)
      throw std::invalid_argument("the start's hinges are not on the rod constraints");
    return;
  }
  requireSize(start.spherePoint, chain.rods - 1, "initial sphere point");
  requireSize(start.sphereVelocity, chain.rods - 1, "initial sphere velocity");
  if (std::abs(start.spherePoint.norm() - 1.0) > 1e-9)
    throw std::invalid_argument("initial sphere point must be a unit vector, |x| = " +
                                std::to_string(start.spherePoint.norm()));
  if (std::abs(start.spherePoint.dot(start.sphereVelocity)) > 1e-9 * (1.0 + start.sphereVelocity.norm()))
    throw std::invalid_argument("initial sphere velocity must be tangent (x . xdot = 0)");
}

Eigen::Matrix2Xd arcHinges(int rods, double baseLength) {
  // Turning angle theta of the whole arc: n chords of length 1 on a circle of radius R subtend theta / n each,
  // R = 1 / (2 sin(theta / 2n)), and the arc's chord 2 R sin(theta / 2) = sin(theta / 2) / sin(theta / 2n)
  // falls from n (theta -> 0, taut) to 0 (theta = 2 pi): bisect it onto L.
  const double pi = std::acos(-1.0);
  auto chord = [&](double theta) { return std::sin(0.5 * theta) / std::sin(0.5 * theta / rods); };
  double low = 1e-12, high = 2 * pi - 1e-12;
  for (int i = 0; i < 200; ++i) {
    const double middle = 0.5 * (low + high);
    (chord(middle) > baseLength ? low : high) = middle;
  }
  const double theta = 0.5 * (low + high), radius = 0.5 / std::sin(0.5 * theta / rods);
  // The centre above the chord's midpoint; p0 at angle -pi/2 - theta/2 from it, each rod turning theta / n.
  const double centreY = radius * std::cos(0.5 * theta), start = -0.5 * pi - 0.5 * theta;
  Eigen::Matrix2Xd hinges(2, rods - 1);
  for (int k = 1; k < rods; ++k) {
    const double angle = start + theta * k / rods;
    hinges.col(k - 1) = Eigen::Vector2d(0.5 * baseLength + radius * std::cos(angle), centreY + radius * std::sin(angle));
  }
  return hinges;
}

InitialState initialStateFromHinges(const Chain& chain, const InitialSpec& spec, StartAdjustment& adjustment) {
  const Eigen::Index count = chain.hingeCount();
  InitialState start;
  start.hinges = spec.shape == InitialSpec::Shape::Arc ? arcHinges(chain.rods, chain.baseLength) : spec.hinges;
  if (start.hinges.cols() != count)
    throw std::invalid_argument("expected n-1 = " + std::to_string(count) + " hinge positions");
  if (spec.hingeVelocities.cols() > 0) {
    start.hingeVelocities = spec.hingeVelocities;
  } else if (spec.pushSeed >= 0) {
    NormalDraws draws(static_cast<unsigned long>(spec.pushSeed));
    const Eigen::VectorXd random = draws.vector(2 * count);
    start.hingeVelocities = spec.pushSize * Eigen::Map<const Eigen::Matrix2Xd>(random.data(), 2, count);
  } else {
    start.hingeVelocities = Eigen::Matrix2Xd::Zero(2, count);
    if (spec.pushHinge >= 1 && spec.pushHinge <= count) start.hingeVelocities.col(spec.pushHinge - 1) = spec.pushVelocity;
  }
  if (start.hingeVelocities.cols() != count)
    throw std::invalid_argument("expected n-1 = " + std::to_string(count) + " hinge velocities");
  if (!start.hinges.allFinite() || !start.hingeVelocities.allFinite())
    throw std::invalid_argument("the hinges or their velocities have a non-finite component");
  // Onto the constraints: positions by Newton (each step the mass-orthogonal least correction), then velocities.
  ConstraintSolver solver(chain);
  const Eigen::Matrix2Xd given = start.hinges, givenVelocities = start.hingeVelocities;
  Eigen::Matrix2Xd rods, correction, relative;
  bool placed = false;
  for (int iteration = 0; iteration < 50 && !placed; ++iteration) {
    solver.rodVectors(start.hinges, rods);
    const Eigen::VectorXd residual = -0.5 * (rods.colwise().squaredNorm().array() - 1.0).matrix().transpose();
    placed = residual.cwiseAbs().maxCoeff() < 1e-15;
    if (placed) break;
    try {
      solver.solve(start.hinges, residual, correction);
    } catch (const ConstraintRankLoss&) {
      throw std::invalid_argument("the hinges put every rod on one line (folded flat or stretched straight), where "
                                  "the motion is not determined; expected hinges off that line");
    }
    start.hinges += correction;
  }
  if (!start.hinges.allFinite() || rodLengthError(chain, start.hinges) > 1e-12)
    throw std::invalid_argument("the hinges cannot be placed on the rod constraints from these positions (each rod "
                                "joins neighbours 1 apart, the first from (0, 0), the last to (L, 0))");
  solver.rodVectors(start.hinges, rods);
  ConstraintSolver::relativeVelocities(start.hingeVelocities, relative);
  try {
    solver.solve(start.hinges, -(rods.cwiseProduct(relative)).colwise().sum().transpose(), correction);
  } catch (const ConstraintRankLoss&) {
    throw std::invalid_argument("the hinges put every rod on one line (folded flat or stretched straight), where "
                                "the motion is not determined; expected hinges off that line");
  }
  start.hingeVelocities += correction;
  adjustment.positions = (start.hinges - given).colwise().norm().maxCoeff();
  const double largest = givenVelocities.colwise().norm().maxCoeff();
  adjustment.velocities = largest > 0 ? (start.hingeVelocities - givenVelocities).colwise().norm().maxCoeff() / largest : 0;
  const double speed2 = speedSquared(chain, start);
  if (!(speed2 > 0) || !std::isfinite(speed2))
    throw std::invalid_argument("the hinge velocities move nothing along the rod constraints (or overflow)");
  if (spec.unitSpeed) start.hingeVelocities /= std::sqrt(speed2);
  // A chain with a configuration sphere (n-2 < L < n): the start's point on it too, for the views.
  if (!chain.isSlack()) start.spherePoint = spherePointFromHinges(chain, start.hinges);
  return start;
}

InitialState initialStateFromSpec(const Chain& chain, const InitialSpec& spec, StartAdjustment* adjustment) {
  if (spec.kind == InitialSpec::Kind::Hinges) {
    StartAdjustment ignored;
    return initialStateFromHinges(chain, spec, adjustment ? *adjustment : ignored);
  }
  if (chain.isSlack())
    throw std::invalid_argument("a slack chain (L <= n-2) has no configuration sphere and no chart; expected a start "
                                "by \"hinges\"");
  if (spec.namesAMotion()) {
    // Found by the inverse problems, which this stage does not know: the commands resolve it first.
    if (!spec.motion)
      throw std::invalid_argument("the start names a found motion (connect or periodic) that was not resolved");
    InitialState start(spec.motion->spherePoint, spec.motion->sphereVelocity);
    validateInitialState(chain, start);
    // `arrival` rescales the found motion's speed (length / arrival): a tiny arrival overflows its energy.
    if (!std::isfinite(speedSquared(chain, start)))
      throw std::invalid_argument("the found motion's speed (its length over its arrival time) is so large that the "
                                  "kinetic energy overflows; expected a later arrival");
    return start;
  }
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
    requireFiniteMotion(chain, start, "the velocity", spec.velocity.cwiseAbs().maxCoeff() > 0);
  return start;
}

void requireCoverableMotion(const Chain& chain, const InitialState& start, double duration) {
  // The kinetic metric weighs each hinge by its mass: the speed over the root of the total mass is the hinges'
  // mass-weighted RMS speed in rod lengths per second, the same measure for 4 rods and for 1000.
  const double totalMass = chain.hingeMasses.sum() + chain.rodMasses.sum();
  const double hingeSpeed = std::sqrt(speedSquared(chain, start) / totalMass), travel = hingeSpeed * duration;
  if (travel <= limits::kMaxHingeTravel) return;
  char text[360];
  std::snprintf(text, sizeof text,
                "the start moves the hinges at %.3g rod lengths per second (mass-weighted root mean square), about "
                "%.3g rod lengths in the duration %.3g s; expected at most %.0e (a smaller velocity, unit_speed, or "
                "a shorter duration)",
                hingeSpeed, travel, duration, limits::kMaxHingeTravel);
  throw std::invalid_argument(text);
}

}  // namespace sl
