#include "simulation/family.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "linkage/chain.hpp"
#include "linkage/chart.hpp"
#include "simulation/initial_state.hpp"
#include "simulation/normal_draws.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

double kineticInner(const Chain& chain, const Eigen::VectorXd& x, const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  return 0.25 * (speedSquared(chain, {x, u + v}) - speedSquared(chain, {x, u - v}));
}

std::vector<Eigen::VectorXd> orthonormalTangentFrame(const Chain& chain, const Eigen::VectorXd& x,
                                                     const Eigen::VectorXd& first, std::size_t count) {
  const Eigen::Index size = x.size();
  const std::size_t wanted = count > 0 ? std::min<std::size_t>(count, static_cast<std::size_t>(size - 1))
                                       : static_cast<std::size_t>(size - 1);
  std::vector<Eigen::VectorXd> frame;
  const AmbientMassMatrix mass = ambientMassMatrix(chain);
  if (chain.rods <= kWholeJacobianRods) {
    // The Jacobian once, and g as speedSquared and kineticInner compute it (the same numbers).
    const Eigen::MatrixXd jacobian = sphereJacobian(chain, x);
    auto speed2 = [&](const Eigen::VectorXd& w) {
      const Eigen::VectorXd stacked = jacobian * w;
      return 2.0 * kineticEnergy(mass, Eigen::Map<const Eigen::Matrix2Xd>(stacked.data(), 2, chain.hingeCount()));
    };
    auto addOrthonormalised = [&](Eigen::VectorXd w) {
      w -= x * x.dot(w);  // tangent
      for (const Eigen::VectorXd& e : frame) w -= 0.25 * (speed2(e + w) - speed2(e - w)) * e;
      const double norm2 = speed2(w);
      if (!(norm2 > 1e-20 * (1.0 + w.squaredNorm()))) return;  // dependent on the vectors so far
      frame.push_back(w / std::sqrt(norm2));
    };
    addOrthonormalised(first);
    if (frame.empty()) throw std::invalid_argument("a family needs a start that moves (zero velocity)");
    for (Eigen::Index k = 0; k < size && frame.size() < wanted; ++k) addOrthonormalised(Eigen::VectorXd::Unit(size, k));
    return frame;
  }
  // Long chains: each vector's image dPsi(w) once (one forward-AD pass, O(n^2)); Gram-Schmidt on the images,
  // which are linear in w, with g(u, w) = <dPsi u, dPsi w>_M.
  std::vector<Eigen::Matrix2Xd> images;
  auto addOrthonormalised = [&](Eigen::VectorXd w) {
    w -= x * x.dot(w);  // tangent
    Eigen::Matrix2Xd image = hingeVelocitiesOnSphere(chain, x, w);
    for (std::size_t k = 0; k < frame.size(); ++k) {
      const double along = mass.innerProduct(images[k], image);
      w -= along * frame[k];
      image -= along * images[k];
    }
    const double norm2 = mass.innerProduct(image, image);
    if (!(norm2 > 1e-20 * (1.0 + w.squaredNorm()))) return;  // dependent on the vectors so far
    frame.push_back(w / std::sqrt(norm2));
    images.push_back(image / std::sqrt(norm2));
  };
  addOrthonormalised(first);
  if (frame.empty()) throw std::invalid_argument("a family needs a start that moves (zero velocity)");
  for (Eigen::Index k = 0; k < size && frame.size() < wanted; ++k) addOrthonormalised(Eigen::VectorXd::Unit(size, k));
  return frame;
}

