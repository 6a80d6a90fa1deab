#include "frames/directed_camera.hpp"

#include <algorithm>
#include <cmath>

#include "contracts/registry.hpp"
#include "contracts/vec3_algebra.hpp"
#include "simulation/trajectory.hpp"

namespace sl {
namespace {

using namespace directed_camera;

const double kPi = std::acos(-1.0);
double radians(double degrees) { return degrees * kPi / 180.0; }

// The direction of v, or empty for a vector too short (or not finite) to have one.
std::optional<Vec3> directionOf(const Vec3& v, double shortest = 1e-9) {
  const double size = length(v);
  if (!(size > shortest) || !std::isfinite(size)) return std::nullopt;
  return (1.0 / size) * v;
}

// The angle between two unit vectors, accurate near 0 and pi.
double angleBetween(const Vec3& a, const Vec3& b) { return std::atan2(length(cross(a, b)), dot(a, b)); }

// The unit vector `from` turned by `angle` towards the unit vector `to` along the great circle through both (for
// opposite vectors: through the vertical, or the x axis if `from` is vertical).
Vec3 turnTowards(const Vec3& from, const Vec3& to, double angle) {
  Vec3 across = to - dot(from, to) * from;  // in the plane of both, orthogonal to `from`
  if (!directionOf(across)) across = cross(from, std::abs(from.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0});
  const Vec3 side = *directionOf(across);
  return std::cos(angle) * from + std::sin(angle) * side;
}

// v (unit) with its elevation limited to kMaxElevationDegrees, its azimuth kept; straight up or down, the azimuth of
// `previous`.
Vec3 clampElevation(const Vec3& v, const Vec3& previous) {
  const double most = std::sin(radians(kMaxElevationDegrees));
  if (std::abs(v.z) <= most) return v;
  std::optional<Vec3> level = directionOf({v.x, v.y, 0});
  if (!level) level = directionOf({previous.x, previous.y, 0});
  if (!level) level = Vec3{1, 0, 0};
  const double out = std::cos(radians(kMaxElevationDegrees));
  return {out * level->x, out * level->y, std::copysign(most, v.z)};
}

// Zero-phase Gaussian smoothing of unit vectors (standard deviation `sigma` frames), renormalised. Where the whole
// window holds one and the same vector, that vector exactly (so a camera at rest stays bit-identical).
std::vector<Vec3> smoothed(const std::vector<Vec3>& v, double sigma) {
  const long count = long(v.size());
  const long reach = long(std::ceil(3 * sigma));
  if (reach < 1) return v;
  std::vector<double> weights;
  for (long i = -reach; i <= reach; ++i) weights.push_back(std::exp(-0.5 * double(i * i) / (sigma * sigma)));
  std::vector<Vec3> out(v.size());
  for (long k = 0; k < count; ++k) {
    Vec3 sum;
    bool constant = true;
    for (long i = -reach; i <= reach; ++i) {
      const Vec3& at = v[std::size_t(std::clamp(k + i, 0L, count - 1))];
      constant = constant && at == v[std::size_t(k)];
      sum = sum + weights[std::size_t(i + reach)] * at;
    }
    out[std::size_t(k)] = constant ? v[std::size_t(k)] : directionOf(sum).value_or(v[std::size_t(k)]);
  }
  return out;
}

// How much the event at `eventTime` draws the camera at time t: 0 outside [eventTime - lead, eventTime + tail],
// 1 within the hold, smooth in between.
double pull(double t, double eventTime) {
  const double before = eventTime - t;  // > 0: the event is still to come
  double s = 1;
  if (before > kHoldSeconds) s = (kLeadSeconds - before) / (kLeadSeconds - kHoldSeconds);
  if (-before > kHoldSeconds) s = (kTailSeconds + before) / (kTailSeconds - kHoldSeconds);
  s = std::clamp(s, 0.0, 1.0);
  return s * s * (3 - 2 * s);
}

Vec3 toVec3(const Eigen::VectorXd& x, const ConfigurationView& view) { return view.project(x); }

// A point between two frames' points, back on the sphere.
Vec3 between(const Vec3& a, const Vec3& b, double u) { return directionOf(a + u * (b - a)).value_or(a); }

}  // namespace

// One run as the camera samples it: its point per frame while it moves.
struct RunTrack {
  std::vector<std::optional<Vec3>> points;              // per frame; empty once stopped
  std::vector<std::vector<std::optional<Vec3>>> members;  // [member][frame]
};

namespace {

void addRunEvents(const Scene& scene, std::size_t r, const RunTrack& track, const Trajectory& run,
                  std::vector<CameraEvent>& events) {
  const int frames = int(track.points.size());
  const int index = int(r);
  const auto at = [&](int k) -> const std::optional<Vec3>& { return track.points[std::size_t(k)]; };
  // A stop: where it stopped, when it stopped.
  if (run.stop()) {
    int last = -1;
    for (int k = 0; k < frames && at(k); ++k) last = k;
    if (last >= 0) events.push_back({CameraEventKind::Stop, run.stop()->time, *at(last), index});
  }
  // Pole passages: closest approaches to a pole of the chart (phi = +-pi/2, the points z = +-1), for runs
  // integrated in charts (where the published methods fail and the others switch charts); a chart-free run passes
  // a pole as any other point (periodic.json: a pole passage 0.15 s before another motion closes).
  const double nearPole = std::cos(radians(kPoleDegrees));
  const MethodTraits& method = traitsOf(kMethods, scene.runs[r].config.method);
  for (int k = 0; k < frames && method.chartBased; ++k) {
    if (!at(k) || std::abs(at(k)->z) < nearPole) continue;
    const double z = std::abs(at(k)->z);
    const bool risen = k == 0 || !at(k - 1) || std::abs(at(k - 1)->z) <= z;
    const bool falls = k + 1 < frames && at(k + 1) && std::abs(at(k + 1)->z) < z;
    if (risen && falls) events.push_back({CameraEventKind::PolePassage, scene.frameTime(k), *at(k), index});
  }
  // Seam crossings t = pi/2 + k pi (the points x = 0 off the poles), where the published formulas break down: for
  // runs on them only. A start on the seam is one.
  if (method.published) {
    for (int k = 0; k < frames; ++k) {
      if (!at(k) || std::abs(at(k)->z) > nearPole) continue;
      const bool onSeam = k == 0 && std::abs(at(k)->x) < 1e-9;
      const bool crossed = k > 0 && at(k - 1) && (at(k - 1)->x < 0) != (at(k)->x < 0) &&
                           std::abs(at(k)->x) <= std::abs(at(k - 1)->x);
      const bool crossesNext = k + 1 < frames && at(k + 1) && (at(k + 1)->x < 0) != (at(k)->x < 0) &&
                               std::abs(at(k)->x) < std::abs(at(k + 1)->x);
      if (onSeam || crossed || crossesNext)
        events.push_back({CameraEventKind::SeamCrossing, scene.frameTime(k), *at(k), index});
    }
  }
  // An event at `time`, placed between the frames around it.
  const auto addAt = [&](CameraEventKind kind, double time) {
    const int k = int(std::ceil(time * scene.output.fps - 1e-9));
    if (k <= 0 || k >= frames || !at(k) || !at(k - 1)) return;
    const double u = (time - scene.frameTime(k - 1)) / (scene.frameTime(k) - scene.frameTime(k - 1));
    events.push_back({kind, time, between(*at(k - 1), *at(k), u), index});
  };
  for (const double time : run.conjugateTimes()) addAt(CameraEventKind::ConjugatePoint, time);
  // A found motion's moment: a connecting motion's arrival at its target, each return of a closed one to its start.
  const InitialSpec& initial = scene.runs[r].initial;
  if (initial.motion && initial.motion->time > 0) {
    if (initial.kind == InitialSpec::Kind::Connect) addAt(CameraEventKind::Arrival, initial.motion->time);
    if (initial.kind == InitialSpec::Kind::Periodic)
      for (double time = initial.motion->time; time <= scene.duration; time += initial.motion->time)
        addAt(CameraEventKind::Closure, time);
  }
}

// The centre of a run's family at frame k (with the run itself) and its angular radius; empty if it has none.
std::optional<std::pair<Vec3, double>> familyCentre(const RunTrack& track, int k) {
  Vec3 sum;
  int count = 0;
  const auto add = [&](const std::optional<Vec3>& p) {
    if (p) sum = sum + *p, ++count;
  };
  add(track.points[std::size_t(k)]);
  for (const auto& member : track.members) add(member[std::size_t(k)]);
  const std::optional<Vec3> centre = directionOf(sum, 0.2 * count);
  if (!centre || count < 3) return std::nullopt;
  double radius = 0;
  for (const auto& member : track.members)
    if (member[std::size_t(k)]) radius = std::max(radius, angleBetween(*centre, *member[std::size_t(k)]));
  return std::pair{*centre, radius};
}

// A family's focus: where its radius has a minimum below half the largest it had before.
void addFocusEvents(const Scene& scene, std::size_t r, const RunTrack& track, std::vector<CameraEvent>& events) {
  const int frames = int(track.points.size());
  std::vector<std::optional<std::pair<Vec3, double>>> centres;
  for (int k = 0; k < frames; ++k) centres.push_back(familyCentre(track, k));
  double widest = 0;
  for (int k = 1; k + 1 < frames; ++k) {
    const auto &before = centres[std::size_t(k - 1)], &now = centres[std::size_t(k)], &after = centres[std::size_t(k + 1)];
    if (before) widest = std::max(widest, before->second);
    if (!before || !now || !after) continue;
    if (now->second <= before->second && now->second < after->second && now->second < 0.5 * widest)
      events.push_back({CameraEventKind::Focus, scene.frameTime(k), now->first, int(r)});
  }
}

bool hasSpherePanel(const Scene& scene) {
  return scene.view.panels.empty() || std::any_of(scene.view.panels.begin(), scene.view.panels.end(),
                                                  [](const PanelSpec& p) { return p.kind == PanelKind::Sphere; });
}

}  // namespace

std::string_view cameraEventName(CameraEventKind kind) {
  switch (kind) {  // every kind, no default: the compiler names a kind left out
    case CameraEventKind::Stop: return "stop";
    case CameraEventKind::PolePassage: return "pole passage";
    case CameraEventKind::SeamCrossing: return "seam crossing";
    case CameraEventKind::ConjugatePoint: return "conjugate point";
    case CameraEventKind::Focus: return "focus";
    case CameraEventKind::Arrival: return "arrival";
    case CameraEventKind::Closure: return "closure";
  }
  return "?";
}

CameraReader::CameraReader(const Scene& scene, const ConfigurationView& view)
    : scene_(scene), view_(view), tracks_(std::make_unique<std::vector<RunTrack>>(scene.runs.size())) {}

CameraReader::~CameraReader() = default;

void CameraReader::read(const SurveyFrame& frame) {
  const auto pointOf = [&](const Sample* sample) -> std::optional<Vec3> {
    if (!sample || sample->spherePoint.size() == 0) return std::nullopt;
    return directionOf(toVec3(sample->spherePoint, view_));
  };
  for (std::size_t r = 0; r < frame.runs.size(); ++r) {
    RunTrack& track = (*tracks_)[r];
    track.points.push_back(pointOf(frame.runs[r]));
    track.members.resize(frame.members[r].size());
    for (std::size_t m = 0; m < frame.members[r].size(); ++m) track.members[m].push_back(pointOf(frame.members[r][m]));
  }
}

CameraTargets CameraReader::targets(const MotionSurvey& survey) const {
  const std::vector<RunTrack>& tracks = *tracks_;
  const int frames = scene_.frameCount();
  const std::size_t runCount = scene_.runs.size();
  const Scene& scene = scene_;
  const std::vector<Trajectory>& runs = survey.runs;
  CameraTargets targets;
  for (int k = 0; k < frames; ++k) {
    Vec3 sum;
    int moving = 0;
    for (std::size_t r = 0; r < runCount; ++r) {
      const std::optional<Vec3>& point = tracks[r].points[std::size_t(k)];
      if (!point) continue;
      const auto family = familyCentre(tracks[r], k);
      sum = sum + (family ? family->first : *point);
      ++moving;
    }
    // Runs far apart (their directions cancel): nothing one direction could follow.
    targets.follow.push_back(moving == 0 ? std::nullopt : directionOf(sum, 0.3 * moving));
  }
  for (std::size_t r = 0; r < runCount; ++r) {
    addRunEvents(scene, r, tracks[r], runs[r], targets.events);
    // A fan's or a parallel family's focus (a cloud's members start together and only spread).
    const std::optional<FamilySpec>& family = scene.runs[r].family;
    if (family && family->kind != FamilyKind::Cloud) addFocusEvents(scene, r, tracks[r], targets.events);
  }
  std::stable_sort(targets.events.begin(), targets.events.end(),
                   [](const CameraEvent& a, const CameraEvent& b) { return a.time < b.time; });
  return targets;
}

std::vector<Vec3> directCamera(const CameraTargets& targets, double fps, const Vec3& fallback) {
  const std::size_t frames = targets.follow.size();
  if (frames == 0) return {};
  const Vec3 rest = directionOf(fallback).value_or(Vec3{1, 0, 0});
  // 1. What to follow: the state, held where there is none; before the first, the first.
  std::vector<Vec3> aim(frames, rest);
  const auto first = std::find_if(targets.follow.begin(), targets.follow.end(), [](const auto& f) { return f.has_value(); });
  if (first != targets.follow.end()) aim[0] = directionOf(**first).value_or(rest);
  for (std::size_t k = 0; k < frames; ++k) {
    const std::optional<Vec3> follow = targets.follow[k] ? directionOf(*targets.follow[k]) : std::nullopt;
    if (follow) aim[k] = *follow;
    else if (k > 0) aim[k] = aim[k - 1];
  }
  // 2. Drawn towards the event nearest in time, while one is due; the elevation kept moderate.
  for (std::size_t k = 0; k < frames; ++k) {
    const double t = double(k) / fps;
    const CameraEvent* nearest = nullptr;
    for (const CameraEvent& event : targets.events)
      if (pull(t, event.time) > 0 && (!nearest || std::abs(event.time - t) < std::abs(nearest->time - t))) nearest = &event;
    if (nearest) {
      if (const auto towards = directionOf(nearest->point))
        aim[k] = turnTowards(aim[k], *towards, pull(t, nearest->time) * angleBetween(aim[k], *towards));
    }
    aim[k] = clampElevation(aim[k], k > 0 ? aim[k - 1] : rest);
  }
  // 3. Smoothed forward and backward, then reframed: the camera holds exactly still while the target stays within
  // the dead zone; once it leaves, the camera turns (bounded per frame) towards where the target will be kAheadSeconds
  // later, and holds again when it gets there.
  const std::vector<Vec3> target = smoothed(aim, kSmoothingSeconds * fps);
  const double zone = radians(kDeadZoneDegrees), step = radians(kMaxDegreesPerSecond) / fps;
  const std::size_t ahead = std::size_t(std::lround(kAheadSeconds * fps));
  std::vector<Vec3> camera(frames);
  camera[0] = clampElevation(target[0], rest);
  bool turning = false;
  for (std::size_t k = 1; k < frames; ++k) {
    turning = turning || angleBetween(camera[k - 1], target[k]) > zone;
    if (!turning) {
      camera[k] = camera[k - 1];
      continue;
    }
    const Vec3& goal = target[std::min(k + ahead, frames - 1)];
    const double off = angleBetween(camera[k - 1], goal);
    camera[k] = clampElevation(turnTowards(camera[k - 1], goal, std::min(off, step)), camera[k - 1]);
    turning = off > step;
  }
  // 4. Starts and stops eased (a short smoothing that leaves a camera at rest exactly where it is), the turn per frame
  // bounded once more (averaging directions may lengthen a step by a hair).
  std::vector<Vec3> eased = smoothed(camera, 0.5 * kSmoothingSeconds * fps);
  camera[0] = eased[0] = clampElevation(eased[0], rest);
  for (std::size_t k = 1; k < frames; ++k) {
    eased[k] = clampElevation(eased[k], camera[k - 1]);
    const double turn = angleBetween(camera[k - 1], eased[k]);
    camera[k] = turn <= step ? eased[k] : clampElevation(turnTowards(camera[k - 1], eased[k], step), camera[k - 1]);
  }
  return camera;
}

bool plansDirectedCamera(const Scene& scene, const std::vector<InitialState>& starts, const ConfigurationView& view) {
  return scene.view.camera.mode == CameraMode::Directed && view.space() == ViewSpace::Sphere && hasSpherePanel(scene) &&
         !starts.empty() && starts.front().spherePoint.size() > 0;
}

std::vector<Vec3> CameraReader::directions(const MotionSurvey& survey) const {
  return directCamera(targets(survey), scene_.output.fps, scene_.view.camera.viewDirection);
}

CameraTargets cameraTargets(const Scene& scene, const std::vector<InitialState>& starts, const ConfigurationView& view,
                            const std::function<bool()>& cancelled) {
  CameraReader reader(scene, view);
  MotionSurvey survey = surveyMotion(
      scene, starts, true, [&](const SurveyFrame& frame) { reader.read(frame); }, cancelled);
  return reader.targets(survey);
}

std::vector<Vec3> planDirectedCamera(const Scene& scene, const std::vector<InitialState>& starts,
                                     const ConfigurationView& view, const std::function<bool()>& cancelled) {
  if (!plansDirectedCamera(scene, starts, view)) return {};
  CameraReader reader(scene, view);
  const MotionSurvey survey = surveyMotion(
      scene, starts, true, [&](const SurveyFrame& frame) { reader.read(frame); }, cancelled);
  return reader.directions(survey);
}

}  // namespace sl
