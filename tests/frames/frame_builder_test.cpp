// The frame builder against fresh trajectories sampled directly, and shards against a full walk.
#include <algorithm>
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "contracts/limits.hpp"
#include "contracts/registry.hpp"
#include "frames/frame_builder.hpp"
#include "geometry/sectional_curvature.hpp"
#include "linkage/chain.hpp"
#include "linkage/chain_constants.hpp"
#include "scene/scene_loader.hpp"
#include "simulation/family.hpp"
#include "simulation/initial_state.hpp"
#include "simulation/trajectory.hpp"
#include "support/scene_files.hpp"

namespace sl {
namespace {

// Two runs from the generic reference start, short so the suite stays fast.
Scene twoRunScene(const std::string& extraView = "") {
  return parseScene(R"({"name": "t", "linkage": {"rods": 4, "L": 3},
    "initial": {"coords": [0.3, 0.2], "velocity": [0.5, 0.7]}, "duration": 1.0,
    "runs": [{"name": "exact", "method": "ambient", "integrator": "dopri5", "tolerance": 1e-10},
             {"name": "published", "method": "christoffel-fd", "integrator": "rk4", "step": 0.05}],
    "output": {"fps": 10},
    "view": {"panels": ["sphere", "linkage", {"panel": "plot", "plot": "divergence"},
                        {"panel": "plot", "plot": "energy"}], "trails": [1, 3])" +
                        extraView + "}}",
                    "t.json");
}

// Each run's start on its own chain, in the scene's order.
std::vector<InitialState> startsOf(const Scene& scene) {
  std::vector<InitialState> starts;
  for (const RunSpec& run : scene.runs) starts.push_back(initialStateFromSpec(run.chain, run.initial));
  return starts;
}

// One fresh Trajectory per scene run, from its start, in the scene's order.
std::vector<Trajectory> runsOf(const Scene& scene) {
  const std::vector<InitialState> starts = startsOf(scene);
  std::vector<Trajectory> runs;
  for (std::size_t i = 0; i < scene.runs.size(); ++i) runs.emplace_back(scene.runs[i].chain, starts[i], scene.runs[i].config);
  return runs;
}

// Each run's family members, as the commands start them (cli/scene_input.cpp).
std::vector<std::vector<Trajectory>> familiesOf(const Scene& scene) {
  const std::vector<InitialState> starts = startsOf(scene);
  std::vector<std::vector<Trajectory>> families(scene.runs.size());
  for (std::size_t i = 0; i < scene.runs.size(); ++i) {
    const RunSpec& run = scene.runs[i];
    if (!run.family) continue;
    families[i] = familyMembers(run.chain, starts[i], *run.family, run.config);
  }
  return families;
}

FrameBuilder builderFor(const Scene& scene) {
  return FrameBuilder(scene, startsOf(scene), runsOf(scene), familiesOf(scene));
}

void expectSameVec(const SharedSpan<Vec3>& a, const SharedSpan<Vec3>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].x, b[i].x);
    EXPECT_EQ(a[i].y, b[i].y);
    EXPECT_EQ(a[i].z, b[i].z);
  }
}

void expectSameFrame(const FrameState& a, const FrameState& b) {
  EXPECT_EQ(a.index, b.index);
  EXPECT_EQ(a.time, b.time);
  ASSERT_EQ(a.runs.size(), b.runs.size());
  for (size_t r = 0; r < a.runs.size(); ++r) {
    expectSameVec(a.runs[r].path, b.runs[r].path);
    EXPECT_EQ(a.runs[r].pathTimes, b.runs[r].pathTimes);
    ASSERT_EQ(a.runs[r].hinges.size(), b.runs[r].hinges.size());
    for (size_t h = 0; h < a.runs[r].hinges.size(); ++h) EXPECT_EQ(a.runs[r].hinges[h].x, b.runs[r].hinges[h].x);
    ASSERT_EQ(a.runs[r].trails.size(), b.runs[r].trails.size());
    for (size_t t = 0; t < a.runs[r].trails.size(); ++t)
      EXPECT_EQ(a.runs[r].trails[t].size(), b.runs[r].trails[t].size());
    EXPECT_EQ(a.runs[r].stopped, b.runs[r].stopped);
  }
  ASSERT_EQ(a.plots.size(), b.plots.size());
  for (size_t p = 0; p < a.plots.size(); ++p) {
    ASSERT_EQ(a.plots[p].series.size(), b.plots[p].series.size());
    for (size_t s = 0; s < a.plots[p].series.size(); ++s) {
      const auto& x = a.plots[p].series[s].values;
      const auto& y = b.plots[p].series[s].values;
      ASSERT_EQ(x.size(), y.size());
      for (size_t i = 0; i < x.size(); ++i) EXPECT_TRUE(x[i] == y[i] || (std::isnan(x[i]) && std::isnan(y[i])));
    }
  }
}

