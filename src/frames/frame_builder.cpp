#include "frames/frame_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "contracts/limits.hpp"
#include "linkage/chain.hpp"
#include "simulation/initial_state.hpp"
#include "contracts/parallel_for.hpp"
#include "frames/directed_camera.hpp"
#include "frames/sphere_decoration.hpp"
#include "linkage/chart.hpp"
#include "scene/title_placeholders.hpp"

namespace sl {

namespace {

// What the title's {injectivity_radius} says: the distance colouring's, when the sphere has one.
std::optional<double> injectivityRadiusOf(const std::shared_ptr<const SphereDecoration>& decoration) {
  if (!decoration || !decoration->distance) return std::nullopt;
  return decoration->distance->injectivityRadius;
}

// When a run stopped, as far as the frame shows it: infinite while it runs (PlotSeries::stopTime).
double stopTimeSoFar(const RunFrame& run) {
  return run.stopped ? run.stopTime : std::numeric_limits<double>::infinity();
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// Whether a run that could be sampled at frame time t stops by t: its last good time is t itself (up to the
// rounding of step times summed against k / fps), so the stop lies in this frame's interval ((k - 1) / fps, k / fps]
// and this frame shows it, not the next. Asking for the state just past t tries the step after it; the steps never
// depend on the times asked for (simulation/trajectory.hpp), and the next sample, `spacing` later, is still after it.
constexpr double kSameTime = 1e-9;  // relative
bool stopsBy(Trajectory& trajectory, double t, double spacing) {
  return !trajectory.reaches(t + std::min(kSameTime * std::max(1.0, std::abs(t)), 0.1 * spacing));
}

std::vector<Vec2> hingeList(const Eigen::Matrix2Xd& hinges) {
  std::vector<Vec2> list;
  for (Eigen::Index k = 0; k < hinges.cols(); ++k) list.push_back({hinges(0, k), hinges(1, k)});
  return list;
}

// Drops points older than `window` seconds before `now` (window 0 keeps everything).
template <class Path>
void fadeOut(Path& path, double now, double window) {
  if (window <= 0) return;
  const auto first = std::lower_bound(path.times.begin(), path.times.end(), now - window);
  const auto count = static_cast<std::size_t>(first - path.times.begin());
  path.points.dropOldest(count);
  path.times.dropOldest(count);
}

// Bounds a path's memory and drawing cost whatever the duration and sampling: past kMaxPathPoints points, every
// other point of the older part goes (the newest kRecentPathPoints stay at full resolution). Depends on the
// sequence of samples only, so every shard thins alike.
template <class Path>
void thinOut(Path& path) {
  const std::size_t size = path.points.size();
  if (size <= limits::kMaxPathPoints) return;
  const std::size_t older = size - limits::kRecentPathPoints;
  std::vector<Vec3> points;
  std::vector<double> times;
  for (std::size_t i = 0; i < size; ++i) {
    if (i < older && i % 2 == 1) continue;
    points.push_back(path.points[i]);
    times.push_back(path.times[i]);
  }
  path.points.assign(std::move(points));
  path.times.assign(std::move(times));
}

// The path's point at time t (times increasing), linearly between the samples around it.
template <class Path>
Vec3 pointAtTime(const Path& path, double t) {
  const auto after = std::lower_bound(path.times.begin(), path.times.end(), t);
  if (after == path.times.end()) return path.points.back();
  const std::size_t i = static_cast<std::size_t>(after - path.times.begin());
  if (i == 0 || path.times[i] == path.times[i - 1]) return path.points[i];
  const double u = (t - path.times[i - 1]) / (path.times[i] - path.times[i - 1]);
  const Vec3 &a = path.points[i - 1], &b = path.points[i];
  return {a.x + u * (b.x - a.x), a.y + u * (b.y - a.y), a.z + u * (b.z - a.z)};
}

// A push or drag start: the hinges it sets moving and their start velocities (none for other starts). A drag moves
// every hinge: the fastest ones (at least half the top speed) are marked.
std::vector<RunFrame::HingeArrow> pushArrows(const InitialSpec& initial, const InitialState& start, const Chain& chain) {
  const bool pushed = initial.kind == InitialSpec::Kind::Drag ||
                      (initial.kind == InitialSpec::Kind::Hinges && initial.hingeVelocities.size() == 0);
  if (!pushed) return {};
  Eigen::Matrix2Xd velocities = start.hingeVelocities;
  if (velocities.size() == 0 && start.spherePoint.size() > 0) velocities = hingeVelocitiesOnSphere(chain, start.spherePoint, start.sphereVelocity);
  std::vector<RunFrame::HingeArrow> arrows;
  const double top = velocities.size() > 0 ? velocities.colwise().norm().maxCoeff() : 0;
  if (!(top > 0) || !std::isfinite(top)) return {};
  for (Eigen::Index k = 0; k < velocities.cols(); ++k)
    if (velocities.col(k).norm() >= 0.5 * top)
      arrows.push_back({int(k) + 1, {velocities(0, k), velocities(1, k)}});
  return arrows;
}

// The point the sphere's distance colouring is measured from: the one the scene names (resolved by the commands),
// else the first run's start (none for a slack chain or a sphere not coloured by distance).
Eigen::VectorXd distancePoint(const Scene& scene, const std::vector<InitialState>& starts) {
  if (scene.view.sphereSurface.colorBy != SphereColoring::Distance) return {};
  if (scene.distanceFrom) {
    if (scene.distancePoint.size() == 0)
      throw std::logic_error("FrameBuilder: view.sphere.distance_from was not resolved (cli/motion_starts.hpp)");
    return scene.distancePoint;
  }
  const InitialState& start = starts.at(0);
  return start.spherePoint.size() > 0 ? start.spherePoint : spherePointFromHinges(scene.chain, start.hinges);
}

}  // namespace

ColorRGB runColor(const Scene& scene, size_t run) {
  // Okabe-Ito: distinguishable with the common colour-vision deficiencies.
  static const ColorRGB palette[] = {{0.00f, 0.45f, 0.70f}, {0.84f, 0.37f, 0.00f}, {0.00f, 0.62f, 0.45f},
                                     {0.80f, 0.47f, 0.65f}, {0.90f, 0.62f, 0.00f}, {0.34f, 0.71f, 0.91f}};
  // On a coloured sphere the runs take colours away from its map: no blue or red on the curvature map (blue-white-
  // red, where blue means K < 0), no blue, green or yellow on viridis (the bending and distance maps).
  static const ColorRGB offCurvature[] = {{0.00f, 0.62f, 0.45f}, {0.10f, 0.10f, 0.12f}, {0.90f, 0.62f, 0.00f},
                                          {0.80f, 0.47f, 0.65f}};
  // On the dark page (view.theme) the charcoal run would vanish from the panels: lavender reads on the page (4.7:1)
  // and on the map's white (3.3:1). Every default colour reads on the dark page (frame_builder_test.cpp).
  static const ColorRGB offCurvatureDark[] = {
      {0.00f, 0.62f, 0.45f}, {0.60f, 0.45f, 0.90f}, {0.90f, 0.62f, 0.00f}, {0.80f, 0.47f, 0.65f}};
  // The third is charcoal on the light page (white vanished there, and on the white cut locus), white on the dark.
  static const ColorRGB offBending[] = {
      {0.84f, 0.37f, 0.00f}, {0.80f, 0.47f, 0.65f}, {0.10f, 0.10f, 0.12f}, {0.55f, 0.10f, 0.10f}};
  static const ColorRGB offBendingDark[] = {{0.84f, 0.37f, 0.00f},
                                            {0.80f, 0.47f, 0.65f},
                                            {0.96f, 0.96f, 0.96f},
                                            {0.92f, 0.36f, 0.36f}};  // the deep red lightened for the dark page
  const std::optional<ColorRGB>& chosen = scene.runs[run].color;
  if (chosen) return *chosen;
  switch (scene.view.sphereSurface.colorBy) {
    case SphereColoring::Curvature:
      return scene.view.theme == Theme::Dark ? offCurvatureDark[run % std::size(offCurvatureDark)]
                                             : offCurvature[run % std::size(offCurvature)];
    case SphereColoring::Bending:
    case SphereColoring::Distance:
      return scene.view.theme == Theme::Dark ? offBendingDark[run % std::size(offBendingDark)]
                                             : offBending[run % std::size(offBending)];
    case SphereColoring::None: break;
  }
  return palette[run % std::size(palette)];
}

FrameBuilder::FrameBuilder(const Scene& scene, const std::vector<InitialState>& starts, std::vector<Trajectory> runs,
                           std::vector<std::vector<Trajectory>> families, const std::function<bool()>& cancelled,
                           int videoStride)
    : scene_(scene),
      runs_(std::move(runs)),
      families_(std::move(families)),
      view_(scene.chain.rods, starts.at(0).spherePoint),  // empty for a slack chain: no sphere to draw
      frameCount_(scene.frameCount()),
      history_(runs_.size()),
      divergence_(runs_.empty() ? 0 : runs_.size() - 1),
      sphereDecoration_(makeSphereDecoration(scene.chain, scene.view.sphereSurface, distancePoint(scene, starts),
                                             !scene.distanceFrom, scene.holonomyPoints)),
      title_(fillTitlePlaceholders(scene.title, scene, injectivityRadiusOf(sphereDecoration_))),
      shortTitle_(fillTitlePlaceholders(scene.shortTitle, scene, injectivityRadiusOf(sphereDecoration_))) {
  surveyBeforeFirstFrame(starts, cancelled, videoStride);
  for (size_t i = 0; i < runs_.size(); ++i) {
    RunFrame& frame = history_[i].frame;
    frame.name = scene.runs[i].name;
    frame.method = scene.runs[i].config.method;
    frame.color = runColor(scene, i);
    frame.baseLength = scene.runs[i].chain.baseLength;
    const Chain& chain = scene.runs[i].chain;
    frame.hingeMasses.assign(chain.hingeMasses.data(), chain.hingeMasses.data() + chain.hingeMasses.size());
    frame.rodMasses.assign(chain.rodMasses.data(), chain.rodMasses.data() + chain.rodMasses.size());
    frame.push = pushArrows(scene.runs[i].initial, starts.at(i), chain);
    if (i < families_.size()) frame.members.resize(families_[i].size());
    history_[i].memberPaths.resize(frame.members.size());
    history_[i].trails.resize(scene.view.trailHinges.size());
  }
}

// What must be known before the first frame, from one survey of the whole motion (frames/motion_survey.hpp) that
// both readers share: the plots' ranges and the linkage box, and the directed camera.
void FrameBuilder::surveyBeforeFirstFrame(const std::vector<InitialState>& starts,
                                          const std::function<bool()>& cancelled, int videoStride) {
  OverviewReader overview(scene_,
                          sphereDecoration_ && sphereDecoration_->transport ? &*sphereDecoration_->transport : nullptr,
                          videoStride);
  std::optional<CameraReader> camera;
  if (plansDirectedCamera(scene_, starts, view_)) camera.emplace(scene_, view_);
  if (!overview.needed() && !camera) return;
  MotionSurvey survey = surveyMotion(
      scene_, starts, overview.wantsMembers() || camera,
      [&](const SurveyFrame& frame) {
        if (overview.needed()) overview.read(frame);
        if (camera) camera->read(frame);
      },
      cancelled);
  if (overview.needed()) overview_ = overview.finish(survey);
  if (camera) cameraDirections_ = camera->directions(survey);
}

// Path sample j of `substeps` on the way to frame k. The last is the frame time itself, computed as k / fps so it
// is the same in every shard.
double FrameBuilder::pathSampleTime(int k, int j, int substeps) const {
  return j == substeps ? scene_.frameTime(k) : ((k - 1) * substeps + j) / double(substeps * scene_.output.fps);
}

double FrameBuilder::sampleSpacing() const {
  return 1.0 / (double(scene_.view.pathSamplesPerFrame) * scene_.output.fps);
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
    PathHistory& path = history_[run].memberPaths[m];
    Trajectory& trajectory = families_[run][m];
    for (int step = 1; step <= substeps && !member.stopped; ++step) {
      const double t = pathSampleTime(k, step, substeps);
      const std::optional<Sample> sample = trajectory.sampleAt(t);
      if (!sample) {
        member.stopped = true;
        break;
      }
      member.current = view_.project(sample->spherePoint);
      path.points.push_back(member.current);
      path.times.push_back(t);
      fadeOut(path, t, scene_.view.pathFadeSeconds);
      thinOut(path);
      if (step == substeps) {
        member.hinges = hingeList(sample->hinges);
        member.stopped = stopsBy(trajectory, t, sampleSpacing());  // stopped at the frame time itself: shown now
      }
    }
  });
}

