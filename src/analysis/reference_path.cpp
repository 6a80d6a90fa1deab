#include "analysis/reference_path.hpp"

#include <cmath>

namespace sl {

std::string referenceMethodFor(const std::string& methodUnderTest) {
  return methodUnderTest == "ambient" ? "embedded" : "ambient";
}

std::string tightestIntegrator() {
  std::string chosen = "dopri5";
  for (const auto& name : integratorNames())
    if (name == "rkf78")
      return name;
    else if (integratorIsAdaptive(name))
      chosen = name;
  return chosen;
}

RunConfig referenceConfig(const std::string& methodUnderTest) {
  RunConfig config;
  config.method = referenceMethodFor(methodUnderTest);
  config.integrator = tightestIntegrator();
  config.tolerance = kReferenceTolerance;
  return config;
}

std::vector<double> gridTimes(double duration, double interval) {
  std::vector<double> times;
  const long count = std::lround(std::floor(duration / interval * (1 + 1e-12)));
  for (long k = 0; k <= count; ++k) times.push_back(k * interval);
  if (duration - times.back() > 1e-9 * interval)
    times.push_back(duration);
  else
    times.back() = duration;
  return times;
}

ReferencePath noReference(const std::vector<double>& times) {
  RunConfig none;
  none.method = "none";
  return {none, times, {}, std::nullopt};
}

ReferencePath computeReferencePath(const Chain& chain, const InitialState& start, const std::vector<double>& times,
                                   const RunConfig& config) {
  ReferencePath path{config, times, {}, std::nullopt};
  Trajectory run(chain, start, config);
  for (double time : times) {
    const auto sample = run.sampleAt(time);
    if (!sample) {
      path.stop = run.stop();
      break;
    }
    path.hinges.push_back(sample->hinges);
  }
  return path;
}

double hingeDistance(const Eigen::Matrix2Xd& a, const Eigen::Matrix2Xd& b) {
  return (a - b).colwise().norm().maxCoeff();
}

}  // namespace sl
