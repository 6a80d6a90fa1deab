#include "frames/motion_survey.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#include "contracts/parallel_for.hpp"
#include "simulation/family.hpp"

namespace sl {
namespace {

// Frames per block: enough that the threads' hand-over is rare against the sampling, few enough that a block of
// samples of a long chain stays small.
constexpr int kBlockFrames = 64;

}  // namespace

MotionSurvey surveyMotion(const Scene& scene, const std::vector<InitialState>& starts, bool withMembers,
                          const std::function<void(const SurveyFrame&)>& read, const std::function<bool()>& cancelled) {
  const std::size_t runCount = scene.runs.size();
  MotionSurvey survey;
  std::vector<std::vector<Trajectory>> members(runCount);
  // A job is one trajectory: a run (member SIZE_MAX) or one member of its family.
  std::vector<std::pair<std::size_t, std::size_t>> jobs;
  for (std::size_t r = 0; r < runCount; ++r) {
    const RunSpec& run = scene.runs[r];
    survey.runs.emplace_back(run.chain, starts.at(r), run.config);
    survey.runs.back().setCancellation(cancelled);
    jobs.emplace_back(r, SIZE_MAX);
  }
  for (std::size_t r = 0; r < runCount && withMembers; ++r) {
    const RunSpec& run = scene.runs[r];
    if (!run.family) continue;
    members[r] = familyMembers(run.chain, starts.at(r), *run.family, run.config, cancelled);
    for (std::size_t m = 0; m < members[r].size(); ++m) jobs.emplace_back(r, m);
  }

  const int frames = scene.frameCount();
  std::vector<std::vector<std::optional<Sample>>> block(jobs.size(), std::vector<std::optional<Sample>>(kBlockFrames));
  std::vector<char> stopped(jobs.size(), false);  // char, not bool: threads write neighbours
  SurveyFrame frame;
  frame.runs.assign(runCount, nullptr);
  frame.members.resize(runCount);
  for (std::size_t r = 0; r < runCount; ++r) frame.members[r].assign(members[r].size(), nullptr);
  for (int first = 0; first < frames; first += kBlockFrames) {
    const int count = std::min(kBlockFrames, frames - first);
    parallelFor(jobs.size(), [&](std::size_t j) {
      const auto [r, m] = jobs[j];
      Trajectory& trajectory = m == SIZE_MAX ? survey.runs[r] : members[r][m];
      for (int i = 0; i < count; ++i) {
        block[j][std::size_t(i)] = stopped[j] ? std::nullopt : trajectory.sampleAt(scene.frameTime(first + i));
        stopped[j] = !block[j][std::size_t(i)];
      }
    });
    for (int i = 0; i < count; ++i) {
      frame.index = first + i;
      frame.time = scene.frameTime(frame.index);
      for (std::size_t j = 0; j < jobs.size(); ++j) {
        const auto [r, m] = jobs[j];
        const std::optional<Sample>& sample = block[j][std::size_t(i)];
        (m == SIZE_MAX ? frame.runs[r] : frame.members[r][m]) = sample ? &*sample : nullptr;
      }
      read(frame);
    }
  }
  return survey;
}

}  // namespace sl
