#pragma once
// What each plot panel shows over the whole animation, known before the first frame: the y range (so the axes
// never jump), for a plot that stays empty why, for one within roundoff a line saying so; and the part of the
// plane the chains sweep (so the linkage panel fills its panel and never jumps). Computed from fresh trajectories
// of the scene's runs sampled at every frame time; integration never depends on which times are asked for, so the
// values are exactly those the frames plot. Every shard computes the same overview.

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "contracts/frame_state.hpp"
#include "contracts/run_config.hpp"
#include "scene/scene.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

struct PlotOverview {
  std::optional<std::array<double, 2>> valueRange;
  PlotEmptiness emptiness = PlotEmptiness::HasValues;
  std::vector<EarlyStop> earlyStops;
  std::optional<PlotFrame::RoundoffOnly> roundoff;  // PlotFrame::roundoff
};

// What the whole animation shows, known before its first frame.
struct MotionOverview {
  std::vector<PlotOverview> plots;  // one per scene.view.plots entry
  // FrameState::linkageBox: both pins and every run's hinges at every frame time (empty when the scene has no
  // linkage panel, or a family whose members the box would not hold).
  std::optional<std::array<double, 4>> linkageBox;
};

// Integrates fresh trajectories of the runs only when the scene has plots or a linkage panel to fit.
// `cancelled` is given to the trajectories (Trajectory::setCancellation): RunCancelled comes through.
// A holonomy plot's values come from `transport`, the polygon the sphere panel draws (its sides' swept curvature).
MotionOverview overviewMotion(const Scene& scene, const std::vector<InitialState>& starts,
                              const std::function<bool()>& cancelled = {}, const SphereTransport* transport = nullptr);

// The sectional plot's values at a sample: the smallest and largest curvature of the planes through the velocity
// (geometry/sectional_curvature.hpp); NaN where the chain is slack, has fewer than 5 rods or the sample is at rest.
std::array<double, 2> curvatureThroughVelocity(const Chain& chain, const Sample& sample);


}  // namespace sl
