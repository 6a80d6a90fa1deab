#pragma once
// The survey: one pass over the whole motion before the first frame. Every run (and, when asked, every member of a
// run's family) is integrated once and sampled at every frame time k / fps; each frame's samples go, in frame order,
// to the readers that need the whole animation in advance (frames/plot_overview.hpp: the plots' ranges and the
// linkage box; frames/directed_camera.hpp: the camera's targets and events). Integration never depends on which
// times are asked for, so these are exactly the states the frames show, in every shard.
//
// The pass goes in blocks of frames: within a block every trajectory is sampled by one thread (runs and members side
// by side, parallel_for.hpp), then the readers see the block's frames one by one on the calling thread. The result
// does not depend on the number of cores, and memory holds one block of samples, never the whole motion.

#include <functional>
#include <vector>

#include "contracts/run_config.hpp"
#include "scene/scene.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

// One frame of the survey: the sample of each run and member at the frame time; null once it has stopped (a
// trajectory is never sampled again after its first failure).
struct SurveyFrame {
  int index = 0;
  double time = 0;
  std::vector<const Sample*> runs;                  // [run]
  std::vector<std::vector<const Sample*>> members;  // [run][member]; empty for a run without a family, or unasked
};

// The runs' trajectories after the pass (their stops and conjugate points, as far as the last frame).
struct MotionSurvey {
  std::vector<Trajectory> runs;
};

// Samples the scene's runs (and with `withMembers` their families' members) at every frame time and hands each frame
// to `read`. `cancelled` is given to the trajectories (Trajectory::setCancellation): RunCancelled comes through.
MotionSurvey surveyMotion(const Scene& scene, const std::vector<InitialState>& starts, bool withMembers,
                          const std::function<void(const SurveyFrame&)>& read,
                          const std::function<bool()>& cancelled = {});

}  // namespace sl
