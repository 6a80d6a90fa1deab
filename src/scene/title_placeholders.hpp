#pragma once
// A scene's title may name values of the scene instead of repeating them, so that `--set linkage.L=3.2` shows
// in the frames: {L} the linkage's L, {n} its number of rods, {name} the scene's name, {method} and
// {integrator} the first run's, {runs[i].family.count} a run's number of family members; once a run's start on a
// found motion is resolved (initial.connect, initial.periodic), {runs[i].length} its length and
// {runs[i].stability} a closed geodesic's stability; once the frames stage has the distance colouring's map,
// {injectivity_radius} its point's injectivity radius. Anything else in braces is left as written.

#include <optional>
#include <string>

#include "scene/scene.hpp"

namespace sl {

std::string fillTitlePlaceholders(const std::string& title, const Scene& scene,
                                  std::optional<double> injectivityRadius = std::nullopt);

}  // namespace sl