// WCAG's contrast ratio of two colours (relative luminance of sRGB), written here apart from the palette's choice.
double contrastRatio(const ColorRGB& a, const ColorRGB& b) {
  const auto linear = [](double v) { return v <= 0.03928 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
  const auto luminance = [&](const ColorRGB& c) {
    return 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b);
  };
  const double la = luminance(a), lb = luminance(b);
  return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

// Every run's default colour, over every sphere colouring, stands off its page: at least 3:1 on the dark page (the
// charcoal run of a curvature-coloured scene was invisible in its panels there), 2:1 on the light one (Okabe-Ito's
// orange and sky blue are 2:1; the white third run of a bending or distance scene was 1:1, its label unreadable).
TEST(FrameBuilder, DefaultRunColoursReadOnTheirPage) {
  Scene scene;
  scene.runs.resize(8);
  for (const auto& [coloring, name] : kSphereColorings) {
    scene.view.sphereSurface.colorBy = coloring;
    for (std::size_t run = 0; run < scene.runs.size(); ++run) {
      scene.view.theme = Theme::Dark;
      EXPECT_GE(contrastRatio(runColor(scene, run), themeBackground(Theme::Dark)), 3.0) << name << " run " << run;
      scene.view.theme = Theme::Light;
      EXPECT_GE(contrastRatio(runColor(scene, run), themeBackground(Theme::Light)), 2.0) << name << " run " << run;
    }
  }
  scene.view.sphereSurface.colorBy = SphereColoring::Curvature;
  scene.view.theme = Theme::Light;
  EXPECT_LT(contrastRatio(runColor(scene, 1), ColorRGB{0, 0, 0}), 1.3);  // the light page keeps the charcoal run
  scene.runs[1].color = ColorRGB{0.1f, 0.1f, 0.1f};
  scene.view.theme = Theme::Dark;
  EXPECT_EQ(runColor(scene, 1), (ColorRGB{0.1f, 0.1f, 0.1f}));  // a colour the scene chose is never replaced
}

TEST(FrameBuilder, FrameTimesAndCount) {
  const Scene scene = twoRunScene();
  FrameBuilder builder = builderFor(scene);
  EXPECT_EQ(builder.frameCount(), 11);
  const FrameState last = builder.frame(10);
  EXPECT_DOUBLE_EQ(last.time, 1.0);
  EXPECT_EQ(last.rods, 4);
  EXPECT_EQ(last.viewSpace, ViewSpace::Sphere);
  EXPECT_EQ(last.runs[1].name, "published");
  EXPECT_EQ(last.runs[1].method, Method::ChristoffelFd);
  // 4 path samples per frame interval after frame 0; pathTimes increase and end at the frame time.
  EXPECT_EQ(last.runs[0].path.size(), 1u + 10u * 4u);
  EXPECT_DOUBLE_EQ(last.runs[0].pathTimes.back(), 1.0);
  for (size_t i = 1; i < last.runs[0].pathTimes.size(); ++i)
    EXPECT_LT(last.runs[0].pathTimes[i - 1], last.runs[0].pathTimes[i]);
}

// Shards: frame k built after skipping straight to it equals frame k of a full walk.
TEST(FrameBuilder, ShardStartEqualsFullWalk) {
  const Scene scene = twoRunScene();
  FrameBuilder full = builderFor(scene);
  std::vector<FrameState> all;
  for (int k = 0; k < full.frameCount(); ++k) all.push_back(full.frame(k));
  for (int start : {3, 7, 10}) {
    SCOPED_TRACE(start);
    FrameBuilder shard = builderFor(scene);
    expectSameFrame(shard.frame(start), all[size_t(start)]);
    FrameBuilder walked = builderFor(scene);  // the render command's walk: advanceTo, then frame
    for (int k = 0; k < start; ++k) walked.advanceTo(k);
    EXPECT_EQ(walked.lastSampledFrame(), start - 1);
    expectSameFrame(walked.frame(start), all[size_t(start)]);
  }
}

// Hinges, sphere points, divergence and energy error against fresh runs sampled at the frame times.
TEST(FrameBuilder, ValuesMatchDirectSampling) {
  const Scene scene = twoRunScene();
  FrameBuilder builder = builderFor(scene);
  std::vector<Trajectory> direct = runsOf(scene);
  for (int k = 0; k < builder.frameCount(); ++k) {
    const FrameState state = builder.frame(k);
    const Sample a = *direct[0].sampleAt(scene.frameTime(k));
    const Sample b = *direct[1].sampleAt(scene.frameTime(k));
    for (int h = 0; h < 3; ++h) EXPECT_NEAR(state.runs[0].hinges[size_t(h)].x, a.hinges(0, h), 1e-14);
    // The sphere panel shows x = (cos phi cos t, cos phi sin t, sin phi) from the sample's chart coordinates.
    const double phi = a.coords(0), t = a.coords(1);
    EXPECT_NEAR(state.runs[0].current.x, std::cos(phi) * std::cos(t), 1e-12);
    EXPECT_NEAR(state.runs[0].current.z, std::sin(phi), 1e-12);
    EXPECT_NEAR(state.plots[0].series[0].values.back(), hingeDistance(a.hinges, b.hinges), 1e-14);
    EXPECT_EQ(state.plots[1].series[1].values.back(), std::abs(b.relativeEnergyDrift));
    EXPECT_EQ(state.plots[0].series[0].times.back(), scene.frameTime(k));
  }
}

// Runs with their own linkage and start: each run is its own chain's motion from its own start, and
// each frame carries the run's own pin distance for the linkage panel.
TEST(FrameBuilder, RunsWithTheirOwnLinkageAndStartFollowTheirOwnPhysics) {
  const Scene scene = parseScene(R"({"name": "t", "linkage": {"rods": 4, "L": 3},
    "initial": {"coords": [0.3, 0.2], "velocity": [0.5, 0.7]}, "duration": 1.0,
    "runs": [{"name": "scene's", "method": "ambient", "integrator": "dopri5", "tolerance": 1e-10},
             {"name": "short, heavy", "method": "ambient", "integrator": "dopri5", "tolerance": 1e-10,
              "linkage": {"L": 2.6, "rod_masses": [3, 3, 3, 3]}},
             {"name": "own start", "method": "christoffel", "integrator": "dopri5", "tolerance": 1e-10,
              "initial": {"coords": [-0.4, 1.0], "velocity": [0.2, -0.3]}}],
    "output": {"fps": 10}, "view": {"panels": ["sphere", "linkage"]}})",
                                 "t.json");
  FrameBuilder builder = builderFor(scene);
  const Chain& shortChain = scene.runs[1].chain;
  ASSERT_DOUBLE_EQ(shortChain.baseLength, 2.6);
  Trajectory alone(shortChain, initialStateFromSpec(shortChain, scene.initial), scene.runs[1].config);
  Trajectory sceneChain(scene.chain, initialStateFromSpec(scene.chain, scene.initial), scene.runs[1].config);
  for (int k = 0; k < builder.frameCount(); ++k) {
    const FrameState state = builder.frame(k);
    EXPECT_DOUBLE_EQ(state.runs[0].baseLength, 3.0);
    EXPECT_DOUBLE_EQ(state.runs[1].baseLength, 2.6);
    const RunFrame& heavy = state.runs[1];
    // The last rod ends on the run's own pin (L = 2.6), not the scene's.
    const Vec2 last = heavy.hinges.back();
    EXPECT_NEAR(std::hypot(last.x - 2.6, last.y), 1.0, 1e-9) << "frame " << k;
    const Sample expected = *alone.sampleAt(scene.frameTime(k));
    for (int h = 0; h < 3; ++h) EXPECT_NEAR(heavy.hinges[size_t(h)].y, expected.hinges(1, h), 1e-14);
    if (k > 0) {  // the same start on another chain moves differently
      const Sample other = *sceneChain.sampleAt(scene.frameTime(k));
      EXPECT_GT(hingeDistance(expected.hinges, other.hinges), 1e-3);
    }
  }
  // The run with its own start begins there: chart coordinates (-0.4, 1.0).
  FrameBuilder again = builderFor(scene);
  const Vec3 start = again.frame(0).runs[2].current;
  EXPECT_NEAR(start.z, std::sin(-0.4), 1e-12);
  EXPECT_NEAR(start.y, std::cos(-0.4) * std::sin(1.0), 1e-12);
}