// The run shown stopped from now on, with when and why (t: the first time it could not be sampled at).
void FrameBuilder::markStopped(std::size_t run, double t) {
  RunFrame& frame = history_[run].frame;
  frame.stopped = true;
  const std::optional<StopInfo>& stop = runs_[run].stop();
  frame.stopTime = stop ? stop->time : t;
  if (stop) {
    frame.stopReason = stop->reason;
    frame.stopMeasured = stop->measured;
    frame.stopLimit = stop->limit;
  }
}

void FrameBuilder::sampleRunAt(size_t run, double t, bool isFrameTime) {
  RunHistory& history = history_[run];
  RunFrame& frame = history.frame;
  if (frame.stopped) {  // the frame showing the stop kept its last good hinges; no plot values after it
    history.hingesAtFrame.resize(2, 0);
    return;
  }
  const std::optional<Sample> sample = runs_[run].sampleAt(t);
  if (!sample) {
    markStopped(run, t);
    history.hingesAtFrame.resize(2, 0);
    return;
  }
  if (sample->spherePoint.size() == 0) {  // a slack chain: no configuration sphere, the linkage alone
    if (isFrameTime) recordFrameState(run, *sample);
    return;
  }
  frame.current = view_.project(sample->spherePoint);
  history.path.points.push_back(frame.current);
  history.path.times.push_back(t);
  // Conjugate points up to t, placed on the path between the samples around them.
  for (const double conjugate : runs_[run].conjugateTimes()) {
    if (conjugate > t || (!frame.conjugateTimes.empty() && conjugate <= frame.conjugateTimes.back())) continue;
    frame.conjugateTimes.push_back(conjugate);
    frame.conjugatePoints.push_back(pointAtTime(history.path, conjugate));
  }
  fadeOut(history.path, t, scene_.view.pathFadeSeconds);
  thinOut(history.path);
  if (!isFrameTime) return;
  recordFrameState(run, *sample);
  if (stopsBy(runs_[run], t, sampleSpacing())) markStopped(run, t);  // stopped at the frame time itself: shown now
}

