#include "frames/frame_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "contracts/limits.hpp"
#include "frames/parallel_for.hpp"
#include "frames/sphere_decoration.hpp"

namespace sl {

namespace {

// When a run stopped, as far as the frame shows it: infinite while it runs (PlotSeries::stopTime).
double stopTimeSoFar(const RunFrame& run) {
  return run.stopped ? run.stopTime : std::numeric_limits<double>::infinity();
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<Vec2> hingeList(const Eigen::Matrix2Xd& hinges) {
  std::vector<Vec2> list;
  for (Eigen::Index k = 0; k < hinges.cols(); ++k) list.push_back({hinges(0, k), hinges(1, k)});
  return list;
}

// Drops points older than `window` seconds before `now` (window 0 keeps everything).
template <class T>
void fadeOut(std::vector<T>& points, std::vector<double>& times, double now, double window) {
  if (window <= 0) return;
  const auto first = std::lower_bound(times.begin(), times.end(), now - window);
  const auto count = first - times.begin();
  points.erase(points.begin(), points.begin() + count);
  times.erase(times.begin(), first);
}

// Bounds a path's memory and drawing cost whatever the duration and sampling: past kMaxPathPoints points, every
// other point of the older part goes (the newest kRecentPathPoints stay at full resolution). Depends on the
// sequence of samples only, so every shard thins alike.
template <class T>
void thinOut(std::vector<T>& points, std::vector<double>& times) {
  if (points.size() <= limits::kMaxPathPoints) return;
  const std::size_t older = points.size() - limits::kRecentPathPoints;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i < older && i % 2 == 1) continue;
    points[kept] = points[i];
    times[kept] = times[i];
    ++kept;
  }
  points.resize(kept);
  times.resize(kept);
}

// The path's point at time t (times increasing), linearly between the samples around it.
Vec3 pointAtTime(const std::vector<Vec3>& path, const std::vector<double>& times, double t) {
  const auto after = std::lower_bound(times.begin(), times.end(), t);
  if (after == times.end()) return path.back();
  const std::size_t i = static_cast<std::size_t>(after - times.begin());
  if (i == 0 || times[i] == times[i - 1]) return path[i];
  const double u = (t - times[i - 1]) / (times[i] - times[i - 1]);
  const Vec3 &a = path[i - 1], &b = path[i];
  return {a.x + u * (b.x - a.x), a.y + u * (b.y - a.y), a.z + u * (b.z - a.z)};
}

}  // namespace

ColorRGB runColor(const Scene& scene, size_t run) {
  // Okabe-Ito: distinguishable with the common colour-vision deficiencies.
  static const ColorRGB palette[] = {{0.00f, 0.45f, 0.70f}, {0.84f, 0.37f, 0.00f}, {0.00f, 0.62f, 0.45f},
                                     {0.80f, 0.47f, 0.65f}, {0.90f, 0.62f, 0.00f}, {0.34f, 0.71f, 0.91f}};
  const std::optional<ColorRGB>& chosen = scene.runs[run].color;
  return chosen ? *chosen : palette[run % std::size(palette)];
}

FrameBuilder::FrameBuilder(const Scene& scene, const std::vector<InitialState>& starts, std::vector<Trajectory> runs,
                           std::vector<std::vector<Trajectory>> families, const std::function<bool()>& cancelled)
    : scene_(scene),
      runs_(std::move(runs)),
      families_(std::move(families)),
      view_(scene.chain.rods, starts.at(0).spherePoint),  // empty for a slack chain: no sphere to draw
      frameCount_(scene.frameCount()),
      history_(runs_.size()),
      sphereDecoration_(makeSphereDecoration(scene.chain, scene.view.sphereSurface)),
      plotOverviews_(overviewPlots(scene, starts, cancelled)) {
  plotTimes_ = newSeries();
  for (size_t i = 1; i < runs_.size(); ++i) divergence_.push_back(newSeries());
  for (size_t i = 0; i < runs_.size(); ++i) {
    history_[i].energyErrors = newSeries();
    history_[i].jacobiSizes = newSeries();
    history_[i].spreads = newSeries();
    RunFrame& frame = history_[i].frame;
    frame.name = scene.runs[i].name;
    frame.method = nameOf(scene.runs[i].config.method);
    frame.color = runColor(scene, i);
    frame.baseLength = scene.runs[i].chain.baseLength;
    if (i < families_.size()) frame.members.resize(families_[i].size());
    frame.trails.resize(scene.view.trailHinges.size());
  }
}

FrameBuilder::Series FrameBuilder::newSeries() const {
  auto series = std::make_shared<std::vector<double>>();
  series->reserve(static_cast<std::size_t>(frameCount_));
  return series;
}