// A run's family: every member in every frame, in member order, each the motion of its own start;
// a shard's first frame equals the full walk's, members included.
TEST(FrameBuilder, FamilyMembersAreSampledWithTheRunInEveryShard) {
  const Scene scene = parseScene(R"({"name": "t", "linkage": {"rods": 4, "L": 3},
    "initial": {"coords": [0.3, 0.2], "velocity": [0.5, 0.7]}, "duration": 1.0,
    "runs": [{"name": "fan", "method": "ambient", "integrator": "dopri5", "tolerance": 1e-10,
              "family": {"kind": "fan", "count": 5, "spread": 0.4}},
             {"name": "alone", "method": "ambient", "integrator": "dopri5", "tolerance": 1e-10}],
    "output": {"fps": 10}, "view": {"panels": ["sphere", "linkage", {"panel": "plot", "plot": "spread"}],
                                    "path_samples_per_frame": 3}})",
                                 "t.json");
  FrameBuilder builder = builderFor(scene);
  const std::vector<InitialState> starts = familyStarts(scene.runs[0].chain, startsOf(scene)[0], *scene.runs[0].family,
                                                        scene.runs[0].config);
  std::vector<Trajectory> direct;
  for (const InitialState& start : starts) direct.emplace_back(scene.runs[0].chain, start, scene.runs[0].config);
  Trajectory runAlone(scene.runs[0].chain, startsOf(scene)[0], scene.runs[0].config);
  std::vector<FrameState> all;
  for (int k = 0; k < builder.frameCount(); ++k) {
    all.push_back(builder.frame(k));
    const FrameState& state = all.back();
    ASSERT_EQ(state.runs[0].members.size(), 5u);
    EXPECT_TRUE(state.runs[1].members.empty());
    // The spread plot: the largest hinge distance of a member from the run, within the whole animation's range.
    const Sample run = *runAlone.sampleAt(scene.frameTime(k));
    double spread = 0;
    ASSERT_EQ(state.plots[0].series.size(), 1u);
    for (std::size_t m = 0; m < 5; ++m) {
      const MemberFrame& member = state.runs[0].members[m];
      const Sample expected = *direct[m].sampleAt(scene.frameTime(k));
      spread = std::max(spread, hingeDistance(run.hinges, expected.hinges));
      EXPECT_FALSE(member.stopped);
      for (int h = 0; h < 3; ++h) EXPECT_NEAR(member.hinges[size_t(h)].x, expected.hinges(0, h), 1e-14);
      EXPECT_EQ(member.path.size(), size_t(k == 0 ? 1 : 1 + 3 * k));
      EXPECT_NEAR(member.current.z, expected.spherePoint(2), 1e-14);
    }
    EXPECT_NEAR(state.plots[0].series[0].values.back(), spread, 1e-14);
    if (k > 0) {
      EXPECT_LE(spread, (*state.plots[0].valueRange)[1] * (1 + 1e-12));
      EXPECT_GE(spread, (*state.plots[0].valueRange)[0] * (1 - 1e-12));
    }
  }
  // Members leave one point in different directions: the wavefront is spread out after a while.
  const auto& last = all.back().runs[0].members;
  EXPECT_GT(std::abs(last.front().current.x - last.back().current.x) + std::abs(last.front().current.y - last.back().current.y),
            0.05);
  for (int start : {3, 7}) {
    FrameBuilder shard = builderFor(scene);
    const FrameState first = shard.frame(start);
    for (std::size_t m = 0; m < 5; ++m) {
      expectSameVec(first.runs[0].members[m].path, all[size_t(start)].runs[0].members[m].path);
    }
  }
}

TEST(FrameBuilder, TrailsFollowTheirHingesAndFade) {
  const Scene scene = twoRunScene(R"(, "trail_fade_seconds": 0.3)");
  FrameBuilder builder = builderFor(scene);
  const FrameState state = builder.frame(10);
  ASSERT_EQ(state.runs[0].trails.size(), 2u);
  EXPECT_EQ(state.runs[0].trails[0].size(), 4u);  // ceil(0.3 * 10) + 1 frames kept
  EXPECT_EQ(state.runs[0].trails[1].back().x, state.runs[0].hinges[2].x);
}

TEST(FrameBuilder, PathFadeKeepsOnlyRecentPoints) {
  const Scene scene = twoRunScene(R"(, "path_fade_seconds": 0.25)");
  FrameBuilder builder = builderFor(scene);
  const FrameState state = builder.frame(10);
  EXPECT_GE(state.runs[0].pathTimes.front(), 0.75);
  EXPECT_LT(state.runs[0].path.size(), 12u);
}

// A run that fails is shown stopped, frozen at its last good state, with the reason.
TEST(FrameBuilder, StoppedRunIsFrozenWithItsReason) {
  Scene scene = twoRunScene();
  scene.runs[1].config.maxRelativeEnergyDrift = 1e-14;  // rk4 at step 0.05 drifts beyond this at once
  FrameBuilder builder = builderFor(scene);
  const FrameState early = builder.frame(2);
  const FrameState late = builder.frame(10);
  ASSERT_TRUE(late.runs[1].stopped);
  EXPECT_FALSE(late.runs[0].stopped);
  EXPECT_EQ(late.runs[1].stopReason, StopReason::EnergyBlowUp);
  // The watchdog's reading against its limit, as numbers.
  EXPECT_GT(late.runs[1].stopMeasured, 1e-14);
  EXPECT_EQ(late.runs[1].stopLimit, 1e-14);
  EXPECT_LT(late.runs[1].stopTime, 0.2);
  EXPECT_EQ(late.runs[1].hinges[0].x, early.runs[1].hinges[0].x);
  EXPECT_TRUE(std::isnan(late.plots[0].series[0].values.back()));  // no divergence once one side stopped
}

// A stop shows on the frame whose interval ((k - 1) / fps, k / fps] holds it, never on the next: a run stopped at
// t = 0 (a start on the seam t = pi/2, where the published single chart fails at its first step, as in
// scenes/seam.json) is stopped in frame 0, frozen at its start; and in every frame, stopped exactly when its stop
// time has come.
TEST(FrameBuilder, AStopShowsOnTheFrameWhoseIntervalHoldsIt) {
  const Scene scene = parseScene(R"({"name": "s", "linkage": {"rods": 4, "L": 3},
    "initial": {"coords": [0.2, 1.5707963267948966], "velocity": [0.3, 1.0]}, "duration": 0.3,
    "runs": [{"name": "exact", "method": "christoffel", "integrator": "dopri5", "tolerance": 1e-10},
             {"name": "published", "method": "christoffel-fd", "integrator": "rk4", "step": 0.02}],
    "output": {"fps": 30}, "view": {"panels": ["sphere", "linkage", {"panel": "plot", "plot": "energy"}]}})",
                                 "s.json");
  FrameBuilder builder = builderFor(scene);
  const FrameState first = builder.frame(0);
  ASSERT_TRUE(first.runs[1].stopped) << "the stop at t = 0 shows only on a later frame";
  EXPECT_EQ(first.runs[1].stopTime, 0.0);
  EXPECT_EQ(first.runs[1].stopReason, StopReason::FieldBlowUp);
  EXPECT_FALSE(first.runs[0].stopped);
  const FrameState second = builder.frame(1);
  ASSERT_TRUE(second.runs[1].stopped);
  EXPECT_EQ(second.runs[1].hinges[1].x, first.runs[1].hinges[1].x);  // frozen at its last good state
  EXPECT_EQ(second.runs[1].hinges[1].y, first.runs[1].hinges[1].y);

  // Through a chart pole (scenes/pole-passage.json) the published method stops at t = 1.38, between two frames at
  // 30 fps and on a frame at 50 fps (its steps of 0.02 summed, against 69 / 50): stopped from the first frame at or
  // after it, and not before.
  for (const int fps : {30, 50}) {
    const Scene pole = parseScene(R"({"name": "p", "linkage": {"rods": 4, "L": 3},
      "initial": {"coords": [0.0, 0.0], "velocity": [1.0, 0.0]}, "duration": 1.5,
      "runs": [{"name": "chart-free", "method": "ambient", "integrator": "dopri5", "tolerance": 1e-10},
               {"name": "published", "method": "christoffel-fd", "integrator": "rk4", "step": 0.02}],
      "output": {"fps": )" + std::to_string(fps) + R"(}, "view": {"panels": ["sphere", "linkage"]}})",
                                  "p.json");
    FrameBuilder walk = builderFor(pole);
    const double stopTime = builderFor(pole).frame(pole.frameCount() - 1).runs[1].stopTime;
    ASSERT_NEAR(stopTime, 1.38, 1e-9);
    int shown = -1;
    for (int k = 0; k < pole.frameCount(); ++k) {
      const FrameState state = walk.frame(k);
      if (state.runs[1].stopped && shown < 0) shown = k;
      EXPECT_EQ(state.runs[1].stopped, stopTime <= state.time + 1e-9)
          << fps << " fps, frame " << k << " at t = " << state.time;
    }
    EXPECT_EQ(shown, fps == 30 ? 42 : 69) << fps << " fps";
  }
}

