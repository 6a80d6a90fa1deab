#pragma once
// Runs that stopped are results: say which, when and why, on stderr (not with --quiet: errors only).

#include <vector>

#include "scene/scene.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

void reportStops(const Scene& scene, const std::vector<Trajectory>& runs, bool quiet = false);

}  // namespace sl
