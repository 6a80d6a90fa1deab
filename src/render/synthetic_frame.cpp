#include "render/synthetic_frame.hpp"

#include <algorithm>
#include <cmath>

#include "linkage/chart.hpp"

namespace sl {
namespace {

// Chart-0 coordinates (phi, t) of run k at time s: a wobbling path round the sphere.
Eigen::Vector2d coordinates(int run, double s) {
  return {0.65 * std::sin(0.7 * s + 0.4 * run) + 0.05 * run * s, 0.9 * s + 0.25 * run};
}

Vec3 spherePoint(const Eigen::Vector2d& c, ViewSpace space) {
  const double phi = c(0), t = c(1);
  if (space == ViewSpace::Circle) return {std::cos(t), std::sin(t), 0};
  const Vec3 p{std::cos(phi) * std::cos(t), std::cos(phi) * std::sin(t), std::sin(phi)};
  if (space == ViewSpace::Sphere) return p;
  return {0.8 * p.x, 0.8 * p.y, 0.8 * p.z + 0.15 * std::sin(3 * t)};  // a stand-in for a projected path
}

const ColorRGB kColors[] = {{0.52f, 0.08f, 0.16f}, {0.11f, 0.37f, 0.62f}, {0.20f, 0.50f, 0.22f}, {0.80f, 0.45f, 0.05f}};

}  // namespace

FrameState syntheticFrame(double time, int index, const SyntheticOptions& options) {
  const Chain chain = Chain::uniform(4, 3.0);
  FrameState frame;
  frame.index = index;
  frame.time = time;
  frame.duration = options.duration;
  frame.title = "Four-rod linkage, L = 3";
  frame.viewSpace = options.viewSpace;
  const int samples = int(std::floor(time * options.samplesPerSecond));
  PlotFrame energy{"relative energy error", true, 0, options.duration, {}};
  for (int k = 0; k < options.runs; ++k) {
    RunFrame run;
    run.name = k == 0 ? "reference" : "run " + std::to_string(k + 1);
    run.method = k == 0 ? "christoffel-exact" : "ambient-rattle";
    run.color = kColors[k % 4];
    const bool stops = options.stopSecondRun && k == 1 && time >= 0.5 * options.duration;
    const double until = stops ? 0.5 * options.duration : time;
    run.stopped = stops;
    run.stopTime = stops ? until : 0;
    run.stopReason = stops ? "pole fold-back" : "";
    const int count = std::min(samples, int(std::floor(until * options.samplesPerSecond)));
    PlotSeries error{run.name, run.color, {}, {}};
    for (int i = 0; i <= count; ++i) {
      const double s = i / options.samplesPerSecond;
      run.path.push_back(spherePoint(coordinates(k, s), options.viewSpace));
      run.pathTimes.push_back(s);
      error.times.push_back(s);
      error.values.push_back(1e-13 * (1 + k * 40) * std::exp(0.9 * s) * (1.5 + std::sin(5 * s)));
    }
    const Eigen::Vector2d now = coordinates(k, until);
    run.current = spherePoint(now, options.viewSpace);
    const Eigen::Matrix2Xd hinges = hingePositions(chain, now);
    for (int j = 0; j < hinges.cols(); ++j) run.hinges.push_back({hinges(0, j), hinges(1, j)});
    std::vector<Vec2> trail;
    for (double s = std::max(0.0, until - 2.0); s <= until; s += 1.0 / 30) {
      const Eigen::Matrix2Xd past = hingePositions(chain, coordinates(k, s));
      trail.push_back({past(0, 1), past(1, 1)});
    }
    run.trails.push_back(trail);
    frame.runs.push_back(run);
    energy.series.push_back(error);
  }
  PlotFrame divergence{"divergence |p_a - p_b|", true, 0, options.duration, {}};
  PlotSeries gap{"reference vs run 2", {0.25f, 0.25f, 0.28f}, {}, {}};
  for (int i = 0; i <= samples; ++i) {
    const double s = i / options.samplesPerSecond;
    gap.times.push_back(s);
    gap.values.push_back(1e-9 * std::exp(1.6 * s));
  }
  divergence.series.push_back(gap);
  frame.plots = {divergence, energy};
  return frame;
}

}  // namespace sl