// The same double, NaN included.
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// A frame's plot series refer to the builder's history instead of copying it: a frame kept while the builder walks
// on still shows exactly its own frames' values, and a later frame's series begin with the same values.
TEST(FrameBuilder, KeptFramesDoNotChangeWhileTheBuilderWalksOn) {
  const Scene scene = twoRunScene();
  FrameBuilder builder = builderFor(scene);
  const FrameState early = builder.frame(3);
  std::vector<std::vector<double>> before;
  for (const PlotFrame& plot : early.plots)
    for (const PlotSeries& series : plot.series) before.emplace_back(series.values.begin(), series.values.end());
  const FrameState late = builder.frame(builder.frameCount() - 1);
  std::size_t s = 0;
  for (std::size_t p = 0; p < early.plots.size(); ++p) {
    for (std::size_t r = 0; r < early.plots[p].series.size(); ++r, ++s) {
      const PlotSeries& kept = early.plots[p].series[r];
      ASSERT_EQ(kept.times.size(), 4u);
      ASSERT_EQ(kept.values.size(), 4u);
      EXPECT_EQ(kept.times.back(), scene.frameTime(3));
      const PlotSeries& later = late.plots[p].series[r];
      ASSERT_EQ(later.values.size(), std::size_t(builder.frameCount()));
      for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_TRUE(sameBits(kept.values[i], before[s][i])) << p << " " << r << " " << i;
        EXPECT_TRUE(sameBits(kept.values[i], later.values[i])) << p << " " << r << " " << i;
      }
    }
  }
  // Writing to a frame's series (as tests do) gives it values of its own: the builder's history stays.
  FrameState edited = early;
  edited.plots[1].series[0].values[0] = 42;
  EXPECT_EQ(edited.plots[1].series[0].values[0], 42);
  EXPECT_TRUE(sameBits(early.plots[1].series[0].values[0], before[early.plots[0].series.size()][0]));
  EXPECT_NE(builder.frame(builder.frameCount() - 1).plots[1].series[0].values[0], 42);
}

// Paths and trails too: a frame kept while the builder walks on, dropping faded points, keeps its own.
TEST(FrameBuilder, KeptFramesKeepTheirPathsAndTrails) {
  const Scene scene = twoRunScene(R"(, "path_fade_seconds": 0.3, "trail_fade_seconds": 0.2)");
  FrameBuilder builder = builderFor(scene);
  const FrameState early = builder.frame(5);
  const std::vector<Vec3> path(early.runs[0].path.begin(), early.runs[0].path.end());
  const std::vector<double> times(early.runs[0].pathTimes.begin(), early.runs[0].pathTimes.end());
  const std::vector<Vec2> trail(early.runs[0].trails[0].begin(), early.runs[0].trails[0].end());
  ASSERT_EQ(path.size(), 13u);  // t = 0.2 .. 0.5 in steps of 0.025
  ASSERT_EQ(trail.size(), 3u);  // frames 3, 4, 5
  const FrameState late = builder.frame(builder.frameCount() - 1);
  EXPECT_GT(late.runs[0].pathTimes.front(), times.back());  // everything the early frame shows has faded since
  ASSERT_EQ(early.runs[0].path.size(), path.size());
  for (std::size_t i = 0; i < path.size(); ++i) {
    EXPECT_EQ(early.runs[0].path[i].x, path[i].x) << i;
    EXPECT_EQ(early.runs[0].pathTimes[i], times[i]) << i;
  }
  ASSERT_EQ(early.runs[0].trails[0].size(), trail.size());
  for (std::size_t i = 0; i < trail.size(); ++i) EXPECT_EQ(early.runs[0].trails[0][i].y, trail[i].y) << i;
}

// Steady axes: every frame's plot carries the same y range, that of the values the whole animation plots
// (checked against the last frame's full series).
TEST(FrameBuilder, PlotRangesAreTheWholeAnimationsFromTheFirstFrame) {
  const Scene scene = twoRunScene();
  FrameBuilder builder = builderFor(scene);
  const FrameState first = builder.frame(0);
  const FrameState last = builder.frame(builder.frameCount() - 1);
  ASSERT_EQ(first.plots.size(), 2u);
  for (std::size_t p = 0; p < 2; ++p) {
    ASSERT_TRUE(first.plots[p].valueRange) << p;
    EXPECT_EQ(first.plots[p].valueRange, last.plots[p].valueRange);
    double lo = INFINITY, hi = -INFINITY;
    for (const PlotSeries& series : last.plots[p].series)
      for (double v : series.values)
        if (std::isfinite(v) && v > 0) lo = std::min(lo, v), hi = std::max(hi, v);
    EXPECT_EQ((*first.plots[p].valueRange)[0], lo) << p;
    EXPECT_EQ((*first.plots[p].valueRange)[1], hi) << p;
    EXPECT_EQ(first.plots[p].emptiness, PlotEmptiness::HasValues);
  }
  // A range given by hand wins.
  Scene fixed = twoRunScene();
  fixed.view.plots[0].yRange = std::array<double, 2>{1e-12, 1.0};
  EXPECT_EQ(builderFor(fixed).frame(0).plots[0].valueRange, (std::array<double, 2>{1e-12, 1.0}));
}

// A still between frame times samples the motion m times as densely (cli/still_command.cpp) and reads the plots'
// axes and the linkage box off every m-th frame, the video's: comparison.json near its stop, where the extra
// frame times reach other values (without the stride the axes differ: 1e-13..1e-4 against the video's 1e-11..1e-3).
TEST(FrameBuilder, AStillBetweenFramesKeepsTheVideosAxesAndBox) {
  const Scene video = loadScene(testing::shippedScene("comparison.json"));
  Scene dense = video;
  const int m = 3;
  dense.output.fps *= m;
  const FrameState videoFrame = builderFor(video).frame(0);
  const FrameState strided = FrameBuilder(dense, startsOf(dense), runsOf(dense), familiesOf(dense), {}, m).frame(0);
  const FrameState unstrided = builderFor(dense).frame(0);
  ASSERT_EQ(videoFrame.plots.size(), 2u);
  bool anyDiffers = false;
  for (std::size_t p = 0; p < videoFrame.plots.size(); ++p) {
    ASSERT_TRUE(videoFrame.plots[p].valueRange) << p;
    EXPECT_EQ(strided.plots[p].valueRange, videoFrame.plots[p].valueRange) << p;
    anyDiffers = anyDiffers || unstrided.plots[p].valueRange != videoFrame.plots[p].valueRange;
  }
  EXPECT_TRUE(anyDiffers) << "the denser frames reach the video's values alone: the check cannot fail";
  EXPECT_EQ(strided.linkageBox, videoFrame.linkageBox);
}

