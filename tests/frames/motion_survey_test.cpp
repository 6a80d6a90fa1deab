// The survey of the whole motion (frames/motion_survey.hpp): every frame in order, each run's and member's sample the
// one a fresh trajectory gives at the frame time (across the pass's blocks of frames), nothing after a stop, members
// only when asked; and the readers sharing one survey read what each reads from a survey of its own.
#include <gtest/gtest.h>

#include "frames/directed_camera.hpp"
#include "frames/motion_survey.hpp"
#include "frames/plot_overview.hpp"
#include "scene/scene_loader.hpp"
#include "simulation/family.hpp"
#include "simulation/initial_state.hpp"
#include "support/scene_files.hpp"

namespace sl {
namespace {

std::vector<InitialState> startsOf(const Scene& scene) {
  std::vector<InitialState> starts;
  for (const RunSpec& run : scene.runs) starts.push_back(initialStateFromSpec(run.chain, run.initial));
  return starts;
}

bool sameState(const Sample* surveyed, const std::optional<Sample>& fresh) {
  if (!surveyed || !fresh) return !surveyed && !fresh;
  return surveyed->time == fresh->time && surveyed->spherePoint == fresh->spherePoint &&
         surveyed->hinges == fresh->hinges && surveyed->relativeEnergyDrift == fresh->relativeEnergyDrift;
}

// A fan of 6 over 150 frames (three blocks): every run and member against its own trajectory, frame by frame.
TEST(MotionSurvey, SamplesEveryFrameAsAFreshTrajectoryDoes) {
  Scene scene = loadScene(testing::shippedScene("fan.json"));
  scene.runs[0].family->count = 6;
  scene.duration = 5;
  const std::vector<InitialState> starts = startsOf(scene);
  Trajectory run(scene.runs[0].chain, starts[0], scene.runs[0].config);
  std::vector<Trajectory> members =
      familyMembers(scene.runs[0].chain, starts[0], *scene.runs[0].family, scene.runs[0].config);
  ASSERT_EQ(members.size(), 6u);
  int next = 0;
  surveyMotion(scene, starts, true, [&](const SurveyFrame& frame) {
    ASSERT_EQ(frame.index, next++);
    EXPECT_EQ(frame.time, scene.frameTime(frame.index));
    ASSERT_EQ(frame.runs.size(), 1u);
    ASSERT_EQ(frame.members.at(0).size(), members.size());
    EXPECT_TRUE(sameState(frame.runs[0], run.sampleAt(frame.time))) << "run at frame " << frame.index;
    for (std::size_t m = 0; m < members.size(); ++m)
      EXPECT_TRUE(sameState(frame.members[0][m], members[m].sampleAt(frame.time)))
          << "member " << m << " at frame " << frame.index;
  });
  EXPECT_EQ(next, scene.frameCount());
  EXPECT_GT(next, 128);  // more than two blocks
}

// pole-passage.json's published run stops at the pole: from then on it is absent, the others go on, and the survey's
// trajectory says when it stopped. Without members asked for, no run has any.
TEST(MotionSurvey, AStoppedRunStaysAbsentAndMembersComeOnlyWhenAsked) {
  const Scene scene = loadScene(testing::shippedScene("pole-passage.json"));
  int stoppedAt = -1, frames = 0;
  const MotionSurvey survey = surveyMotion(scene, startsOf(scene), false, [&](const SurveyFrame& frame) {
    ++frames;
    for (const auto& members : frame.members) EXPECT_TRUE(members.empty());
    if (!frame.runs[0] && stoppedAt < 0) stoppedAt = frame.index;
    if (stoppedAt >= 0) {
      EXPECT_EQ(frame.runs[0], nullptr) << "frame " << frame.index;
    }
    EXPECT_NE(frame.runs[2], nullptr) << "frame " << frame.index;
  });
  EXPECT_EQ(frames, scene.frameCount());
  ASSERT_GT(stoppedAt, 0);
  ASSERT_TRUE(survey.runs[0].stop());
  EXPECT_LT(survey.runs[0].stop()->time, scene.frameTime(stoppedAt));
  EXPECT_GE(survey.runs[0].stop()->time, scene.frameTime(stoppedAt - 1));
  EXPECT_FALSE(survey.runs[2].stop());
}

// The builder's way: one survey read by both readers gives the camera a survey of its own gives (and the overview
// its plot ranges), on a scene with a family, plots and a directed camera.
TEST(MotionSurvey, ReadersSharingOneSurveyReadWhatEachReadsAlone) {
  Scene scene = loadScene(testing::shippedScene("fan.json"));
  scene.runs[0].family->count = 5;
  scene.duration = 4;
  scene.view.plots.push_back(PlotSpec{});
  scene.view.plots.back().kind = PlotKind::Spread;
  const std::vector<InitialState> starts = startsOf(scene);
  const ConfigurationView view(scene.chain.rods, starts.at(0).spherePoint);
  ASSERT_TRUE(plansDirectedCamera(scene, starts, view));
  OverviewReader overview(scene, nullptr);
  CameraReader camera(scene, view);
  ASSERT_TRUE(overview.wantsMembers());
  MotionSurvey survey = surveyMotion(scene, starts, true, [&](const SurveyFrame& frame) {
    overview.read(frame);
    camera.read(frame);
  });
  const std::vector<Vec3> shared = camera.directions(survey);
  const std::vector<Vec3> alone = planDirectedCamera(scene, starts, view);
  ASSERT_EQ(shared.size(), alone.size());
  for (std::size_t k = 0; k < alone.size(); ++k)
    EXPECT_TRUE(shared[k].x == alone[k].x && shared[k].y == alone[k].y && shared[k].z == alone[k].z) << k;
  const MotionOverview read = overview.finish(survey);
  ASSERT_EQ(read.plots.size(), 1u);
  ASSERT_TRUE(read.plots[0].valueRange);  // a fan's members spread from 0
  EXPECT_GT((*read.plots[0].valueRange)[1], 0.0);
}

}  // namespace
}  // namespace sl
