#include "analysis/reference_path.hpp"

namespace sl {

static_assert(traitsOf(kIntegrators, tightestIntegrator()).adaptive, "references are run at a tolerance");

Method referenceMethodFor(Method methodUnderTest) {
  return methodUnderTest == Method::Ambient ? Method::Embedded : Method::Ambient;
}

RunConfig referenceConfig(Method methodUnderTest) {
  RunConfig config;
  config.method = referenceMethodFor(methodUnderTest);
  config.integrator = tightestIntegrator();
  config.tolerance = kReferenceTolerance;
  return config;
}

ReferencePath noReference(const std::vector<double>& times) { return {std::nullopt, times, {}, std::nullopt}; }

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

std::string referenceMethodName(const ReferencePath& reference) {
  return reference.config ? nameOf(reference.config->method) : std::string(kNoReferenceName);
}

}  // namespace sl