// A plot that stays empty for the whole animation says why: here the published run stops at once on the seam.
TEST(FrameBuilder, APlotThatStaysEmptySaysWhy) {
  const Scene scene = parseScene(R"({"name": "s", "linkage": {"rods": 4, "L": 3},
    "initial": {"coords": [0.2, 1.5707963267948966], "velocity": [0.5, 0.7]}, "duration": 1.0,
    "runs": [{"name": "exact", "method": "christoffel", "integrator": "dopri5", "tolerance": 1e-10},
             {"name": "published", "method": "christoffel-fd", "integrator": "rk4", "step": 0.02}],
    "output": {"fps": 10}, "view": {"panels": [{"panel": "plot", "plot": "divergence"}]}})",
                                 "s.json");
  FrameBuilder builder = builderFor(scene);
  const FrameState frame = builder.frame(5);
  ASSERT_EQ(frame.plots.size(), 1u);
  EXPECT_FALSE(frame.plots[0].valueRange);
  EXPECT_EQ(frame.plots[0].kind, PlotKind::Divergence);
  EXPECT_EQ(frame.plots[0].referenceRun, "exact");
  EXPECT_EQ(frame.plots[0].emptiness, PlotEmptiness::RunsStopped);
  ASSERT_EQ(frame.plots[0].earlyStops.size(), 1u);
  EXPECT_EQ(frame.plots[0].earlyStops[0].run, "published");
  EXPECT_EQ(frame.plots[0].earlyStops[0].time, 0.0);
  EXPECT_EQ(frame.plots[0].earlyStops[0].reason, StopReason::FieldBlowUp);
}

// The sectional plot (5 rods): each run's largest and smallest curvature of the planes through its velocity, two
// series per run; each value is checked against planes through the velocity computed here, and the axis holds both.
TEST(FrameBuilder, SectionalPlotShowsTheRangeOfCurvatureThroughTheVelocity) {
  const Scene scene = parseScene(R"({"name": "s", "linkage": {"rods": 5, "L": 4},
    "initial": {"coords": [0.2, 0.3, 0.4], "velocity": [0.4, -0.3, 0.6]}, "duration": 2.0,
    "runs": [{"name": "g", "method": "ambient", "integrator": "dopri5", "tolerance": 1e-10}],
    "output": {"fps": 5}, "view": {"panels": ["sphere", {"panel": "plot", "plot": "sectional"}]}})",
                                 "s.json");
  ASSERT_EQ(scene.view.plots.size(), 1u);
  EXPECT_FALSE(scene.view.plots[0].logY);
  FrameBuilder builder = builderFor(scene);
  const FrameState last = builder.frame(builder.frameCount() - 1);
  ASSERT_EQ(last.plots[0].series.size(), 2u);
  const PlotSeries &high = last.plots[0].series[0], &low = last.plots[0].series[1];
  EXPECT_EQ(high.label, "g, largest");
  EXPECT_EQ(low.label, "g, smallest");
  ASSERT_EQ(high.values.size(), static_cast<std::size_t>(builder.frameCount()));
  Trajectory run(scene.runs[0].chain, startsOf(scene)[0], scene.runs[0].config);
  const ChainConstants bound(scene.runs[0].chain);
  for (int k = 0; k < builder.frameCount(); ++k) {
    const std::optional<Sample> sample = run.sampleAt(scene.frameTime(k));
    ASSERT_TRUE(sample);
    const Eigen::VectorXd& x = sample->spherePoint;
    const Eigen::VectorXd& v = sample->sphereVelocity;
    ASSERT_LT(low.values[std::size_t(k)], high.values[std::size_t(k)]);
    // Planes through v: each within the range.
    for (const Eigen::Vector4d& other : {Eigen::Vector4d(1, 0, 0, 0), Eigen::Vector4d(0, 1, 0, 0), Eigen::Vector4d(0, 0, 1, 1)}) {
      Eigen::VectorXd w = other - other.dot(x) * x;
      const double K = sectionalCurvature(bound, x, v, w);
      EXPECT_GE(K, low.values[std::size_t(k)] - 1e-10);
      EXPECT_LE(K, high.values[std::size_t(k)] + 1e-10);
    }
    ASSERT_TRUE(last.plots[0].valueRange);
    EXPECT_LE((*last.plots[0].valueRange)[0], low.values[std::size_t(k)]);
    EXPECT_GE((*last.plots[0].valueRange)[1], high.values[std::size_t(k)]);
  }
  // 4 rods: refused with its path.
  try {
    parseScene(R"({"name": "s", "linkage": {"rods": 4, "L": 3}, "initial": {"coords": [0.2, 0.3], "velocity": [0.4, 0.3]},
      "runs": [{"name": "g", "method": "ambient"}], "view": {"panels": [{"panel": "plot", "plot": "sectional"}]}})",
               "four.json");
    FAIL() << "a sectional plot of 4 rods was accepted";
  } catch (const std::exception& error) {
    EXPECT_NE(std::string(error.what()).find("view.panels[0]"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("expected 5 rods or more, found 4"), std::string::npos) << error.what();
  }
}

// The linkage panel's box is the part of the plane the whole motion sweeps, known from the first frame: the box
// of both pins and of every hinge the frames themselves show, at every frame.
TEST(FrameBuilder, TheLinkageBoxIsWhatTheFramesSweep) {
  const Scene scene = twoRunScene();
  FrameBuilder builder = builderFor(scene);
  const FrameState first = builder.frame(0);
  ASSERT_TRUE(first.linkageBox);
  std::array<double, 4> swept{0, scene.chain.baseLength, 0, 0};
  for (int k = 0; k < builder.frameCount(); ++k) {
    const FrameState frame = builder.frame(k);
    EXPECT_EQ(frame.linkageBox, first.linkageBox) << k;
    for (const RunFrame& run : frame.runs)
      for (const Vec2& h : run.hinges) {
        swept[0] = std::min(swept[0], h.x), swept[1] = std::max(swept[1], h.x);
        swept[2] = std::min(swept[2], h.y), swept[3] = std::max(swept[3], h.y);
      }
  }
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR((*first.linkageBox)[i], swept[i], 1e-12) << i;
  // Narrower than every configuration the chain can take (hinge 2 may reach 2 rods above the floor).
  EXPECT_LT((*first.linkageBox)[3] - (*first.linkageBox)[2], 3.0);
  // No linkage panel, no box.
  Scene plotsOnly = twoRunScene();
  std::erase_if(plotsOnly.view.panels, [](const PanelSpec& p) { return p.kind == PanelKind::Linkage; });
  EXPECT_FALSE(builderFor(plotsOnly).frame(0).linkageBox);
}

