#pragma once
// The frame builder: a scene's runs sampled at the frame times k / fps, k = 0..frameCount()-1, turned
// into FrameStates one at a time (memory holds the short path history, never images).
//
// Sharding: frame(k) for any k >= the last one asked gives exactly the FrameState a full run gives for
// frame k, because every frame before k is still sampled (cheaply, without rendering) to build the path,
// trail and plot history. Nothing beyond frame k's time is integrated for the history; what must be known before the
// first frame (the plots' ranges, the linkage box, the directed camera) comes from one survey of the whole motion
// (frames/motion_survey.hpp), the same in every shard.

#include <vector>

#include "contracts/frame_state.hpp"
#include "contracts/run_config.hpp"
#include "frames/configuration_view.hpp"
#include "frames/plot_overview.hpp"
#include "frames/shared_track.hpp"
#include "scene/scene.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

class FrameBuilder {
 public:
  // runs: one Trajectory per scene run, in the scene's order, run i from starts[i] on the run's own chain.
  // families[i]: the members of run i's family (empty without one; families may be empty for none at all).
  // The ball view of 5+ rods is centred on run 0's start. `cancelled` is asked during the builder's own
  // integration (the plots' overview), which then throws RunCancelled. `videoStride`: the video's frames are every
  // videoStride-th of this scene's (a still between frame times); the plots' axes and the linkage box are the video's.
  FrameBuilder(const Scene& scene, const std::vector<InitialState>& starts, std::vector<Trajectory> runs,
               std::vector<std::vector<Trajectory>> families = {}, const std::function<bool()>& cancelled = {},
               int videoStride = 1);

  int frameCount() const { return frameCount_; }
  // Frame k; k must not be smaller than the previous call's.
  FrameState frame(int k);
  // Samples the history up to frame k without building a FrameState (cheap: shards walk in this way,
  // and callers can check for interrupts between frames).
  void advanceTo(int k);
  int lastSampledFrame() const { return sampled_; }  // -1 before the first
  const std::vector<Trajectory>& runs() const { return runs_; }

 private:
  // The histories below are shared with the frames (SharedTrack): a frame refers to them, never copies them.
  struct PathHistory {
    SharedTrack<Vec3> points;  // oldest first
    SharedTrack<double> times;
  };

  struct RunHistory {
    RunFrame frame;                  // the latest state (its path, trails and members' paths are below)
    PathHistory path;
    std::vector<SharedTrack<Vec2>> trails;
    std::vector<PathHistory> memberPaths;
    Eigen::Matrix2Xd hingesAtFrame;    // for the divergence plot; no columns after the frame showing the stop
    SharedTrack<double> energyErrors;  // one per frame while running
    SharedTrack<double> jacobiSizes;   // one per frame while running (runs with Jacobi fields; else NaN)
    SharedTrack<double> spreads;       // one per frame: the family's largest hinge distance from the run
    // One per frame while running, with a sectional plot: the smallest and largest curvature of the planes through
    // the velocity (plot_overview.hpp's curvatureThroughVelocity).
    SharedTrack<double> curvatureLow, curvatureHigh;
  };

  void surveyBeforeFirstFrame(const std::vector<InitialState>& starts, const std::function<bool()>& cancelled,
                              int videoStride);
  void sampleFrame(int k);  // advance the history to frame k (k = sampled_ + 1)
  void sampleRunAt(size_t run, double t, bool isFrameTime);
  void markStopped(std::size_t run, double t);
  void recordFrameState(std::size_t run, const Sample& sample);
  void sampleMembers(int k);
  double sampleSpacing() const;  // between consecutive path samples (after frame 0)
  double pathSampleTime(int k, int j, int substeps) const;  // every family member up to frame k, members spread over the cores
  void recordPlots(int k);
  FrameState snapshot(int k) const;

  const Scene& scene_;
  std::vector<Trajectory> runs_;
  std::vector<std::vector<Trajectory>> families_;  // [run][member]
  ConfigurationView view_;
  int frameCount_;
  int sampled_ = -1;  // the last frame sampled into the history
  std::vector<RunHistory> history_;
  SharedTrack<double> plotTimes_;
  SharedTrack<double> holonomy_;  // [frame]: the curvature the holonomy polygon's sides have swept (its plot)
  std::vector<SharedTrack<double>> divergence_;  // [run - 1][frame]: run 0 against run
  std::shared_ptr<const SphereDecoration> sphereDecoration_;  // computed once, shared by every frame
  std::string title_, shortTitle_;  // the scene's, with what the decoration found ({injectivity_radius})
  MotionOverview overview_;  // per plot: the whole animation's range, empty note; the linkage panel's box
  std::vector<Vec3> cameraDirections_;  // per frame: the directed camera (frames/directed_camera.hpp); else empty
};

// The default colour of run i (a colour-blind-safe palette), unless the scene gives one.
ColorRGB runColor(const Scene& scene, size_t run);

}  // namespace sl