// At a frame time: the linkage, the plots' values and the trails (one point per frame, while visible).
void FrameBuilder::recordFrameState(std::size_t run, const Sample& sample) {
  RunHistory& history = history_[run];
  RunFrame& frame = history.frame;
  frame.hinges = hingeList(sample.hinges);
  history.hingesAtFrame = sample.hinges;
  history.energyErrors.push_back(std::abs(sample.relativeEnergyDrift));
  history.jacobiSizes.push_back(sample.jacobi.value_or(kNaN));
  if (std::any_of(scene_.view.plots.begin(), scene_.view.plots.end(),
                  [](const PlotSpec& plot) { return plot.kind == PlotKind::Sectional; })) {
    const std::array<double, 2> through = curvatureThroughVelocity(scene_.runs[run].chain, sample);
    history.curvatureLow.push_back(through[0]);
    history.curvatureHigh.push_back(through[1]);
  }
  const size_t kept = static_cast<size_t>(std::ceil(scene_.view.trailFadeSeconds * scene_.output.fps)) + 1;
  for (size_t i = 0; i < scene_.view.trailHinges.size(); ++i) {
    SharedTrack<Vec2>& trail = history.trails[i];
    trail.push_back(frame.hinges[static_cast<size_t>(scene_.view.trailHinges[i] - 1)]);
    if (trail.size() > kept) trail.dropOldest(trail.size() - kept);
  }
}