// An energy plot whose every value stays within what the run's tolerance allows says so in one line (its largest
// value, typeset); one with a value above that (a fixed-step run) draws its axis. Checked against the values the
// frames plot.
TEST(FrameBuilder, ARoundoffOnlyPlotSaysSo) {
  const Scene scene = parseScene(R"({"name": "r", "linkage": {"rods": 4, "L": 3, "rod_masses": [1, 1, 1, 1]},
    "initial": {"drag": {"point": [0.936, 0.190, 0.296], "direction": [-0.35, 0.55, 0.75]}, "unit_speed": true},
    "duration": 1.0,
    "runs": [{"name": "exact", "method": "ambient", "integrator": "dopri5", "tolerance": 1e-10}],
    "output": {"fps": 10}, "view": {"panels": [{"panel": "plot", "plot": "energy"}]}})",
                                 "r.json");
  FrameBuilder builder = builderFor(scene);
  const FrameState last = builder.frame(builder.frameCount() - 1);
  double largest = 0;
  for (const double v : last.plots[0].series[0].values)
    if (std::isfinite(v)) largest = std::max(largest, v);
  ASSERT_LE(largest, limits::kToleranceEnergyFactor * 1e-10) << "energy drifts beyond the tolerance";
  ASSERT_GT(largest, limits::kRoundoffLevel);
  ASSERT_TRUE(last.plots[0].roundoff);
  EXPECT_EQ(last.plots[0].roundoff->largest, largest);
  EXPECT_TRUE(last.plots[0].roundoff->byTolerance);
  EXPECT_EQ(last.plots[0].roundoff->runs, 1u);
  EXPECT_EQ(last.plots[0].emptiness, PlotEmptiness::HasValues);
  // The published method's drift is far above roundoff: an axis.
  const FrameState published = builderFor(twoRunScene()).frame(0);
  EXPECT_FALSE(published.plots[1].roundoff);
}

// The linkage panel's physics: each run's masses, and a push start's arrow (the pushed hinge's start velocity)
// in the first frames only.
TEST(FrameBuilder, MassesAndAPushReachTheFrames) {
  const Scene scene = parseScene(R"({"name": "p", "linkage": {"rods": 6, "L": 3, "hinge_masses": [0, 1, 2, 3, 4],
                                             "rod_masses": [1, 1, 1, 1, 1, 1]},
    "initial": {"hinges": "arc", "push": {"hinge": 2, "velocity": [0.5, 1.5]}}, "duration": 3.0,
    "runs": [{"name": "pushed", "method": "ambient", "integrator": "dopri5", "tolerance": 1e-8}],
    "output": {"fps": 10}, "view": {"panels": ["linkage"]}})",
                                 "p.json");
  FrameBuilder builder = builderFor(scene);
  const FrameState first = builder.frame(0);
  EXPECT_EQ(first.runs[0].hingeMasses, (std::vector<double>{0, 1, 2, 3, 4}));
  EXPECT_EQ(first.runs[0].rodMasses, std::vector<double>(6, 1.0));
  // The pushed hinge is marked, along the push (its velocity projected onto the rods' constraints).
  const auto& push = first.runs[0].push;
  const auto pushed = std::find_if(push.begin(), push.end(), [](const RunFrame::HingeArrow& a) { return a.hinge == 2; });
  ASSERT_NE(pushed, push.end());
  EXPECT_GT(0.5 * pushed->velocity.x + 1.5 * pushed->velocity.y, 0) << "the arrow points against the push";
  EXPECT_EQ(first.runs[0].pushShown, 1.0f);
  const FrameState later = builder.frame(int(limits::kPushShownSeconds * 10) + 1);
  EXPECT_TRUE(later.runs[0].push.empty());
  EXPECT_TRUE(builderFor(twoRunScene()).frame(0).runs[0].push.empty()) << "coordinates and rates are no push";
}

// Memory per run is bounded: a long, densely sampled path is thinned in its older part, never in its newest.
TEST(FrameBuilder, PathHistoryIsBounded) {
  const Scene scene = parseScene(R"({"name": "long", "linkage": {"rods": 4, "L": 3},
    "initial": {"coords": [0.3, 0.2], "velocity": [0.5, 0.7]}, "duration": 120.0,
    "runs": [{"name": "a", "method": "ambient", "integrator": "dopri5", "tolerance": 1e-8}],
    "output": {"fps": 30}, "view": {"path_samples_per_frame": 100}})",
                                 "long.json");
  FrameBuilder builder = builderFor(scene);
  const FrameState last = builder.frame(builder.frameCount() - 1);
  const RunFrame& run = last.runs[0];
  EXPECT_LE(run.path.size(), limits::kMaxPathPoints);
  EXPECT_GT(run.path.size(), limits::kMaxPathPoints / 2);
  ASSERT_EQ(run.path.size(), run.pathTimes.size());
  const double spacing = 1.0 / (30 * 100);
  for (std::size_t i = run.pathTimes.size() - limits::kRecentPathPoints + 1; i < run.pathTimes.size(); ++i)
    EXPECT_NEAR(run.pathTimes[i] - run.pathTimes[i - 1], spacing, 1e-9) << i;
  EXPECT_EQ(run.pathTimes.front(), 0.0);  // the start is kept
  EXPECT_EQ(run.pathTimes.back(), 120.0);
}

TEST(FrameBuilder, RefusesFramesOutOfOrder) {
  const Scene scene = twoRunScene();
  FrameBuilder builder = builderFor(scene);
  builder.frame(5);
  EXPECT_THROW(builder.frame(4), std::out_of_range);
  EXPECT_THROW(builder.frame(11), std::out_of_range);
}

}  // namespace
}  // namespace sl

// view.sphere: the decoration is computed once from the exact geometry and shared by every frame.
#include "frames/sphere_decoration.hpp"
#include "geometry/curvature.hpp"

namespace sl {
namespace {

TEST(SphereDecoration, CurvatureFieldMatchesTheGeometryAndEllipsesAreTangent) {
  const Chain chain = Chain::uniform(4, 3.0);
  EXPECT_EQ(makeSphereDecoration(chain, {}), nullptr);
  const auto decoration = makeSphereDecoration(chain, {SphereColoring::Curvature, true});
  ASSERT_NE(decoration, nullptr);
  ASSERT_TRUE(decoration->field);
  const SphereField& field = *decoration->field;
  EXPECT_TRUE(field.diverging);
  ASSERT_EQ(field.values.size(), std::size_t(field.phiCount * field.tCount));
  // The range: K from about -0.272 to 4.15 at L = 3 (docs/geometry.md); the grid's cell centres come close.
  EXPECT_NEAR(field.min, -0.2718, 2e-3);
  EXPECT_NEAR(field.max, 4.15, 0.1);
  // A value at its cell centre is the surface's K there.
  const ConfigurationSurface surface(chain);
  const double pi = std::acos(-1.0);
  const int i = 83, j = 177;
  const double phi = -pi / 2 + (i + 0.5) * pi / field.phiCount, t = -pi + (j + 0.5) * 2 * pi / field.tCount;
  EXPECT_NEAR(field.values[i * field.tCount + j], surface.curvatureAtCoordinates(phi, t).gaussianCurvature, 1e-6);

  ASSERT_EQ(decoration->ellipses.size(), std::size_t(kStiffnessEllipses));
  for (const SphereEllipse& e : decoration->ellipses) {
    const Eigen::Vector3d c(e.centre.x, e.centre.y, e.centre.z), major(e.major.x, e.major.y, e.major.z),
        minor(e.minor.x, e.minor.y, e.minor.z);
    EXPECT_NEAR(c.norm(), 1.0, 1e-12);
    EXPECT_NEAR(c.dot(major), 0.0, 1e-12);
    EXPECT_NEAR(c.dot(minor), 0.0, 1e-12);
    EXPECT_GE(major.norm(), minor.norm() - 1e-15);
    EXPECT_GT(major.norm(), 0.0);
  }
  const auto bending = makeSphereDecoration(chain, {SphereColoring::Bending, false});
  EXPECT_FALSE(bending->field->diverging);
  EXPECT_GT(bending->field->min, 0.0);
  EXPECT_TRUE(bending->ellipses.empty());
}

}  // namespace
}  // namespace sl

