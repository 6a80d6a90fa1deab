#pragma once
// Where a render goes, so that previews never touch the render of the scene's own settings:
// - the scene's own size and frame rate, every frame: its output.folder (renders/<name>), as always;
// - another size (--size), frame rate (--set output.fps) or a frame step (--frames A:B:STEP), without --out:
//   output.folder with what differs appended, renders/<name>-640x360, renders/<name>-60fps, renders/<name>-every5;
// - --preview: renders/<name>-preview (a quarter of the size, every second frame unless --frames gives a step).
// --out is always taken as given. And the check that a shard or --resume joins only the same render, naming
// what differs, before anything is written.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.hpp"

namespace sl {

// The folder for a render of `scene` (its settings as the command line left them) whose scene file says
// `ownSize` and `ownFps`, rendering every `step`-th frame. `overrides` (the --set and --unset texts): those
// outside `output` change the picture, so the render gets a folder of its own named by them,
// renders/<name>-linkage.L=3.2 (a hash of them when long), and never replaces the scene's own render.
std::string renderFolderFor(const Scene& scene, ImageSize ownSize, int ownFps, int step, bool preview,
                            const std::vector<std::string>& overrides = {});

// The preview size: a quarter of each side, even (videos need it), at least 16.
ImageSize previewSize(ImageSize size);

// If `folder`'s manifest records another render than `ours` (manifest "info": scene, sceneSha256, width, height,
// fps, frames), throws CommandExit(kExitBadInput) naming each difference and what to do instead.
void refuseJoiningAnotherRender(const std::string& folder, const nlohmann::json& ours);

}  // namespace sl
