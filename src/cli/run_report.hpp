#pragma once
// Runs that stopped are results: say which, when and why, on stderr (also with --quiet).

#include <vector>

#include "scene/scene.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

void reportStops(const Scene& scene, const std::vector<Trajectory>& runs);

}  // namespace sl