// Path sample j of `substeps` on the way to frame k. The last is the frame time itself, computed as k / fps so it
// is the same in every shard.
double FrameBuilder::pathSampleTime(int k, int j, int substeps) const {
  return j == substeps ? scene_.frameTime(k) : ((k - 1) * substeps + j) / double(substeps * scene_.output.fps);
}

void FrameBuilder::advanceTo(int k) {
  if (k < sampled_ || k >= frameCount_) throw std::out_of_range("FrameBuilder: frame out of order or range");
  while (sampled_ < k) sampleFrame(sampled_ + 1);
}

FrameState FrameBuilder::frame(int k) {
  advanceTo(k);
  return snapshot(k);
}

void FrameBuilder::sampleFrame(int k) {
  const int substeps = k == 0 ? 1 : scene_.view.pathSamplesPerFrame;
  for (size_t run = 0; run < runs_.size(); ++run) {
    for (int j = 1; j <= substeps; ++j) {
      sampleRunAt(run, pathSampleTime(k, j, substeps), j == substeps);
    }
  }
  sampleMembers(k);
  recordPlots(k);
  sampled_ = k;
}

// Members are sampled at the run's times, each by one thread into its own MemberFrame: the frames are the
// same however many cores there are.
void FrameBuilder::sampleMembers(int k) {
  std::vector<std::pair<std::size_t, std::size_t>> jobs;
  for (std::size_t run = 0; run < families_.size(); ++run)
    for (std::size_t m = 0; m < families_[run].size(); ++m)
      if (!history_[run].frame.members[m].stopped) jobs.emplace_back(run, m);
  const int substeps = k == 0 ? 1 : scene_.view.pathSamplesPerFrame;
  parallelFor(jobs.size(), [&](std::size_t j) {
    const auto [run, m] = jobs[j];
    MemberFrame& member = history_[run].frame.members[m];
    Trajectory& trajectory = families_[run][m];
    for (int step = 1; step <= substeps && !member.stopped; ++step) {
      const double t = pathSampleTime(k, step, substeps);
      const std::optional<Sample> sample = trajectory.sampleAt(t);
      if (!sample) {
        member.stopped = true;
        break;
      }
      member.current = view_.project(sample->spherePoint);
      member.path.push_back(member.current);
      member.pathTimes.push_back(t);
      fadeOut(member.path, member.pathTimes, t, scene_.view.pathFadeSeconds);
      thinOut(member.path, member.pathTimes);
      if (step == substeps) member.hinges = hingeList(sample->hinges);
    }
  });
}

void FrameBuilder::sampleRunAt(size_t run, double t, bool isFrameTime) {
  RunHistory& history = history_[run];
  RunFrame& frame = history.frame;
  if (frame.stopped) return;
  const std::optional<Sample> sample = runs_[run].sampleAt(t);
  if (!sample) {
    frame.stopped = true;
    const std::optional<StopInfo>& stop = runs_[run].stop();
    frame.stopTime = stop ? stop->time : t;
    if (stop) {
      frame.stopReason = nameOf(stop->reason);
      frame.stopWhy = std::string(traits(stop->reason).meaning);
      frame.stopMeasured = stop->measured;
    }
    history.hingesAtFrame.resize(2, 0);
    return;
  }
  if (sample->spherePoint.size() == 0) {  // a slack chain: no configuration sphere, the linkage alone
    if (isFrameTime) recordFrameState(history, *sample);
    return;
  }
  frame.current = view_.project(sample->spherePoint);
  frame.path.push_back(frame.current);
  frame.pathTimes.push_back(t);
  // Conjugate points up to t, placed on the path between the samples around them.
  for (const double conjugate : runs_[run].conjugateTimes()) {
    if (conjugate > t || (!frame.conjugateTimes.empty() && conjugate <= frame.conjugateTimes.back())) continue;
    frame.conjugateTimes.push_back(conjugate);
    frame.conjugatePoints.push_back(pointAtTime(frame.path, frame.pathTimes, conjugate));
  }
  fadeOut(frame.path, frame.pathTimes, t, scene_.view.pathFadeSeconds);
  thinOut(frame.path, frame.pathTimes);
  if (isFrameTime) recordFrameState(history, *sample);
}

// At a frame time: the linkage, the plots' values and the trails (one point per frame, while visible).
void FrameBuilder::recordFrameState(RunHistory& history, const Sample& sample) {
  RunFrame& frame = history.frame;
  frame.hinges = hingeList(sample.hinges);
  history.hingesAtFrame = sample.hinges;
  history.energyErrors->push_back(std::abs(sample.relativeEnergyDrift));
  history.jacobiSizes->push_back(sample.jacobi.value_or(kNaN));
  const size_t kept = static_cast<size_t>(std::ceil(scene_.view.trailFadeSeconds * scene_.output.fps)) + 1;
  for (size_t i = 0; i < scene_.view.trailHinges.size(); ++i) {
    std::vector<Vec2>& trail = frame.trails[i];
    trail.push_back(frame.hinges[static_cast<size_t>(scene_.view.trailHinges[i] - 1)]);
    if (trail.size() > kept) trail.erase(trail.begin());
  }
}

