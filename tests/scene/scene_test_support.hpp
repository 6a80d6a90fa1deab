#pragma once
// Limits for scene tests: the names the simulation accepts, without linking the simulation.

#include "scene/scene_loader.hpp"

namespace sl::testing {

inline SceneLimits testLimits() {
  SceneLimits limits;
  limits.methods = {"christoffel-fd", "embedded-fd", "christoffel", "embedded", "ambient"};
  limits.integrators = {"rk4", "dopri5"};
  limits.adaptiveIntegrators = {"dopri5"};
  limits.maxImageSize = 4096;
  return limits;
}

inline std::string shippedScene(const std::string& name) { return std::string(SL_SOURCE_DIR) + "/scenes/" + name; }

}  // namespace sl::testing
