#pragma once
// Scene files: read, check everything, report every problem (scene_problems.hpp) before any work.
// What is accepted comes from the registry and the limits of contracts/ (one home for each).

#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_problems.hpp"

namespace sl {

// Throws SceneError listing every problem; the file is not touched otherwise. The file is read once (it may be
// a pipe); `overrides` are --set KEY=VALUE assignments (scene_overrides.hpp), checked like the file's own keys.
Scene loadScene(const std::string& file, const std::vector<std::string>& overrides = {});
Scene parseScene(const std::string& text, const std::string& file, const std::vector<std::string>& overrides = {});

// The checks on an output size, shared by the scene's output.width/height and the --size option; even sides
// when the video format needs them (VideoFormatTraits::needsEvenSize).
std::vector<SceneProblem> checkImageSize(ImageSize size, bool evenForVideo, const std::string& path);
// Refuses frame counts beyond limits::kMaxFrames, naming the numbers.
std::vector<SceneProblem> checkFrameCount(double duration, int fps);
// The checks that wait for the duration when the scene leaves it to its found motions (Scene::durationFromMotions):
// the frame count, fixed steps no longer than the duration, the scene's cost.
std::vector<SceneProblem> checkResolvedDuration(const Scene& scene);

}  // namespace sl
