#pragma once
// What each plot panel shows over the whole animation, known before the first frame: the y range (so the axes
// never jump), for a plot that stays empty why, for one within roundoff a line saying so; and the part of the
// plane the chains sweep (so the linkage panel fills its panel and never jumps). Read off the survey of the whole
// motion (frames/motion_survey.hpp): the values are exactly those the frames plot, and every shard reads the same.

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "contracts/frame_state.hpp"
#include "contracts/run_config.hpp"
#include "frames/motion_survey.hpp"
#include "scene/scene.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

struct PlotOverview {
  std::optional<std::array<double, 2>> valueRange;
  PlotEmptiness emptiness = PlotEmptiness::HasValues;
  std::vector<EarlyStop> earlyStops;
  std::optional<PlotFrame::RoundoffOnly> roundoff;  // PlotFrame::roundoff
};

// What the whole animation shows, known before its first frame.
struct MotionOverview {
  std::vector<PlotOverview> plots;  // one per scene.view.plots entry
  // FrameState::linkageBox: both pins and every run's hinges at every frame time (empty when the scene has no
  // linkage panel, or a family whose members the box would not hold).
  std::optional<std::array<double, 4>> linkageBox;
};

// Reads the overview off the survey (frames/motion_survey.hpp), frame by frame. A holonomy plot's values come from
// `transport`, the polygon the sphere panel draws (its sides' swept curvature). `videoStride`: the video's frames
// are every videoStride-th of the scene's, and only those are read (a still between frame times samples the motion
// that many times as densely, and its axes and box must be the video's).
class OverviewReader {
 public:
  OverviewReader(const Scene& scene, const SphereTransport* transport, int videoStride = 1);
  bool needed() const { return !scene_.view.plots.empty() || wantBox_; }  // plots, or a linkage panel to fit
  bool wantsMembers() const { return wantSpread_; }
  void read(const SurveyFrame& frame);
  MotionOverview finish(const MotionSurvey& survey) const;

 private:
  const Scene& scene_;
  const SphereTransport* transport_;
  int videoStride_;
  bool wantBox_, wantSpread_, wantSectional_;
  std::array<double, 4> box_{0, 0, 0, 0};
  // Per run, per frame: divergence from run 0 (run 0's unused), energy error, Jacobi size, the family's spread, the
  // sectional range (two per frame), the swept holonomy (run 0's only); NaN where not defined.
  std::vector<std::vector<double>> divergence_, energy_, jacobi_, spread_, sectional_, holonomy_;
};

// The sectional plot's values at a sample: the smallest and largest curvature of the planes through the velocity
// (geometry/sectional_curvature.hpp); NaN where the chain is slack, has fewer than 5 rods or the sample is at rest.
std::array<double, 2> curvatureThroughVelocity(const Chain& chain, const Sample& sample);


}  // namespace sl