namespace {

// Evenly over [-width/2, width/2]: member k of count (count >= 2).
double evenOffset(double width, int k, int count) { return width * (double(k) / double(count - 1) - 0.5); }

std::vector<InitialState> fan(const Chain& chain, const InitialState& start, const FamilySpec& family) {
  const double speed = std::sqrt(speedSquared(chain, start));
  const std::vector<Eigen::VectorXd> frame = orthonormalTangentFrame(chain, start.spherePoint, start.sphereVelocity, 2);
  if (frame.size() < 2) throw std::invalid_argument("a fan needs a tangent plane (at least 4 rods)");
  std::vector<InitialState> members;
  for (int k = 0; k < family.count; ++k) {
    const double angle = evenOffset(family.spread, k, family.count);
    members.push_back({start.spherePoint, speed * (std::cos(angle) * frame[0] + std::sin(angle) * frame[1])});
  }
  return members;
}

// Along the geodesic orthogonal to the run's velocity (unit speed, in the frame's second direction), at
// geodesic distance s: the point, and there the run's velocity carried along, made g-orthogonal to that
// geodesic and given the run's speed. On S^2 (4 rods) this is the parallel transport of the run's velocity
// (the unit normal of a geodesic is parallel along it); on higher spheres it keeps the velocity's direction as
// closely as orthogonality allows.
std::vector<InitialState> parallel(const Chain& chain, const InitialState& start, const FamilySpec& family,
                                   const RunConfig& config) {
  const double speed = std::sqrt(speedSquared(chain, start));
  const std::vector<Eigen::VectorXd> frame = orthonormalTangentFrame(chain, start.spherePoint, start.sphereVelocity, 2);
  if (frame.size() < 2) throw std::invalid_argument("a parallel family needs a tangent plane (at least 4 rods)");
  // Two unit-speed geodesics out of the start, one each way, sampled at the members' distances in order.
  std::vector<InitialState> members(static_cast<std::size_t>(family.count));
  for (const double side : {-1.0, 1.0}) {
    Trajectory across(chain, {start.spherePoint, side * frame[1]}, config);
    std::vector<int> order;
    for (int k = 0; k < family.count; ++k)
      if (side * evenOffset(family.spread, k, family.count) >= 0) order.push_back(k);
    if (side < 0) std::reverse(order.begin(), order.end());  // increasing distance
    for (const int k : order) {
      const double distance = std::abs(evenOffset(family.spread, k, family.count));
      const std::optional<Sample> at = across.sampleAt(distance);
      if (!at)
        throw std::invalid_argument("the geodesic orthogonal to the run stopped before distance " +
                                    std::to_string(distance) + " (" + (across.stop() ? across.stop()->detail() : "") +
                                    ")");
      const Eigen::VectorXd& y = at->spherePoint;
      const Eigen::VectorXd u = side * at->sphereVelocity;  // pointing the way of increasing offset
      Eigen::VectorXd w = start.sphereVelocity - y * y.dot(start.sphereVelocity);
      const double uu = speedSquared(chain, {y, u});
      w -= kineticInner(chain, y, u, w) / uu * u;
      const double ww = speedSquared(chain, {y, w});
      if (!(ww > 0)) throw std::invalid_argument("the run's velocity cannot be carried that far across");
      members[static_cast<std::size_t>(k)] = {y, speed / std::sqrt(ww) * w};
    }
  }
  return members;
}

std::vector<InitialState> cloud(const Chain& chain, const InitialState& start, const FamilySpec& family) {
  NormalDraws draws(family.seed);
  const Eigen::Index size = start.spherePoint.size();
  const double velocitySize = start.sphereVelocity.norm();
  std::vector<InitialState> members;
  for (int k = 0; k < family.count; ++k) {
    Eigen::VectorXd along = draws.vector(size);
    along -= start.spherePoint * start.spherePoint.dot(along);
    const Eigen::VectorXd x = (start.spherePoint + family.epsilon * along.normalized()).normalized();
    Eigen::VectorXd v = start.sphereVelocity + family.epsilon * velocitySize * draws.vector(size).normalized();
    v -= x * x.dot(v);
    members.push_back({x, v});
  }
  (void)chain;
  return members;
}

}  // namespace

std::vector<InitialState> familyStarts(const Chain& chain, const InitialState& start, const FamilySpec& family,
                                       const RunConfig& config) {
  if (family.count < 2) throw std::invalid_argument("a family needs at least 2 members");
  std::vector<InitialState> members;
  switch (family.kind) {
    case FamilyKind::Fan: members = fan(chain, start, family); break;
    case FamilyKind::Parallel: members = parallel(chain, start, family, config); break;
    case FamilyKind::Cloud: members = cloud(chain, start, family); break;
  }
  for (const InitialState& member : members) validateInitialState(chain, member);
  return members;
}

std::vector<Trajectory> familyMembers(const Chain& chain, const InitialState& start, const FamilySpec& family,
                                      const RunConfig& config, const std::function<bool()>& cancelled) {
  RunConfig memberConfig = config;
  memberConfig.jacobi = false;
  std::vector<Trajectory> members;
  for (const InitialState& member : familyStarts(chain, start, family, memberConfig)) {
    if (cancelled && cancelled()) throw RunCancelled();
    members.emplace_back(chain, member, memberConfig);
    if (cancelled) members.back().setCancellation(cancelled);
  }
  return members;
}

}  // namespace sl
