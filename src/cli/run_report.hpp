#pragma once
// Runs that stopped are results: say which, when and why, on stderr (not with --quiet: errors only).

#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

// "run \"published\" stopped at t = 3.41: pole-fold-back (...)", a line per run that stopped.
std::string stopReports(const Scene& scene, const std::vector<Trajectory>& runs);
void reportStops(const Scene& scene, const std::vector<Trajectory>& runs, bool quiet = false);

}  // namespace sl
