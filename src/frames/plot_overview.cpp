#include "frames/plot_overview.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "contracts/limits.hpp"
#include "contracts/registry.hpp"
#include "geometry/sectional_curvature.hpp"
#include "linkage/chain.hpp"
#include "linkage/chain_constants.hpp"
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

OverviewReader::OverviewReader(const Scene& scene, const SphereTransport* transport, int videoStride)
    : scene_(scene),
      transport_(transport),
      videoStride_(std::max(videoStride, 1)),
      divergence_(scene.runs.size()),
      energy_(scene.runs.size()),
      jacobi_(scene.runs.size()),
      spread_(scene.runs.size()),
      sectional_(scene.runs.size()),
      holonomy_(scene.runs.size()) {
  const std::vector<PlotSpec>& plots = scene.view.plots;
  const auto anyPlot = [&](PlotKind kind) {
    return std::any_of(plots.begin(), plots.end(), [&](const PlotSpec& plot) { return plot.kind == kind; });
  };
  const bool anyFamily =
      std::any_of(scene.runs.begin(), scene.runs.end(), [](const RunSpec& run) { return bool(run.family); });
  wantBox_ = showsLinkage(scene) && !anyFamily && !scene.runs.empty();
  wantSpread_ = anyPlot(PlotKind::Spread);  // the families, only if a spread plot shows them
  wantSectional_ = anyPlot(PlotKind::Sectional);
  for (const RunSpec& run : scene.runs) holdPoint(box_, run.chain.baseLength, 0);
}

void OverviewReader::read(const SurveyFrame& frame) {
  if (frame.index % videoStride_ != 0) return;
  const double nan = std::nan("");
  const std::size_t runCount = frame.runs.size();
  const std::vector<const Sample*>& samples = frame.runs;
  for (std::size_t r = 0; r < runCount; ++r) {
    if (samples[r])
      for (Eigen::Index j = 0; j < samples[r]->hinges.cols(); ++j)
        holdPoint(box_, samples[r]->hinges(0, j), samples[r]->hinges(1, j));
    energy_[r].push_back(samples[r] ? std::abs(samples[r]->relativeEnergyDrift) : nan);
    jacobi_[r].push_back(samples[r] ? samples[r]->jacobi.value_or(nan) : nan);
    if (wantSectional_) {  // both ends of the range: the axis holds them all
      const std::array<double, 2> through =
          samples[r] ? curvatureThroughVelocity(scene_.runs[r].chain, *samples[r]) : std::array<double, 2>{nan, nan};
      sectional_[r].insert(sectional_[r].end(), through.begin(), through.end());
    }
    divergence_[r].push_back(r > 0 && samples[0] && samples[r] ? hingeDistance(samples[0]->hinges, samples[r]->hinges)
                                                               : nan);
    spread_[r].push_back(nan);
    for (std::size_t m = 0; m < frame.members[r].size() && wantSpread_; ++m) {
      const Sample* member = frame.members[r][m];
      if (!samples[r] || !member) continue;
      const double distance = hingeDistance(samples[r]->hinges, member->hinges);
      spread_[r].back() = std::isnan(spread_[r].back()) ? distance : std::max(spread_[r].back(), distance);
    }
  }
  if (transport_ && runCount > 0)  // one line
    holonomy_[0].push_back(transport_->sweptAt(SphereTransport::carriedFraction(frame.time, scene_.duration)));
}

MotionOverview OverviewReader::finish(const MotionSurvey& survey) const {
  const Scene& scene = scene_;
  const std::vector<PlotSpec>& plots = scene.view.plots;
  const std::size_t runCount = scene.runs.size();
  const int frames = scene.frameCount();
  const std::vector<Trajectory>& runs = survey.runs;
  const auto &divergence = divergence_, &energy = energy_, &jacobi = jacobi_, &spread = spread_,
             &sectional = sectional_, &holonomy = holonomy_;
  MotionOverview overview;
  if (wantBox_) overview.linkageBox = box_;
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
      throw std::logic_error("OverviewReader: a plot kind without values");
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
        if (runs[r].stop() && runs[r].stop()->time <= scene.frameTime(std::min(frames - 1, videoStride_)))
          plot.earlyStops.push_back({scene.runs[r].name, runs[r].stop()->time, runs[r].stop()->reason});
      plot.emptiness = !plot.earlyStops.empty() ? PlotEmptiness::RunsStopped
                           : spec.logY                  ? PlotEmptiness::ZeroOnLogAxis
                                                        : PlotEmptiness::NothingToPlot;
    }
  }
  return overview;
}

}  // namespace sl
