#include "frames/plot_overview.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "contracts/limits.hpp"
#include "contracts/parallel_for.hpp"
#include "contracts/registry.hpp"
#include "geometry/sectional_curvature.hpp"
#include "linkage/chain.hpp"
#include "linkage/chain_constants.hpp"
#include "simulation/family.hpp"
#include "simulation/trajectory.hpp"

namespace sl {
namespace {

bool drawable(double v, bool logY) { return std::isfinite(v) && (!logY || v > 0); }

bool showsLinkage(const Scene& scene) {
  return scene.view.panels.empty() || std::any_of(scene.view.panels.begin(), scene.view.panels.end(),
                                                  [](const PanelSpec& panel) { return panel.kind == PanelKind::Linkage; });
}

// The box {x0, x1, y0, y1} grown to hold p.
void holdPoint(std::array<double, 4>& box, double x, double y) {
  if (!std::isfinite(x) || !std::isfinite(y)) return;
  box[0] = std::min(box[0], x), box[1] = std::max(box[1], x);
  box[2] = std::min(box[2], y), box[3] = std::max(box[3], y);
}

// Set when every value lies within roundoff (or, for an energy error, within what its integrator's tolerance
// allows): `allowed` is that level. Only the plots whose steady values would be noise: a Jacobi field's zeros are its
// events, and a family that stays together is what the spread plot is there to show.
std::optional<PlotFrame::RoundoffOnly> roundoffOnly(PlotKind kind, double largest, double allowed, std::size_t runs) {
  if (!(largest >= 0 && largest <= allowed)) return std::nullopt;  // -inf: no value at all
  switch (kind) {
    case PlotKind::EnergyError:
    case PlotKind::Divergence:
      return PlotFrame::RoundoffOnly{largest, largest > limits::kRoundoffLevel, runs};
    case PlotKind::Jacobi:
    case PlotKind::Spread:
    case PlotKind::Sectional:
    case PlotKind::Holonomy:
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace

std::array<double, 2> curvatureThroughVelocity(const Chain& chain, const Sample& sample) {
  const double nan = std::nan("");
  if (chain.rods < 5 || chain.isSlack() || chain.rods > limits::kMaxRods || !(sample.sphereVelocity.norm() > 0))
    return {nan, nan};
  return sectionalCurvatureThrough(ChainConstants(chain), sample.spherePoint, sample.sphereVelocity);
}

MotionOverview overviewMotion(const Scene& scene, const std::vector<InitialState>& starts,
                              const std::function<bool()>& cancelled, const SphereTransport* transport) {
  const std::vector<PlotSpec>& plots = scene.view.plots;
  const bool anyFamily =
      std::any_of(scene.runs.begin(), scene.runs.end(), [](const RunSpec& run) { return bool(run.family); });
  const bool wantBox = showsLinkage(scene) && !anyFamily && !scene.runs.empty();
  if (plots.empty() && !wantBox) return {};
  const std::size_t runCount = scene.runs.size();
  std::array<double, 4> box{0, 0, 0, 0};
  for (const RunSpec& run : scene.runs) holdPoint(box, run.chain.baseLength, 0);
  std::vector<Trajectory> runs;
  for (std::size_t r = 0; r < runCount; ++r) {
    runs.emplace_back(scene.runs[r].chain, starts.at(r), scene.runs[r].config);
    runs.back().setCancellation(cancelled);
  }

  // Per frame: each run's divergence from run 0 (index 0 unused) and its energy error; NaN where not defined.
  const int frames = scene.frameCount();
  const double nan = std::nan("");
  std::vector<std::vector<double>> divergence(runCount), energy(runCount), jacobi(runCount), spread(runCount),
      sectional(runCount), holonomy(runCount);
  const bool wantSectional =
      std::any_of(plots.begin(), plots.end(), [](const PlotSpec& plot) { return plot.kind == PlotKind::Sectional; });
  std::vector<bool> stopped(runCount, false);
  // The families, only if a spread plot shows them.
  const bool wantSpread =
      std::any_of(plots.begin(), plots.end(), [](const PlotSpec& plot) { return plot.kind == PlotKind::Spread; });
  std::vector<std::vector<Trajectory>> members(runCount);
  std::vector<std::pair<std::size_t, std::size_t>> memberJobs;
  for (std::size_t r = 0; r < runCount && wantSpread; ++r) {
    if (!scene.runs[r].family) continue;
    const RunSpec& run = scene.runs[r];
    members[r] = familyMembers(run.chain, starts.at(r), *run.family, run.config, cancelled);
    for (std::size_t m = 0; m < members[r].size(); ++m) memberJobs.emplace_back(r, m);
  }
  std::vector<std::optional<Sample>> memberSamples(memberJobs.size());
  for (int k = 0; k < frames; ++k) {
    const double t = scene.frameTime(k);
    std::vector<std::optional<Sample>> samples(runCount);
    for (std::size_t r = 0; r < runCount; ++r) {
      if (!stopped[r]) samples[r] = runs[r].sampleAt(t);
      stopped[r] = stopped[r] || !samples[r];
      if (samples[r])
        for (Eigen::Index j = 0; j < samples[r]->hinges.cols(); ++j)
          holdPoint(box, samples[r]->hinges(0, j), samples[r]->hinges(1, j));
      energy[r].push_back(samples[r] ? std::abs(samples[r]->relativeEnergyDrift) : nan);
      jacobi[r].push_back(samples[r] ? samples[r]->jacobi.value_or(nan) : nan);
      if (wantSectional) {  // both ends of the range: the axis holds them all
        const std::array<double, 2> through = samples[r] ? curvatureThroughVelocity(scene.runs[r].chain, *samples[r])
                                                         : std::array<double, 2>{nan, nan};
        sectional[r].insert(sectional[r].end(), through.begin(), through.end());
      }
      divergence[r].push_back(r > 0 && samples[0] && samples[r] ? hingeDistance(samples[0]->hinges, samples[r]->hinges)
                                                                 : nan);
    }
    if (transport && runCount > 0)
      holonomy[0].push_back(transport->sweptAt(SphereTransport::carriedFraction(t, scene.duration)));  // one line
    parallelFor(memberJobs.size(), [&](std::size_t j) {
      const auto [r, m] = memberJobs[j];
      if (k == 0 || memberSamples[j]) memberSamples[j] = members[r][m].sampleAt(t);  // a stopped member stays out
    });
    for (std::size_t r = 0; r < runCount; ++r) spread[r].push_back(nan);
    for (std::size_t j = 0; j < memberJobs.size(); ++j) {
      const std::size_t r = memberJobs[j].first;
      if (!samples[r] || !memberSamples[j]) continue;
      const double distance = hingeDistance(samples[r]->hinges, memberSamples[j]->hinges);
      spread[r].back() = std::isnan(spread[r].back()) ? distance : std::max(spread[r].back(), distance);
    }
  }

  MotionOverview overview;
  if (wantBox) overview.linkageBox = box;
  for (const PlotSpec& spec : plots) {
    const bool isDivergence = spec.kind == PlotKind::Divergence;
    const auto& values = [&]() -> const std::vector<std::vector<double>>& {
      switch (spec.kind) {  // every kind, no default: the compiler names a kind left out
        case PlotKind::Divergence: return divergence;
        case PlotKind::Jacobi: return jacobi;
        case PlotKind::Spread: return spread;
        case PlotKind::EnergyError: return energy;
        case PlotKind::Sectional: return sectional;
        case PlotKind::Holonomy:
          return holonomy;
      }
      throw std::logic_error("overviewMotion: a plot kind without values");
    }();
    double lo = INFINITY, hi = -INFINITY, largest = -INFINITY;
    // A level every run's values stay under: roundoff, or for an energy error of adaptive runs alone their
    // tolerance's (limits::kToleranceEnergyFactor), the least of the runs'.
    double allowed = INFINITY;
    std::size_t shown = 0;  // runs with a value past the start (at the start alone, runs agree exactly)
    for (std::size_t r = isDivergence ? 1 : 0; r < runCount; ++r) {
      std::size_t finite = 0;
      for (double v : values[r]) {
        if (drawable(v, spec.logY)) lo = std::min(lo, v), hi = std::max(hi, v);
        if (std::isfinite(v)) largest = std::max(largest, std::abs(v)), ++finite;
      }
      shown += finite > 1 ? 1 : 0;
      const RunConfig& config = scene.runs[r].config;
      const bool byTolerance = spec.kind == PlotKind::EnergyError && traits(config.integrator).adaptive;
      allowed = std::min(allowed, std::max(limits::kRoundoffLevel,
                                           byTolerance ? limits::kToleranceEnergyFactor * config.tolerance : 0.0));
    }
    PlotOverview& plot = overview.plots.emplace_back();
    if (spec.yRange) {
      plot.valueRange = spec.yRange;
    } else if (lo <= hi) {
      plot.valueRange = std::array<double, 2>{lo, hi};
    }
    if (shown > 0) plot.roundoff = roundoffOnly(spec.kind, largest, allowed, shown);
    if (!(lo <= hi) && !plot.roundoff) {
      // Say why: runs that stopped at once, or values a log axis cannot show (exactly zero).
      for (std::size_t r = 0; r < runCount; ++r)
        if (runs[r].stop() && runs[r].stop()->time <= scene.frameTime(std::min(frames - 1, 1)))
          plot.earlyStops.push_back({scene.runs[r].name, runs[r].stop()->time, runs[r].stop()->reason});
      plot.emptiness = !plot.earlyStops.empty() ? PlotEmptiness::RunsStopped
                           : spec.logY                  ? PlotEmptiness::ZeroOnLogAxis
                                                        : PlotEmptiness::NothingToPlot;
    }
  }
  return overview;
}

}  // namespace sl
