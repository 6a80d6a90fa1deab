#pragma once
// Can the frames be written? Checked before any work, without creating anything.

#include <cstddef>
#include <string>
#include <vector>

#include "scene/scene_problems.hpp"

namespace sl {

// What no file system takes: a NUL byte (it would cut the path short), or a component longer than NAME_MAX;
// empty if the path is usable.
std::string unusablePathReason(const std::string& path);

// The folder must be a usable path (unusablePathReason), and it (or its nearest existing ancestor, if it does not
// exist yet) a directory in which a file can be created: probed with a temporary file that is removed at once.
std::vector<SceneProblem> checkOutputFolder(const std::string& folder, const std::string& jsonPath);

// A file path that can work (a CSV, an events file): a usable path naming a file, not a folder (no trailing '/'),
// whose name leaves room for the temporary beside it, in a folder where a file can be created. Links and devices
// are outputTarget's to judge.
std::vector<SceneProblem> checkOutputFile(const std::string& file, const std::string& jsonPath);

// A video path that can work: a known extension (.mp4, .webm, .gif), a file name (not a folder, no trailing
// '/') short enough to leave room for the temporary name beside it, in a folder where a file can be created.
std::vector<SceneProblem> checkVideoPath(const std::string& video, const std::string& jsonPath);

// The longest file name a frame, video or temporary of ours may have: 255 bytes (NAME_MAX) less the suffix
// of a temporary (output/temporary_file.hpp).
inline constexpr std::size_t kMaxOutputNameBytes = 200;

}  // namespace sl
