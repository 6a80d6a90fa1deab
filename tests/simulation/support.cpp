#include "support.hpp"

namespace sl::testing {

InitialState poleCrossingStart(const Chain& chain, double arrival, const Eigen::VectorXd& poleVelocity) {
  const Eigen::Index dim = chain.rods - 1;
  InitialState backwards;
  backwards.spherePoint = Eigen::VectorXd::Unit(dim, dim - 1);  // chart 0's pole: x1 = x2 = 0
  backwards.sphereVelocity = -poleVelocity;
  backwards.sphereVelocity(dim - 1) = 0.0;
  Trajectory run(chain, backwards, config("ambient", "bulirsch-stoer", 1e-13));
  const std::optional<Sample> there = run.sampleAt(arrival);
  if (!there) throw std::runtime_error("the backward run stopped: " + run.stop()->detail());
  return {there->spherePoint, -there->sphereVelocity};
}

}  // namespace sl::testing