// view.sphere color_by distance: the field is the distance from the point, each curve is a locus of it.
#include "inverse/connect.hpp"
#include "linkage/chart.hpp"

namespace sl {
namespace {

Eigen::VectorXd stackedAt(const Chain& chain, const Eigen::Vector3d& x) {
  return ConstrainedModel::stack(hingePositionsAt(chain, x));
}

// The shortest motions from `from` to `to` by shooting (inverse/connect.hpp), independent of the distance map's
// rasterised fan: their lengths, shortest first.
std::vector<double> connectionLengths(const Chain& chain, const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  ConnectOptions options;
  options.discreteRoute = false;
  std::vector<double> lengths;
  for (const Connection& c :
       findConnections(ConstrainedModel::fromChain(chain), &chain, stackedAt(chain, from), stackedAt(chain, to), options))
    lengths.push_back(c.length);
  return lengths;
}

TEST(SphereDecoration, DistanceFieldIsTheShortestMotionsLengthAndTheCutLocusWhereTwoAreShortest) {
  const Chain chain = Chain::uniform(4, 3.0);
  const Eigen::Vector3d point = Eigen::Vector3d(0.936, 0.190, 0.296).normalized();
  EXPECT_THROW(makeSphereDecoration(chain, {SphereColoring::Distance}), std::invalid_argument);
  const auto decoration = makeSphereDecoration(chain, {SphereColoring::Distance}, point, true);
  ASSERT_NE(decoration, nullptr);
  ASSERT_TRUE(decoration->field && decoration->distance);
  const SphereField& field = *decoration->field;
  EXPECT_EQ(field.coloring, SphereColoring::Distance);
  EXPECT_FALSE(field.diverging);
  EXPECT_EQ(field.phiCount, kSphereFieldRows);
  EXPECT_EQ(field.tCount, 2 * kSphereFieldRows);
  EXPECT_EQ(field.min, 0.0);
  EXPECT_NEAR((Eigen::Vector3d(decoration->distance->point.x, decoration->distance->point.y,
                               decoration->distance->point.z) - point).norm(), 0.0, 1e-9);
  EXPECT_TRUE(decoration->distance->fromStart);
  // A cell's value is the length of the shortest motion from the point to the cell's centre.
  const double pi = std::acos(-1.0);
  auto centre = [&](int i, int j) {
    const double phi = -pi / 2 + (i + 0.5) * pi / field.phiCount, t = -pi + (j + 0.5) * 2 * pi / field.tCount;
    return Eigen::Vector3d(std::cos(phi) * std::cos(t), std::cos(phi) * std::sin(t), std::sin(phi));
  };
  for (const auto& [i, j] : {std::pair{70, 140}, {40, 60}, {100, 200}, {64, 10}}) {
    SCOPED_TRACE(std::to_string(i) + ", " + std::to_string(j));
    const std::vector<double> lengths = connectionLengths(chain, point, centre(i, j));
    ASSERT_FALSE(lengths.empty());
    EXPECT_NEAR(field.values[static_cast<std::size_t>(i * field.tCount + j)], lengths.front(), 2e-2);
    EXPECT_LE(field.values[static_cast<std::size_t>(i * field.tCount + j)], field.max);
  }
  // Both loci are drawn; every point on the unit sphere. In the middle of the longest cut-locus curve two motions of
  // (nearly) the same length are the shortest; beside the point, one is much shorter than any other.
  const SphereCurve* cut = nullptr;
  bool conjugate = false;
  for (const SphereCurve& curve : decoration->curves) {
    for (const Vec3& p : curve.points) EXPECT_NEAR(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z), 1.0, 1e-12);
    conjugate = conjugate || curve.kind == SphereCurveKind::ConjugateLocus;
    if (curve.kind == SphereCurveKind::CutLocus && (!cut || curve.points.size() > cut->points.size())) cut = &curve;
  }
  EXPECT_TRUE(conjugate);
  ASSERT_NE(cut, nullptr);
  const Vec3 middle = cut->points[cut->points.size() / 2];
  const std::vector<double> atCut = connectionLengths(chain, point, {middle.x, middle.y, middle.z});
  ASSERT_GE(atCut.size(), 2u);
  EXPECT_NEAR(atCut[0], atCut[1], 3e-2) << "two shortest motions meet on the cut locus";
  EXPECT_GE(atCut[0], decoration->distance->injectivityRadius - 1e-6);
  const std::vector<double> near = connectionLengths(chain, point, centre(70, 140));
  if (near.size() >= 2) {
    EXPECT_GT(near[1] - near[0], 0.3);
  }
}

}  // namespace
}  // namespace sl

