#include "analysis/starts.hpp"

#include <cmath>
#include <stdexcept>

#include "analysis/reference_path.hpp"
#include "simulation/initial_state.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

InitialState stateArrivingAt(const Chain& chain, const InitialState& arrival, double arrivalTime) {
  const InitialState reversed{arrival.spherePoint, -arrival.sphereVelocity};
  // The chart-free method at the reference setting: the starts are then checked by the chart-based methods,
  // independent of the method that built them.
  RunConfig chartFree;
  chartFree.method = Method::Ambient;
  chartFree.integrator = tightestIntegrator();
  chartFree.tolerance = kReferenceTolerance;
  Trajectory backwards(chain, reversed, chartFree);
  const auto end = backwards.sampleAt(arrivalTime);
  if (!end)
    throw std::runtime_error("the backward reference run stopped (" + nameOf(backwards.stop()->reason) + " at time " +
                             std::to_string(backwards.stop()->time) + ")");
  return {end->spherePoint, -end->sphereVelocity};
}

InitialState closestApproachToPole(int sphereAmbientDimension, double distance, double azimuth, double speed) {
  InitialState state;
  state.spherePoint = Eigen::VectorXd::Zero(sphereAmbientDimension);
  state.sphereVelocity = Eigen::VectorXd::Zero(sphereAmbientDimension);
  const int last = sphereAmbientDimension - 1;
  state.spherePoint(0) = std::sin(distance) * std::cos(azimuth);
  state.spherePoint(1) = std::sin(distance) * std::sin(azimuth);
  state.spherePoint(last) = std::cos(distance);
  state.sphereVelocity(0) = -speed * std::sin(azimuth);
  state.sphereVelocity(1) = speed * std::cos(azimuth);
  return state;
}

namespace {

NamedStart chartStart(std::string name, std::string description, double baseLength, Eigen::Vector2d coords,
                      Eigen::Vector2d rates) {
  const Chain chain = Chain::uniform(4, baseLength);
  return {std::move(name), std::move(description), chain, initialStateFromChart(chain, coords, rates), 20.0};
}

// Passes the pole at time 5: at distance 1e-3 (near) or through it (distance 0).
NamedStart poleStart(std::string name, std::string description, double distance) {
  const Chain chain = Chain::uniform(4, 3.0);
  const InitialState atPole = closestApproachToPole(3, distance, 0.4, 0.5);
  return {std::move(name), std::move(description), chain, stateArrivingAt(chain, atPole, 5.0), 20.0};
}

}  // namespace

std::vector<NamedStart> shippedStarts() {
  const Eigen::Vector2d genericCoords(0.3, 0.2), genericRates(0.5, 0.7);
  return {
      chartStart("generic", "L=3, (phi,t)=(0.3,0.2), rates (0.5,0.7); the reference generic_L3", 3.0, genericCoords,
                 genericRates),
      chartStart("seam-crossing", "L=3, (phi,t)=(-0.2,1.0), rates (0.1,1.0): crosses t=pi/2+k pi seven times", 3.0,
                 Eigen::Vector2d(-0.2, 1.0), Eigen::Vector2d(0.1, 1.0)),
      poleStart("near-pole", "L=3, passes 1e-3 from the pole phi=pi/2 at time 5", 1e-3),
      poleStart("through-pole", "L=3, passes through the pole phi=pi/2 at time 5", 0.0),
      chartStart("L-near-2", "L=2.01, the generic chart start", 2.01, genericCoords, genericRates),
      chartStart("L-near-4", "L=3.99, the generic chart start", 3.99, genericCoords, genericRates),
  };
}

}  // namespace sl
