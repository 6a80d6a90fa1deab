#pragma once
// A scene's title may name values of the scene instead of repeating them, so that `--set linkage.L=3.2` shows
// in the frames: {L} the linkage's L, {n} its number of rods, {name} the scene's name, {method} and
// {integrator} the first run's. Anything else in braces is left as written.

#include <string>

#include "scene/scene.hpp"

namespace sl {

std::string fillTitlePlaceholders(const std::string& title, const Scene& scene);

}  // namespace sl