// Divergence: the largest distance between corresponding hinges of run 0 and each other run, while
// both still run. Energy error: |E - E0| / E0 per run, while it runs.
void FrameBuilder::recordPlots(int k) {
  plotTimes_.push_back(scene_.frameTime(k));
  if (sphereDecoration_ && sphereDecoration_->transport)
    holonomy_.push_back(
        sphereDecoration_->transport->sweptAt(SphereTransport::carriedFraction(scene_.frameTime(k), scene_.duration)));
  const Eigen::Matrix2Xd& reference = history_[0].hingesAtFrame;
  for (size_t run = 1; run < runs_.size(); ++run) {
    const Eigen::Matrix2Xd& other = history_[run].hingesAtFrame;
    divergence_[run - 1].push_back(reference.size() == 0 || other.size() == 0 ? kNaN : hingeDistance(reference, other));
  }
  for (RunHistory& history : history_) {
    if (history.energyErrors.size() < plotTimes_.size()) history.energyErrors.push_back(kNaN);
    if (history.jacobiSizes.size() < plotTimes_.size()) history.jacobiSizes.push_back(kNaN);
    if (history.curvatureLow.size() < plotTimes_.size()) history.curvatureLow.push_back(kNaN);
    if (history.curvatureHigh.size() < plotTimes_.size()) history.curvatureHigh.push_back(kNaN);
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
    history.spreads.push_back(spread);
  }
}

