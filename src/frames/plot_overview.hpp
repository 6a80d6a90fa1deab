#pragma once
// What each plot panel shows over the whole animation, known before the first frame: the y range (so the axes
// never jump) and, for a plot that stays empty, why. Computed from fresh trajectories of the scene's runs sampled
// at every frame time; integration never depends on which times are asked for, so the values are exactly those the
// frames plot. Every shard computes the same overview.

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "contracts/frame_state.hpp"
#include "contracts/run_config.hpp"
#include "scene/scene.hpp"

namespace sl {

struct PlotOverview {
  std::optional<std::array<double, 2>> valueRange;
  PlotEmptiness emptiness = PlotEmptiness::HasValues;
  std::vector<EarlyStop> earlyStops;
};

// One per scene.view.plots entry; empty when the scene has no plots (nothing is integrated then).
// `cancelled` is given to the trajectories (Trajectory::setCancellation): RunCancelled comes through.
std::vector<PlotOverview> overviewPlots(const Scene& scene, const std::vector<InitialState>& starts,
                                        const std::function<bool()>& cancelled = {});


}  // namespace sl