namespace sl {
namespace {

// view.sphere.closed_geodesics: the three simple closed geodesics of the 4-rod chain at L = 3, each a closed curve
// on the unit sphere; the 5-rod refusal is the loader's (tests/data/scenes/bad/closed_geodesics_five_rods.json).
TEST(SphereDecoration, ClosedGeodesicsAreTheThreeSimpleOnesEachClosed) {
  const Chain chain = Chain::uniform(4, 3.0);
  SphereSurfaceSpec spec;
  spec.closedGeodesics = true;
  const auto decoration = makeSphereDecoration(chain, spec);
  ASSERT_NE(decoration, nullptr);
  EXPECT_FALSE(decoration->field);
  ASSERT_EQ(decoration->curves.size(), 3u);
  for (const SphereCurve& curve : decoration->curves) {
    EXPECT_EQ(curve.kind, SphereCurveKind::ClosedGeodesic);
    ASSERT_GT(curve.points.size(), 500u);
    const Vec3 &a = curve.points.front(), &b = curve.points.back();
    EXPECT_LT(std::hypot(a.x - b.x, a.y - b.y, a.z - b.z), 1e-6) << "closes after one period";
    double longest = 0;  // sampled densely: no chord longer than a few degrees
    for (std::size_t k = 1; k < curve.points.size(); ++k) {
      const Vec3 &p = curve.points[k - 1], &q = curve.points[k];
      longest = std::max(longest, std::hypot(p.x - q.x, p.y - q.y, p.z - q.z));
      EXPECT_NEAR(std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z), 1.0, 1e-12);
    }
    EXPECT_LT(longest, 0.06);
  }
}

// A vector carried round a geodesic triangle (view.sphere.holonomy): arrows round the loop from the first corner back
// to it, each tangent to the sphere; the three figures of Gauss-Bonnet agree.
TEST(SphereDecoration, HolonomyArrowsGoRoundTheTriangleAndItsFiguresAgree) {
  const Chain chain = Chain::uniform(4, 3.0);
  auto point = [](double phi, double t) {
    return Eigen::VectorXd(Eigen::Vector3d(std::cos(phi) * std::cos(t), std::cos(phi) * std::sin(t), std::sin(phi)));
  };
  const std::vector<Eigen::VectorXd> corners = {point(0.2, 0.0), point(0.3, 1.4), point(1.2, 0.6)};
  SphereSurfaceSpec spec;
  spec.holonomy = true;
  EXPECT_THROW(makeSphereDecoration(chain, spec), std::invalid_argument);  // the corners were not given
  const auto decoration = makeSphereDecoration(chain, spec, {}, true, corners);
  ASSERT_NE(decoration, nullptr);
  ASSERT_TRUE(decoration->transport);
  const SphereTransport& t = *decoration->transport;
  ASSERT_EQ(t.corners.size(), 3u);
  ASSERT_GE(t.arrows.size(), 7u);
  auto near = [](const Vec3& a, const Eigen::VectorXd& b, double tolerance) {
    return std::abs(a.x - b(0)) < tolerance && std::abs(a.y - b(1)) < tolerance && std::abs(a.z - b(2)) < tolerance;
  };
  EXPECT_TRUE(near(t.arrows.front().base, corners[0], 1e-12));
  EXPECT_TRUE(near(t.arrows.back().base, corners[0], 1e-8));  // back at the first corner
  for (const SphereTransport::Arrow& a : t.arrows) {
    EXPECT_NEAR(a.base.x * a.direction.x + a.base.y * a.direction.y + a.base.z * a.direction.z, 0.0, 1e-8);  // tangent
    EXPECT_NEAR(std::hypot(a.direction.x, a.direction.y, a.direction.z), 1.0, 1e-12);
  }
  // The returning arrow differs from the starting one: the vector came back turned.
  const double turned = std::acos(t.arrows.front().direction.x * t.arrows.back().direction.x +
                                  t.arrows.front().direction.y * t.arrows.back().direction.y +
                                  t.arrows.front().direction.z * t.arrows.back().direction.z);
  EXPECT_GT(turned, 0.1);
  EXPECT_NEAR(t.holonomy, 0.3298489844393, 1e-9);  // docs/geometry.md's triangle, by the CLI
  EXPECT_NEAR(t.angleExcess, t.holonomy, 1e-8);
  EXPECT_NEAR(t.enclosedCurvature, t.holonomy, 1e-8);
  // Carried over the animation, every side at once: each side's vector from its first corner to the next, and the
  // curvature the sides sweep from 0 to the enclosed curvature.
  for (std::size_t side = 0; side < 3; ++side) {
    EXPECT_TRUE(near(t.carriedAt(side, 0.0).base, corners[side], 1e-8)) << side;
    EXPECT_TRUE(near(t.carriedAt(side, 1.0).base, corners[(side + 1) % 3], 1e-8)) << side;
    const SphereTransport::Arrow between = t.carriedAt(side, 0.37);
    EXPECT_NEAR(between.base.x * between.direction.x + between.base.y * between.direction.y +
                    between.base.z * between.direction.z,
                0.0, 1e-12);
    EXPECT_NEAR(std::hypot(between.base.x, between.base.y, between.base.z), 1.0, 1e-12);
  }
  EXPECT_EQ(t.sweptAt(0.0), 0.0);
  EXPECT_NEAR(t.sweptAt(1.0), t.enclosedCurvature, 1e-9);
}

// The holonomy plot: one line, the curvature the sides have swept by each frame, from 0 at the start to the
// holonomy at the end, inside the axis fixed from the first frame; refused without the polygon it plots.
TEST(FrameBuilder, HolonomyPlotRisesFromZeroToTheHolonomy) {
  const std::string polygon = R"("holonomy": {"corners": [{"coords": [0.2, 0.0]}, {"coords": [0.3, 1.4]},
    {"coords": [1.2, 0.6]}]})";
  const Scene scene = parseScene(R"({"name": "h", "linkage": {"rods": 4, "L": 3}, "duration": 1.0,
    "initial": {"coords": [0.2, 0.0], "velocity": [0.1, 1.0]}, "runs": [{"name": "g", "method": "ambient"}],
    "output": {"fps": 4}, "view": {"panels": ["sphere", {"panel": "plot", "plot": "holonomy"}],
    "sphere": {)" + polygon + R"(}}})",
                                 "h.json");
  ASSERT_EQ(scene.view.plots.size(), 1u);
  EXPECT_FALSE(scene.view.plots[0].logY);
  ASSERT_EQ(scene.holonomyCorners.size(), 3u);
  Scene resolved = scene;  // the corners' chart-0 points, as the commands resolve them (cli/motion_starts.hpp)
  for (const auto& [phi, t] : {std::pair{0.2, 0.0}, std::pair{0.3, 1.4}, std::pair{1.2, 0.6}})
    resolved.holonomyPoints.push_back(
        Eigen::Vector3d(std::cos(phi) * std::cos(t), std::cos(phi) * std::sin(t), std::sin(phi)));
  FrameBuilder builder = builderFor(resolved);
  const FrameState first = builder.frame(0);
  ASSERT_EQ(first.plots[0].series.size(), 1u);
  EXPECT_EQ(first.plots[0].series[0].values.size(), 1u);
  EXPECT_EQ(first.plots[0].series[0].values[0], 0.0);
  const FrameState last = builder.frame(builder.frameCount() - 1);
  const PlotSeries& line = last.plots[0].series[0];
  ASSERT_EQ(line.values.size(), static_cast<std::size_t>(builder.frameCount()));
  EXPECT_NEAR(line.values[line.values.size() - 1], 0.3298489844393, 1e-8);  // the triangle's holonomy
  ASSERT_TRUE(first.plots[0].valueRange);
  for (double v : line.values) {
    EXPECT_GE(v, (*first.plots[0].valueRange)[0]);
    EXPECT_LE(v, (*first.plots[0].valueRange)[1]);
  }
  try {
    parseScene(R"({"name": "h", "linkage": {"rods": 4, "L": 3}, "duration": 1.0,
      "initial": {"coords": [0.2, 0.0], "velocity": [0.1, 1.0]}, "runs": [{"name": "g", "method": "ambient"}],
      "view": {"panels": ["sphere", {"panel": "plot", "plot": "holonomy"}]}})",
               "plain.json");
    FAIL() << "a holonomy plot without a polygon was accepted";
  } catch (const std::exception& error) {
    EXPECT_NE(std::string(error.what()).find("view.panels[1].plot"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("expected view.sphere.holonomy"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace sl