FrameState FrameBuilder::snapshot(int k) const {
  FrameState state;
  state.index = k;
  state.time = scene_.frameTime(k);
  state.duration = scene_.duration;
  state.title = title_;
  state.shortTitle = shortTitle_;
  state.rods = scene_.chain.rods;
  state.viewSpace = view_.space();
  state.sphereDecoration = sphereDecoration_;
  state.linkageBox = overview_.linkageBox;
  if (static_cast<std::size_t>(k) < cameraDirections_.size()) state.cameraDirection = cameraDirections_[std::size_t(k)];
  // Paths, trails and plots refer to the history, never copy it.
  for (const RunHistory& history : history_) {
    RunFrame run = history.frame;
    run.pushShown = run.push.empty() ? 0.0f : float(std::max(0.0, 1.0 - state.time / limits::kPushShownSeconds));
    if (run.pushShown == 0) run.push.clear();
    run.path = history.path.points.view();
    run.pathTimes = history.path.times.view();
    for (const SharedTrack<Vec2>& trail : history.trails) run.trails.push_back(trail.view());
    for (std::size_t m = 0; m < run.members.size(); ++m) {
      run.members[m].path = history.memberPaths[m].points.view();
      run.members[m].pathTimes = history.memberPaths[m].times.view();
    }
    state.runs.push_back(std::move(run));
  }
  const SharedSamples times = plotTimes_.view();
  for (std::size_t p = 0; p < scene_.view.plots.size(); ++p) {
    const PlotSpec& spec = scene_.view.plots[p];
    PlotFrame plot;
    plot.logY = spec.logY;
    plot.timeMax = scene_.duration;
    plot.valueRange = overview_.plots[p].valueRange;
    plot.kind = spec.kind;
    plot.emptiness = overview_.plots[p].emptiness;
    plot.earlyStops = overview_.plots[p].earlyStops;
    plot.roundoff = overview_.plots[p].roundoff;
    switch (spec.kind) {  // every kind, no default: the compiler names a kind left out
      case PlotKind::Divergence:
        plot.referenceRun = scene_.runs[0].name;
        for (size_t run = 1; run < runs_.size(); ++run) {
          plot.series.push_back({scene_.runs[run].name, runColor(scene_, run), times, divergence_[run - 1].view(), {},
                                 std::min(stopTimeSoFar(history_[0].frame), stopTimeSoFar(history_[run].frame))});
        }
        break;
      case PlotKind::Spread:
        for (size_t run = 0; run < runs_.size(); ++run) {
          if (!scene_.runs[run].family) continue;
          plot.series.push_back({scene_.runs[run].name, runColor(scene_, run), times, history_[run].spreads.view(), {},
                                 stopTimeSoFar(history_[run].frame)});
        }
        break;
      case PlotKind::Jacobi:
        for (size_t run = 0; run < runs_.size(); ++run) {
          if (!scene_.runs[run].config.jacobi) continue;
          plot.series.push_back({scene_.runs[run].name, runColor(scene_, run), times, history_[run].jacobiSizes.view(),
                                 history_[run].frame.conjugateTimes, stopTimeSoFar(history_[run].frame)});
        }
        break;
      case PlotKind::Sectional:
        // Each run twice: the largest curvature through its velocity in its colour, the smallest paler.
        for (size_t run = 0; run < runs_.size(); ++run) {
          const ColorRGB color = runColor(scene_, run);
          const ColorRGB pale{0.45f * color.r + 0.55f, 0.45f * color.g + 0.55f, 0.45f * color.b + 0.55f};
          plot.series.push_back({scene_.runs[run].name + ", largest", color, times, history_[run].curvatureHigh.view(),
                                 {}, stopTimeSoFar(history_[run].frame)});
          plot.series.push_back({scene_.runs[run].name + ", smallest", pale, times, history_[run].curvatureLow.view(),
                                 {}, stopTimeSoFar(history_[run].frame)});
        }
        break;
      case PlotKind::EnergyError:
        for (size_t run = 0; run < runs_.size(); ++run) {
          plot.series.push_back({scene_.runs[run].name, runColor(scene_, run), times, history_[run].energyErrors.view(),
                                 {}, stopTimeSoFar(history_[run].frame)});
        }
        break;
      case PlotKind::Holonomy:  // one line, the polygon's: known in advance, shown up to this frame
        plot.series.push_back({"\u222bK dA swept",
                               SphereTransport::kReturningColor,
                               times,
                               holonomy_.view(),
                               {},
                               std::numeric_limits<double>::infinity()});
        break;
    }
    state.plots.push_back(std::move(plot));
  }
  return state;
}

}  // namespace sl
