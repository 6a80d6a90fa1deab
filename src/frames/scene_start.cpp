#include "frames/scene_start.hpp"

#include <cmath>

#include "simulation/initial_state.hpp"

namespace sl {

InitialState sceneStart(const Scene& scene) {
  const InitialSpec& spec = scene.initial;
  if (spec.kind == InitialSpec::Kind::Drag) {
    return initialStateFromDrag(scene.chain, spec.dragPoint, spec.dragDirection, spec.unitSpeed);
  }
  InitialState start = initialStateFromChart(scene.chain, spec.coords, spec.velocity);
  const double speed = std::sqrt(speedSquared(scene.chain, start));
  if (spec.unitSpeed && speed > 0) start.sphereVelocity /= speed;
  return start;
}

SceneLimits simulationSceneLimits() {
  SceneLimits limits;
  limits.methods = methodNames();
  limits.integrators = integratorNames();
  for (const std::string& name : limits.integrators)
    if (integratorIsAdaptive(name)) limits.adaptiveIntegrators.push_back(name);
  return limits;
}

}  // namespace sl
