// `linkage still SCENE.json --time T --out FILE.png`: the frame at time T, alone (papers, slides, thumbnails).
// At a frame time of the scene it is that frame of a full render, pixel for pixel: the same builder samples the
// same history up to it. Between frame times the history is sampled at a multiple of the scene's frame rate
// that has T as a frame time (path points per frame divided alike, so the path is as dense), and the state
// shown is the one at T exactly; the plots' axes and the linkage panel's box are read off the video's own frames,
// so that a still between two frames is drawn on the axes of the frames on either side.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include <CLI/CLI.hpp>
#include <stb_image_write.h>

#include "cli/commands.hpp"
#include "cli/environment.hpp"
#include "cli/exit_codes.hpp"
#include "cli/frame_range.hpp"
#include "cli/gl_choice.hpp"
#include "cli/interrupt.hpp"
#include "cli/number_options.hpp"
#include "cli/scene_input.hpp"
#include "cli/summary.hpp"
#include "contracts/csv_format.hpp"
#include "contracts/time_grid.hpp"
#include "frames/frame_builder.hpp"
#include "output/atomic_file.hpp"
#include "output/png_encoder.hpp"
#include "render/renderer.hpp"
#include "scene/output_folder.hpp"

namespace sl {

namespace {

struct StillArguments {
  std::string scene, out, size, gl;
  std::vector<std::string> overrides;
  double time = 0;
  bool transparent = false, quiet = false, noClobber = false;
};

// Without --out: beside the scene's render folder, named by the time (and the size when --size gives one):
// renders/default-t10.png, renders/default-t10-1920x1080.png.
std::string defaultStillPath(const Scene& scene, const StillArguments& args) {
  return scene.output.folder + "-t" + shortest(args.time) + (args.size.empty() ? "" : "-" + args.size) +
         (args.transparent ? "-transparent" : "") + ".png";
}

// The smallest multiple m of the scene's frame rate (m <= 1000) at which `time` is a frame time; 0 if none.
int frameRateMultiple(double time, int fps) {
  for (int m = 1; m <= 1000; ++m) {
    const double frames = time * fps * m;
    if (std::abs(frames - std::round(frames)) <= 1e-9 * std::max(1.0, frames)) return m;
  }
  return 0;
}

// Straight (not premultiplied) RGBA from the same frame drawn on black and on white: where the two agree the
// pixel is opaque, where they differ by the full range it is the background alone.
std::vector<std::uint8_t> unblend(const Image& onBlack, const Image& onWhite) {
  std::vector<std::uint8_t> rgba(size_t(onBlack.width) * onBlack.height * 4);
  for (size_t p = 0; p < size_t(onBlack.width) * onBlack.height; ++p) {
    int spread = 0;
    for (int c = 0; c < 3; ++c) spread = std::max(spread, int(onWhite.rgb[3 * p + c]) - int(onBlack.rgb[3 * p + c]));
    const int alpha = 255 - std::clamp(spread, 0, 255);
    for (int c = 0; c < 3; ++c)
      rgba[4 * p + c] =
          alpha == 0 ? 0 : static_cast<std::uint8_t>(std::min(255, (onBlack.rgb[3 * p + c] * 255 + alpha / 2) / alpha));
    rgba[4 * p + 3] = static_cast<std::uint8_t>(alpha);
  }
  return rgba;
}

void appendBytes(void* context, void* data, int size) {
  auto* bytes = static_cast<std::vector<std::uint8_t>*>(context);
  bytes->insert(bytes->end(), static_cast<std::uint8_t*>(data), static_cast<std::uint8_t*>(data) + size);
}

void runStill(StillArguments args) {
  installInterruptHandlers();
  const CommandSummary summary("still", args.quiet);
  Scene scene = loadSceneForCommand(args.scene, args.overrides);
  if (args.out.empty()) args.out = defaultStillPath(scene, args);
  if (args.noClobber) refuseExistingOutputs("still", {{"--out", args.out}});
  requireOutputsBeforeWork("still", {{"the scene", args.scene}}, {{"--out", args.out}});
  if (!args.size.empty()) {
    const auto [width, height] = parseImageSize(args.size);
    scene.output.size = {width, height};
  }
  std::vector<SceneProblem> problems = checkImageSize(scene.output.size, false, args.size.empty() ? "output" : "--size");
  if (args.out.size() < 5 || args.out.substr(args.out.size() - 4) != ".png")
    problems.push_back({"--out", "found \"" + args.out + "\"; expected a file name ending in .png"});
  char numbers[128];
  std::snprintf(numbers, sizeof numbers, "found %.10g; expected a time from 0 to the duration %.10g", args.time,
                scene.duration);
  if (args.time > scene.duration) problems.push_back({"--time", numbers});
  const int multiple = frameRateMultiple(args.time, scene.output.fps);
  if (multiple == 0)
    problems.push_back({"--time", "expected a time that is a frame time at some multiple (up to 1000) of the frame "
                                  "rate, such as a decimal with at most three places"});
  failOnProblems(args.scene, problems);
  chooseGlBackend(args.gl);
  // The history between frame times, as dense as a render's.
  scene.output.fps *= multiple;
  scene.view.pathSamplesPerFrame = std::max(1, (scene.view.pathSamplesPerFrame + multiple - 1) / multiple);
  const int frame = static_cast<int>(std::llround(args.time * scene.output.fps));

  const std::vector<InitialState> starts = runStarts(scene);
  std::optional<FrameBuilder> builder;
  FrameState state;
  try {
    builder.emplace(scene, starts, startRuns(scene, starts), startFamilies(scene, starts), interruptRequested,
                    multiple);
    for (int k = 0; k < frame && !interruptRequested(); ++k) builder->advanceTo(k);
    stopIfInterrupted("nothing was written");
    state = builder->frame(frame);
  } catch (const RunCancelled&) {
    stopIfInterrupted("nothing was written");
    throw;
  }
  std::vector<std::uint8_t> png;
  if (!args.transparent) {
    Renderer renderer(scene.view, scene.output.size, environment().shaderFolder);
    png = PngEncoder().encode(renderer.render(state));
  } else {
    ViewSettings black = scene.view, white = scene.view;
    black.background = {0, 0, 0};
    white.background = {1, 1, 1};
    const Image onBlack = Renderer(black, scene.output.size, environment().shaderFolder).render(state);
    const Image onWhite = Renderer(white, scene.output.size, environment().shaderFolder).render(state);
    const std::vector<std::uint8_t> rgba = unblend(onBlack, onWhite);
    if (!stbi_write_png_to_func(appendBytes, &png, onBlack.width, onBlack.height, 4, rgba.data(), onBlack.width * 4))
      throw CommandExit(kExitFailure, args.out + ": cannot encode the PNG");
  }
  writeFileAtomically(args.out, png);
  char time[32];
  std::snprintf(time, sizeof time, "%.10g", scene.frameTime(frame));
  summary.print("\"" + scene.name + "\" at t = " + time + ", " + std::to_string(scene.output.size.width) + "x" +
                    std::to_string(scene.output.size.height) + (args.transparent ? " (transparent)" : "") + " -> " +
                    args.out,
                " (" + glBackendWords() + "); " + runOutcomes(scene, builder->runs(), scene.frameTime(frame)));
}

}  // namespace

void addStillCommand(CLI::App& app) {
  auto args = std::make_shared<StillArguments>();
  CLI::App* command = app.add_subcommand("still", "Render the frame at one time to a PNG file");
  command->add_option("scene", args->scene, "scene file (JSON, see scenes/README.md; - reads standard input)")
      ->required();
  addSceneOverrideOption(*command, args->overrides);
  command->add_option("--time", args->time, "the time shown, from 0 to the scene's duration")
      ->required()
      ->check(finiteNonNegative());
  command->add_option("--out", args->out,
                      "the PNG file to write (written whole or not at all); default: beside the scene's render "
                      "folder, named by the time, e.g. renders/default-t10.png");
  addNoClobberFlag(*command, args->noClobber);
  command->add_option("--size", args->size, "override the frame size, WIDTHxHEIGHT, e.g. 1920x1080");
  command->add_flag("--transparent", args->transparent,
                    "a transparent background (RGBA PNG, for compositing): drawn on black and on white and unblended");
  addGlOption(*command, args->gl);
  command->add_flag("--quiet", args->quiet, "no run reports or summary line");
  command->footer(
      "At a frame time (k / fps) the still is frame k of `linkage render`, pixel for pixel.\n"
      "Examples:\n"
      "  linkage still scenes/default.json --time 10 --out default-t10.png\n"
      "  linkage still scenes/jacobi.json --time 3.3436 --size 1920x1080 --transparent --out jacobi.png");
  command->callback([args] { runStill(*args); });
}

}  // namespace sl