// Divergence: the largest distance between corresponding hinges of run 0 and each other run, while
// both still run. Energy error: |E - E0| / E0 per run, while it runs.
void FrameBuilder::recordPlots(int k) {
  plotTimes_->push_back(scene_.frameTime(k));
  const Eigen::Matrix2Xd& reference = history_[0].hingesAtFrame;
  for (size_t run = 1; run < runs_.size(); ++run) {
    const Eigen::Matrix2Xd& other = history_[run].hingesAtFrame;
    divergence_[run - 1]->push_back(reference.size() == 0 || other.size() == 0 ? kNaN : hingeDistance(reference, other));
  }
  for (RunHistory& history : history_) {
    if (history.energyErrors->size() < plotTimes_->size()) history.energyErrors->push_back(kNaN);
    if (history.jacobiSizes->size() < plotTimes_->size()) history.jacobiSizes->push_back(kNaN);
    // Spread: members still moving against the run, while it moves (plot_overview.cpp computes the same).
    double spread = kNaN;
    for (const MemberFrame& member : history.frame.members) {
      if (member.stopped || history.hingesAtFrame.size() == 0) continue;
      Eigen::Matrix2Xd hinges(2, static_cast<Eigen::Index>(member.hinges.size()));
      for (std::size_t j = 0; j < member.hinges.size(); ++j)
        hinges.col(static_cast<Eigen::Index>(j)) = Eigen::Vector2d(member.hinges[j].x, member.hinges[j].y);
      const double distance = hingeDistance(history.hingesAtFrame, hinges);
      spread = std::isnan(spread) ? distance : std::max(spread, distance);
    }
    history.spreads->push_back(spread);
  }
}

FrameState FrameBuilder::snapshot(int k) const {
  FrameState state;
  state.index = k;
  state.time = scene_.frameTime(k);
  state.duration = scene_.duration;
  state.title = scene_.title;
  state.rods = scene_.chain.rods;
  state.viewSpace = view_.space();
  state.sphereDecoration = sphereDecoration_;
  for (const RunHistory& history : history_) state.runs.push_back(history.frame);
  // The plots refer to the history up to this frame (one value per frame so far), never copy it.
  const std::size_t count = plotTimes_->size();
  const SharedSamples times(plotTimes_, count);
  const auto upToNow = [count](const Series& series) { return SharedSamples(series, count); };
  for (std::size_t p = 0; p < scene_.view.plots.size(); ++p) {
    const PlotSpec& spec = scene_.view.plots[p];
    PlotFrame plot;
    plot.logY = spec.logY;
    plot.timeMax = scene_.duration;
    plot.valueRange = plotOverviews_[p].valueRange;
    plot.emptyNote = plotOverviews_[p].emptyNote;
    if (spec.kind == PlotKind::Divergence) {
      plot.title = "divergence from " + scene_.runs[0].name + " (max hinge distance)";
      for (size_t run = 1; run < runs_.size(); ++run) {
        plot.series.push_back({scene_.runs[run].name, runColor(scene_, run), times, upToNow(divergence_[run - 1]), {},
                               std::min(stopTimeSoFar(history_[0].frame), stopTimeSoFar(history_[run].frame))});
      }
    } else if (spec.kind == PlotKind::Spread) {
      plot.title = "spread of the family (largest hinge distance from the run)";
      for (size_t run = 0; run < runs_.size(); ++run) {
        if (!scene_.runs[run].family) continue;
        plot.series.push_back({scene_.runs[run].name, runColor(scene_, run), times, upToNow(history_[run].spreads), {},
                               stopTimeSoFar(history_[run].frame)});
      }
    } else if (spec.kind == PlotKind::Jacobi) {
      plot.title = "Jacobi field across the motion |J_perp| (zeros: conjugate points)";
      for (size_t run = 0; run < runs_.size(); ++run) {
        if (!scene_.runs[run].config.jacobi) continue;
        plot.series.push_back({scene_.runs[run].name, runColor(scene_, run), times, upToNow(history_[run].jacobiSizes),
                               history_[run].frame.conjugateTimes, stopTimeSoFar(history_[run].frame)});
      }
    } else {
      plot.title = "relative energy error |E - E0| / E0";
      for (size_t run = 0; run < runs_.size(); ++run) {
        plot.series.push_back({scene_.runs[run].name, runColor(scene_, run), times, upToNow(history_[run].energyErrors), {},
                               stopTimeSoFar(history_[run].frame)});
      }
    }
    state.plots.push_back(std::move(plot));
  }
  return state;
}

}  // namespace sl
