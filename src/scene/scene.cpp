#include "scene/scene.hpp"

#include <cmath>

namespace sl {

int Scene::frameCount() const {
  // k = 0..ceil(duration * fps); the small allowance keeps 20 s at 30 fps at 601 frames despite rounding.
  return static_cast<int>(std::ceil(duration * output.fps - 1e-9)) + 1;
}

}  // namespace sl
