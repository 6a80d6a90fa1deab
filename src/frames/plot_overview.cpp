#include "frames/plot_overview.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "contracts/parallel_for.hpp"
#include "linkage/chain.hpp"
#include "simulation/family.hpp"
#include "simulation/trajectory.hpp"

namespace sl {
namespace {

bool drawable(double v, bool logY) { return std::isfinite(v) && (!logY || v > 0); }

}  // namespace

std::vector<PlotOverview> overviewPlots(const Scene& scene, const std::vector<InitialState>& starts,
                                        const std::function<bool()>& cancelled) {
  const std::vector<PlotSpec>& plots = scene.view.plots;
  if (plots.empty()) return {};
  const std::size_t runCount = scene.runs.size();
  std::vector<Trajectory> runs;
  for (std::size_t r = 0; r < runCount; ++r) {
    runs.emplace_back(scene.runs[r].chain, starts.at(r), scene.runs[r].config);
    runs.back().setCancellation(cancelled);
  }

  // Per frame: each run's divergence from run 0 (index 0 unused) and its energy error; NaN where not defined.
  const int frames = scene.frameCount();
  const double nan = std::nan("");
  std::vector<std::vector<double>> divergence(runCount), energy(runCount), jacobi(runCount), spread(runCount);
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
      energy[r].push_back(samples[r] ? std::abs(samples[r]->relativeEnergyDrift) : nan);
      jacobi[r].push_back(samples[r] ? samples[r]->jacobi.value_or(nan) : nan);
      divergence[r].push_back(r > 0 && samples[0] && samples[r] ? hingeDistance(samples[0]->hinges, samples[r]->hinges)
                                                                 : nan);
    }
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

  std::vector<PlotOverview> overviews;
  for (const PlotSpec& spec : plots) {
    const bool isDivergence = spec.kind == PlotKind::Divergence;
    const auto& values = [&]() -> const std::vector<std::vector<double>>& {
      switch (spec.kind) {  // every kind, no default: the compiler names a kind left out
        case PlotKind::Divergence: return divergence;
        case PlotKind::Jacobi: return jacobi;
        case PlotKind::Spread: return spread;
        case PlotKind::EnergyError: return energy;
      }
      throw std::logic_error("overviewPlots: a plot kind without values");
    }();
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t r = isDivergence ? 1 : 0; r < runCount; ++r)
      for (double v : values[r])
        if (drawable(v, spec.logY)) lo = std::min(lo, v), hi = std::max(hi, v);
    PlotOverview overview;
    if (spec.yRange) {
      overview.valueRange = spec.yRange;
    } else if (lo <= hi) {
      overview.valueRange = std::array<double, 2>{lo, hi};
    }
    if (!(lo <= hi)) {
      // Say why: runs that stopped at once, or values a log axis cannot show (exactly zero).
      for (std::size_t r = 0; r < runCount; ++r)
        if (runs[r].stop() && runs[r].stop()->time <= scene.frameTime(std::min(frames - 1, 1)))
          overview.earlyStops.push_back({scene.runs[r].name, runs[r].stop()->time, runs[r].stop()->reason});
      overview.emptiness = !overview.earlyStops.empty() ? PlotEmptiness::RunsStopped
                           : spec.logY                  ? PlotEmptiness::ZeroOnLogAxis
                                                        : PlotEmptiness::NothingToPlot;
    }
    overviews.push_back(std::move(overview));
  }
  return overviews;
}

}  // namespace sl
