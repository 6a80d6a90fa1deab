#include "linkage/method_rules.hpp"

#include "contracts/limits.hpp"

namespace sl {

std::vector<MethodRefusal> methodRefusals(const MotionRequest& request) {
  std::vector<MethodRefusal> refusals;
  const Chain* chain = request.chain;
  const bool ambient = request.method == Method::Ambient;
  const bool slack = chain != nullptr && chain->isSlack();
  if (request.jacobi && !ambient) refusals.push_back(MethodRefusal::JacobiNeedsAmbient);
  if (!ambient) {
    if (slack)
      refusals.push_back(MethodRefusal::SlackChainHasNoChart);
    else if (request.startByHinges)
      refusals.push_back(MethodRefusal::HingeStartHasNoChart);
    else if (chain != nullptr && chain->rods > limits::kMaxRods)
      refusals.push_back(MethodRefusal::TooManyRodsForCharts);
  }
  if (request.jacobi && (slack || request.startByHinges)) refusals.push_back(MethodRefusal::JacobiNeedsSpherePoint);
  if (request.jacobi && chain != nullptr && chain->rods < 4) refusals.push_back(MethodRefusal::JacobiNeedsFourRods);
  if (traits(request.method).published && chain != nullptr) {
    if (chain->rods != 4)
      refusals.push_back(MethodRefusal::PublishedNeedsFourRods);
    else if ((chain->hingeMasses.array() != 1.0).any() || chain->hasRodMass())
      refusals.push_back(MethodRefusal::PublishedNeedsSpecMasses);
  }
  return refusals;
}

}  // namespace sl
