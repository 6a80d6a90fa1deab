#pragma once
// The directed camera of the sphere panel (CameraMode::Directed): one view direction per frame, planned before the
// first frame from the whole motion, so that every frame, shard, --frames range and still gets the same camera.
//
// It keeps the action in front: it follows the runs' current states (a run with a family: the family's centre) and
// turns to face each event when it happens: a run's stop, a pole passage of the chart, a seam crossing t = pi/2 + k
// pi of a run on the published formulas (or its start on the seam), a conjugate point, a family's focus, a
// connecting motion's arrival, a closed geodesic's return to its start. Per frame a
// target direction (the state, drawn towards the event nearest in time while one is due), smoothed forward and
// backward, then reframed: while the target stays within kDeadZoneDegrees of the view's centre the direction stays
// exactly the same (the renderer reuses its cached sphere then); once it leaves, the camera turns towards where the
// target will be kAheadSeconds later, never faster than kMaxDegreesPerSecond, and holds again when it gets there. The
// elevation stays within kMaxElevationDegrees, so the chart's axis keeps pointing up the picture.
//
// Only the sphere of 4 rods is directed. The glass views of 3 rods (the circle) and 5+ rods (the ball) hide nothing:
// they keep the scene's direction, still (planDirectedCamera returns no directions for them).

#include <functional>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "contracts/run_config.hpp"
#include "contracts/values.hpp"
#include "frames/configuration_view.hpp"
#include "frames/motion_survey.hpp"
#include "scene/scene.hpp"

namespace sl {

namespace directed_camera {
inline constexpr double kMaxDegreesPerSecond = 120;  // of simulated time
inline constexpr double kDeadZoneDegrees = 25;      // the target this close to the view's centre: the camera holds
inline constexpr double kAheadSeconds = 0.5;        // a turning camera heads for the target this much later
inline constexpr double kMaxElevationDegrees = 60;  // above or below the equator
inline constexpr double kLeadSeconds = 2.0;         // an event starts drawing the camera this long before it
inline constexpr double kHoldSeconds = 0.4;         // and holds it fully this long either side of it
inline constexpr double kTailSeconds = 1.0;         // then lets go over this long
inline constexpr double kSmoothingSeconds = 0.25;   // the targets' Gaussian smoothing (standard deviation)
inline constexpr double kPoleDegrees = 20;          // a pole passage: a closest approach to a chart pole within this
}  // namespace directed_camera

// Arrival: a connecting motion (initial.connect) reaches its target; Closure: a closed geodesic (initial.periodic)
// is back at its start, once per period.
enum class CameraEventKind { Stop, PolePassage, SeamCrossing, ConjugatePoint, Focus, Arrival, Closure };

std::string_view cameraEventName(CameraEventKind kind);

// Something the camera turns to face: where (a point of the view, unit length for the sphere) and when.
struct CameraEvent {
  CameraEventKind kind = CameraEventKind::Stop;
  double time = 0;
  Vec3 point;
  int run = 0;  // the scene run it belongs to
};

// The motion as the camera sees it: per frame the direction to follow (empty: nothing moving to follow, or runs in
// opposite directions), and the events.
struct CameraTargets {
  std::vector<std::optional<Vec3>> follow;  // one per frame
  std::vector<CameraEvent> events;          // in time order
};

struct RunTrack;

// Reads the camera's targets off the survey (frames/motion_survey.hpp; with the families' members), frame by frame.
class CameraReader {
 public:
  CameraReader(const Scene& scene, const ConfigurationView& view);
  ~CameraReader();
  void read(const SurveyFrame& frame);
  CameraTargets targets(const MotionSurvey& survey) const;
  std::vector<Vec3> directions(const MotionSurvey& survey) const;  // directCamera of the targets

 private:
  const Scene& scene_;
  const ConfigurationView& view_;
  std::unique_ptr<std::vector<RunTrack>> tracks_;  // per run: its point (and its members') per frame
};

// The targets of a scene of 4 rods from its own survey (for a scene's camera alone; frames share one survey).
// `cancelled` is given to the trajectories (RunCancelled comes through).
CameraTargets cameraTargets(const Scene& scene, const std::vector<InitialState>& starts, const ConfigurationView& view,
                            const std::function<bool()>& cancelled = {});

// One unit direction per frame (frames at k / fps) from the targets; `fallback` where nothing was ever followed.
std::vector<Vec3> directCamera(const CameraTargets& targets, double fps, const Vec3& fallback);

// Whether a scene has a directed camera: its camera directed, its view the sphere (4 rods), a sphere panel.
bool plansDirectedCamera(const Scene& scene, const std::vector<InitialState>& starts, const ConfigurationView& view);

// The directed camera of a scene from its own survey: empty unless plansDirectedCamera.
std::vector<Vec3> planDirectedCamera(const Scene& scene, const std::vector<InitialState>& starts,
                                     const ConfigurationView& view, const std::function<bool()>& cancelled = {});

}  // namespace sl
