// `unit_speed` gives g(v, v) = 1 (kinetic energy 1/2) for every form a start can take, on chains with hinge
// masses, rod masses or both. The speed is measured independently of the code under test: hinge velocities by
// a central difference of the chart map Psi along the great circle of the start (or as given, for a start by
// hinges), and the kinetic energy of point masses plus uniform rods written out (a rod with end velocities a and
// b: (m / 2) (|a|^2 + a.b + |b|^2) / 3), not through speedSquared or the ambient mass matrix.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "linkage/chart.hpp"
#include "simulation/initial_state.hpp"

namespace sl {
namespace {

// 2 T of hinge velocities `velocities` (2 x (n-1)); the pins do not move.
double twiceKineticEnergy(const Chain& chain, const Eigen::Matrix2Xd& velocities) {
  double energy = 0;
  for (int j = 0; j < chain.hingeCount(); ++j) energy += chain.hingeMasses(j) * velocities.col(j).squaredNorm();
  for (int k = 0; k < chain.rods; ++k) {
    const Eigen::Vector2d a = k == 0 ? Eigen::Vector2d::Zero() : Eigen::Vector2d(velocities.col(k - 1));
    const Eigen::Vector2d b = k == chain.rods - 1 ? Eigen::Vector2d::Zero() : Eigen::Vector2d(velocities.col(k));
    energy += chain.rodMasses(k) * (a.squaredNorm() + a.dot(b) + b.squaredNorm()) / 3;
  }
  return energy;
}

// g(v, v) of a start, measured as above.
double measuredSpeedSquared(const Chain& chain, const InitialState& start) {
  if (start.byHinges()) return twiceKineticEnergy(chain, start.hingeVelocities);
  const Eigen::VectorXd& x = start.spherePoint;
  const double speed = start.sphereVelocity.norm();
  const Eigen::VectorXd u = start.sphereVelocity / speed;
  const double h = 1e-5;
  auto along = [&](double s) -> Eigen::Matrix2Xd {
    const Eigen::VectorXd point = std::cos(s * speed) * x + std::sin(s * speed) * u;  // on the sphere
    return hingePositionsOnSphere<double>(chain, point);
  };
  return twiceKineticEnergy(chain, (along(h) - along(-h)) / (2 * h));
}

struct NamedChain {
  std::string name;
  Chain chain;
};

std::vector<NamedChain> chains() {
  Chain massiveRods = Chain::uniform(4, 3.0);
  massiveRods.hingeMasses.setZero();
  massiveRods.rodMasses.setConstant(2.0);
  Chain mixed = Chain::uniform(6, 4.7);
  mixed.hingeMasses << 1, 3, 0.5, 2, 1;
  mixed.rodMasses << 0.5, 0, 1, 0, 4, 1;
  return {{"unit hinge masses", Chain::uniform(4, 3.0)}, {"massive rods", massiveRods}, {"mixed, 6 rods", mixed}};
}

std::vector<std::pair<std::string, InitialSpec>> startsFor(const Chain& chain) {
  const int d = chain.sphereDimension();
  std::vector<std::pair<std::string, InitialSpec>> starts;
  InitialSpec coords;
  coords.kind = InitialSpec::Kind::ChartCoordinates;
  coords.coords = Eigen::VectorXd::LinSpaced(d, 0.3, -0.2);
  coords.velocity = Eigen::VectorXd::LinSpaced(d, 2.5, -1.0);
  starts.emplace_back("coords", coords);
  InitialSpec drag;
  drag.kind = InitialSpec::Kind::Drag;
  drag.dragPoint = Eigen::VectorXd::LinSpaced(d + 1, 1.0, 0.2);
  drag.dragDirection = Eigen::VectorXd::LinSpaced(d + 1, -0.4, 3.0);
  starts.emplace_back("drag", drag);
  InitialSpec pushed;
  pushed.kind = InitialSpec::Kind::Hinges;
  pushed.shape = InitialSpec::Shape::Arc;
  pushed.pushHinge = 2;
  pushed.pushVelocity = Eigen::Vector2d(0.7, 5.0);
  starts.emplace_back("hinges, a push on one hinge", pushed);
  InitialSpec random = pushed;
  random.pushHinge = 0;
  random.pushSeed = 3;
  random.pushSize = 20;
  starts.emplace_back("hinges, a random push", random);
  InitialSpec given;
  given.kind = InitialSpec::Kind::Hinges;
  given.shape = InitialSpec::Shape::Given;
  given.hinges = arcHinges(chain.rods, chain.baseLength);
  given.hingeVelocities = Eigen::Matrix2Xd::Zero(2, chain.hingeCount());
  given.hingeVelocities.col(0) << 0, 3;
  given.hingeVelocities.col(chain.hingeCount() - 1) << 1, -2;
  starts.emplace_back("hinges with velocities", given);
  return starts;
}

TEST(UnitSpeed, EveryStartFormOnEveryChainHasUnitSpeed) {
  for (const NamedChain& named : chains()) {
    for (auto [form, spec] : startsFor(named.chain)) {
      SCOPED_TRACE(named.name + ", " + form);
      spec.unitSpeed = false;
      const double given = measuredSpeedSquared(named.chain, initialStateFromSpec(named.chain, spec));
      EXPECT_GT(std::abs(given - 1), 0.1) << "the start was already at unit speed: the test would prove nothing";
      spec.unitSpeed = true;
      EXPECT_NEAR(measuredSpeedSquared(named.chain, initialStateFromSpec(named.chain, spec)), 1.0, 1e-8);
    }
  }
}

// A drag direction nearly along the point keeps its small tangential part: accepted and moving that way (at unit
// speed too) down to 1e-11 of its size; below the refusal's 1e-12 it is rounding noise and refused.
TEST(UnitSpeed, ADragNearlyAlongThePointMovesAcrossIt) {
  const Chain chain = Chain::uniform(4, 3.0);
  const Eigen::Vector3d point = Eigen::Vector3d(1, 2, 2) / 3;
  const Eigen::Vector3d across = Eigen::Vector3d(2, -2, 1) / 3;  // orthogonal to the point, unit
  for (const bool unitSpeed : {false, true}) {
    SCOPED_TRACE(unitSpeed ? "unit speed" : "as given");
    const InitialState start = initialStateFromDrag(chain, 5 * point, 5 * (point + 1e-11 * across), unitSpeed);
    EXPECT_NEAR(start.sphereVelocity.normalized().dot(across), 1.0, 1e-4);
    if (unitSpeed) {
      EXPECT_NEAR(measuredSpeedSquared(chain, start), 1.0, 1e-8);
    }
    EXPECT_THROW(initialStateFromDrag(chain, point, point + 1e-13 * across, unitSpeed), std::invalid_argument);
  }
}

}  // namespace
}  // namespace sl
