// `linkage render SCENE.json`: frames (PNG + manifest) and/or a video. The frame range, the folder and
// the size may be overridden; --frames A:B renders a shard, --resume skips frames already complete.

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <functional>
#include <sstream>
#include <system_error>
#include <iostream>
#include <memory>
#include <optional>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/disk_space.hpp"
#include "cli/environment.hpp"
#include "cli/exit_codes.hpp"
#include "cli/forked_workers.hpp"
#include "cli/frame_range.hpp"
#include "cli/gl_choice.hpp"
#include "cli/interrupt.hpp"
#include "cli/number_options.hpp"
#include "cli/progress.hpp"
#include "cli/render_folder.hpp"
#include "cli/run_report.hpp"
#include "cli/scene_input.hpp"
#include "cli/summary.hpp"
#include "contracts/csv_format.hpp"
#include "contracts/limits.hpp"
#include "contracts/parallel_for.hpp"
#include "frames/frame_builder.hpp"
#include "output/distinct_files.hpp"
#include "output/png_encoder.hpp"
#include "output/png_sequence_sink.hpp"
#include "output/sha256.hpp"
#include "output/temporary_file.hpp"
#include "output/video_sink.hpp"
#include "render/gl_backend.hpp"
#include "render/renderer_pool.hpp"
#include "scene/output_folder.hpp"
#include "scene/scene_cost.hpp"
#include "scene/scene_overrides.hpp"

namespace sl {

namespace {

namespace fs = std::filesystem;

struct RenderArguments {
  std::vector<std::string> overrides;  // --set KEY=VALUE
  std::string scene, out, frames, time, size, videoQuality, gl;
  std::vector<std::string> videos;  // --video, repeatable
  bool png = false, noPng = false, quiet = false, resume = false, replace = false, preview = false, noClobber = false;
  int threads = 0;  // --threads; 0: the cores this process may use
  int crf = -1;     // --crf; -1: not given
  double speed = 0;     // --speed; 0: not given
  std::string quality;  // -q/--quality: a preset of size, frame rate and video quality
};

// What a render will do, after the scene's choices and the options are combined and checked.
struct RenderPlan {
  Scene scene;
  FrameRange range;
  std::string folder;
  bool png = true;
  std::vector<std::string> videos;  // every one encoded from the same drawing of each frame
  bool quiet = false, resume = false;
  // Renderers drawing frames side by side, and PNG encoders: as many as the cores the process may use (at least
  // two encoders: they overlap with the drawing even on one core), no more renderers than frames. With
  // `workerProcesses`, each renderer is a worker process of its own, the encoders shared out among them.
  int renderers = 1, encoders = 2;
  bool workerProcesses = false;
};

// Processes of their own for the renderers where each may repeat the runs' integration (every process samples
// every frame up to its own) at no more than this many work units (scene_cost.hpp) per frame: a few hundredths of
// drawing a frame. Beyond, the renderers share this process's integration as threads.
constexpr double kMaxRepeatedWorkPerFrame = 1e4;

// The folder a video goes into ("." for a bare file name).
std::string videoFolder(const std::string& video) {
  const fs::path parent = fs::path(video).parent_path();
  return parent.empty() ? "." : parent.string();
}

// -q/--quality: manim's presets (-ql 480p15, -qm 720p30, -qh 1080p60, -qk 2160p60); each differs from the scene in
// size or rate, so its frames go to a folder of their own (output.folder-WxH-Nfps).
struct QualityPreset {
  const char* name;
  ImageSize size;
  int fps;
  VideoQuality video;
};
constexpr QualityPreset kQualityPresets[] = {{"low", {854, 480}, 15, VideoQuality::Small},
                                             {"medium", {1280, 720}, 30, VideoQuality::Medium},
                                             {"high", {1920, 1080}, 60, VideoQuality::High},
                                             {"4k", {3840, 2160}, 60, VideoQuality::High}};

std::string qualityPresetWords() {
  std::string words;
  for (const QualityPreset& p : kQualityPresets)
    words += (words.empty() ? "" : ", ") + std::string(p.name) + " (" + std::to_string(p.size.width) + "x" +
             std::to_string(p.size.height) + ", " + std::to_string(p.fps) + " frames/s, " +
             std::string(traitsOf(kVideoQualities, p.video).name) + " video)";
  return words;
}

// The preset's size (unless --size), frame rate and video quality (unless --video-quality); false if unknown.
bool applyQualityPreset(const RenderArguments& args, Scene& scene) {
  if (args.quality.empty()) return true;
  for (const QualityPreset& p : kQualityPresets) {
    if (args.quality != p.name) continue;
    if (args.size.empty()) scene.output.size = p.size;
    scene.output.fps = p.fps;
    if (args.videoQuality.empty()) scene.output.videoQuality = p.video;
    return true;
  }
  return false;
}

void applySize(const RenderArguments& args, Scene& scene) {
  if (args.preview && args.size.empty()) scene.output.size = previewSize(scene.output.size);
  if (args.size.empty()) return;
  const auto [width, height] = parseImageSize(args.size);
  scene.output.size = {width, height};
}

RenderPlan planRender(const RenderArguments& args) {
  RenderPlan plan;
  plan.scene = loadSceneForCommand(args.scene, args.overrides);
  Scene& scene = plan.scene;
  // The file's own size and frame rate: read again without the overrides only when one may have changed them
  // (a piped scene can be read only once: its overrides count as its own).
  const ImageSize ownSize = scene.output.size;
  const bool outputOverridden = std::any_of(args.overrides.begin(), args.overrides.end(), [](const std::string& o) {
    return o.rfind("output", 0) == 0 || o.rfind(kUnsetPrefix + std::string("output"), 0) == 0;
  });
  const int ownFps = outputOverridden && fs::is_regular_file(args.scene) ? loadSceneForCommand(args.scene).output.fps
                                                                          : scene.output.fps;
  if (!applyQualityPreset(args, scene))
    throw CommandExit(kExitBadInput,
                      "-q/--quality: found \"" + args.quality + "\"; expected one of " + qualityPresetWords());
  applySize(args, scene);
  plan.png = args.noPng ? false : (args.png || scene.output.png);
  plan.videos = args.videos;
  if (plan.videos.empty() && !scene.output.video.empty()) plan.videos.push_back(scene.output.video);
  plan.quiet = args.quiet;
  plan.resume = args.resume;
  if (!plan.png && plan.videos.empty()) {
    throw CommandExit(kExitBadInput,
                      "nothing to write: PNG frames are off (--no-png or output.png) and no video is asked for");
  }
  if (plan.resume && !plan.videos.empty()) {
    throw CommandExit(kExitBadInput,
                      "--resume completes PNG frames; a video is always encoded whole (drop --video or --resume)");
  }
  if (plan.resume && args.replace)
    throw CommandExit(kExitBadInput, "--resume joins the render in the folder and --replace removes it: give one");
  const std::string videoPath = args.videos.empty() ? "output.video" : "--video";
  const bool needsEvenSize = std::any_of(plan.videos.begin(), plan.videos.end(), [](const std::string& video) {
    const auto format = videoFormatOfPath(video);
    return format && traits(*format).needsEvenSize;
  });
  std::vector<SceneProblem> problems =
      checkImageSize(scene.output.size, needsEvenSize, args.size.empty() ? "output" : "--size");
  for (std::size_t i = 0; i < plan.videos.size(); ++i) {
    const std::string& video = plan.videos[i];
    for (SceneProblem& problem : checkVideoPath(video, videoPath)) problems.push_back(problem);
    if (sameFile(video, args.scene))
      problems.push_back({videoPath, "is the scene file itself; an output never replaces an input"});
    for (std::size_t j = 0; j < i; ++j)
      if (fs::absolute(video).lexically_normal() == fs::absolute(plan.videos[j]).lexically_normal())
        problems.push_back({videoPath, "names " + video + " twice; expected each video once"});
  }
  if (args.crf >= 0) {
    if (args.crf > limits::kMaxVideoCrf)
      problems.push_back({"--crf", "found " + std::to_string(args.crf) + "; expected an integer from 0 to " +
                                       std::to_string(limits::kMaxVideoCrf)});
    scene.output.videoCrf = args.crf;
  }
  if (args.speed > 0) scene.output.playbackSpeed = args.speed;
  if (!args.videoQuality.empty()) {
    if (const auto quality = parseKind(kVideoQualities, args.videoQuality)) {
      scene.output.videoQuality = *quality;
    } else {
      problems.push_back({"--video-quality", "found \"" + args.videoQuality + "\"; expected high, medium or small"});
    }
  }
  plan.range = !args.time.empty()
                   ? parseTimeRange(args.time, scene.duration, scene.output.fps)
                   : parseFrameRange(args.frames.empty() ? (args.preview ? "::2" : ":") : args.frames, scene.frameCount());
  if (!args.time.empty() && args.preview && args.time.find(':') == args.time.rfind(':')) plan.range.step = 2;
  plan.folder = args.out.empty() ? renderFolderFor(scene, ownSize, ownFps, plan.range.step, args.preview, args.overrides)
                               : args.out;
  for (SceneProblem& problem : checkOutputFolder(plan.folder, args.out.empty() ? "output.folder" : "--out")) {
    problems.push_back(problem);
  }
  failOnProblems(args.scene, problems);
  if (args.noClobber) {  // a render the folder holds (its manifest), or a video of that name
    std::vector<NamedFile> outputs;
    if (plan.png) outputs.push_back({args.out.empty() ? "output.folder" : "--out", plan.folder + "/manifest.json"});
    for (const std::string& video : plan.videos) outputs.push_back({videoPath, video});
    refuseExistingOutputs("render", outputs);
  }
  const int cores = args.threads > 0 ? args.threads : static_cast<int>(defaultThreadCount());
  // A video encoder (x264) takes the cores itself: one renderer keeps up with it. PNG frames are encoded here,
  // by as many encoders as renderers.
  const int renderers = plan.videos.empty() ? std::min(cores, limits::kMaxRenderers) : 1;
  plan.renderers = std::clamp(static_cast<int>(plan.range.count()), 1, renderers);
  plan.encoders = std::max(2, std::min(cores, limits::kMaxRenderers));
  // Renderers on threads of one process take turns at llvmpipe's shading (its lock is the process's): in processes
  // of their own they do not (docs/rendering.md, "Frames drawn by several processes"). PNG frames only: a video
  // takes its frames in order from one process.
  plan.workerProcesses = plan.renderers > 1 && plan.videos.empty() && plan.range.count() >= 2 * plan.renderers &&
                         sceneWork(scene) / scene.frameCount() <= kMaxRepeatedWorkPerFrame;
  return plan;
}

// Identifies the render in its manifest, so shards and resumes only ever join the same render.
nlohmann::json manifestInfo(const RenderPlan& plan) {
  const Scene& scene = plan.scene;
  nlohmann::json info{{"scene", scene.name},
          {"sceneSha256", sha256Hex(reinterpret_cast<const std::uint8_t*>(scene.identity.data()),
                                             scene.identity.size())},
          {"width", scene.output.size.width},
          {"height", scene.output.size.height},
          {"fps", scene.output.fps},
          {"frames", scene.frameCount()}};
  // The encoder decides the files' bytes: shards and resumes of another encoder must not join.
  if (plan.png) info["png"] = PngEncoder::identity(scene.output.pngCompression);
  return info;
}

// Samples the history up to (not including) frame k, one frame at a time so that a signal is noticed even while
// a late shard walks up to its first frame; false if interrupted.
bool sampleUpTo(FrameBuilder& builder, int k) {
  for (int next = builder.lastSampledFrame() + 1; next < k && !interruptRequested(); ++next) builder.advanceTo(next);
  return !interruptRequested();
}

// Before anything is written or created: do the PNG frames still to write fit? The range's first frame is drawn
// and encoded to measure one (the render loop draws it again: a few milliseconds).
void checkSpaceForFrames(const RenderPlan& plan, RendererPool& renderers, FrameBuilder& builder) {
  if (!plan.png) return;  // x264's output size depends on the motion; a full disk shows up as ffmpeg's error
  const int first = plan.range.first;
  renderers.submit(builder.frame(first));
  const Image image = renderers.takeOldest();
  FrameSpaceNeed need{plan.folder, 0, first, PngEncoder(plan.scene.output.pngCompression).encode(image).size(),
                      image.width, image.height};
  for (int frame = first; frame < plan.range.end; frame += plan.range.step)
    need.framesToWrite += !fs::exists(fs::path(plan.folder) / frameFileName(frame));
  refuseIfFramesCannotFit(need);
}

// The frames of `range` into the sinks, in order; returns false if interrupted (the frames being drawn are still
// handed to the sinks). Tells `onFrame` of every frame drawn (true) or found complete by --resume (false). The
// builder runs on this thread, the renderers on theirs: frame k + 1 is built while frame k is drawn.
bool renderFrames(const RenderPlan& plan, const FrameRange& range, FrameManifest* pngManifest,
                  const std::vector<FrameSink*>& sinks, RendererPool& renderers, FrameBuilder& builder,
                  ImageRecycler& buffers, const std::function<void(int frame, bool drawn)>& onFrame) {
  std::deque<int> inFlight;  // the frames the renderers hold, oldest first
  auto handOver = [&] {      // the oldest frame drawn, to every sink
    Image image = renderers.takeOldest();
    const int k = inFlight.front();
    inFlight.pop_front();
    for (size_t i = 0; i + 1 < sinks.size(); ++i) sinks[i]->consume(k, image);
    sinks.back()->consume(k, std::move(image));
    onFrame(k, true);
  };
  bool finished = true;
  for (int k = range.first; k < range.end; k += range.step) {
    if (plan.resume && pngManifest && pngManifest->isFrameComplete(k)) {
      onFrame(k, false);
      continue;
    }
    // Frames before k are sampled (not rendered) for the path and plot history.
    if (!sampleUpTo(builder, k)) {
      finished = false;
      break;
    }
    if (renderers.inFlight() == renderers.capacity()) handOver();
    inFlight.push_back(k);
    renderers.submit(builder.frame(k), buffers.take());
  }
  while (!inFlight.empty()) handOver();
  return finished;
}

// Temporaries a killed render left in the output folders (its frames in flight, its video) go first.
void sweepOutputFolders(const RenderPlan& plan) {
  std::vector<std::string> folders;
  if (plan.png) folders.push_back(plan.folder);
  for (const std::string& video : plan.videos) folders.push_back(videoFolder(video));
  for (const std::string& folder : folders) {
    const std::vector<std::string> removed = removeStaleTemporaries(folder);
    if (!removed.empty() && !plan.quiet)
      std::cerr << "removed " << removed.size() << " temporary file(s) an interrupted render left in " << folder
                << "\n";
  }
}

// "601 frames of 1280x720 -> renders/default/ (PNG + manifest.json) and default.mp4".
std::string renderSummary(const RenderPlan& plan, int drawn, int skipped) {
  std::string what = std::to_string(drawn) + " frame" + (drawn == 1 ? "" : "s") + " of " +
                     std::to_string(plan.scene.output.size.width) + "x" +
                     std::to_string(plan.scene.output.size.height) + " -> ";
  if (plan.png) what += plan.folder + "/ (PNG + manifest.json)";
  for (std::size_t i = 0; i < plan.videos.size(); ++i)
    what += std::string(plan.png || i > 0 ? " and " : "") + plan.videos[i];
  if (skipped > 0) what += ", " + std::to_string(skipped) + " already complete";
  return what;
}

// What a render did, for its summary line.
struct RenderCounts {
  int drawn = 0, skipped = 0;
  std::string outcomes;  // runOutcomes up to the range's last frame
  std::string backend;   // the GL backend that drew the frames (glBackendWords)
};

// What draws this process's frames, in a manifest: the renderer's identity (what the bytes depend on: a folder of
// another's frames is refused) and its backend.
void recordRenderer(FrameManifest& manifest, const RendererPool& renderers) {
  manifest.addRenderer(rendererIdentity(renderers.glRenderer(), renderers.glVersion()), nameOf(*glBackendInUse()));
}

double lastFrameTime(const RenderPlan& plan) {
  return plan.scene.frameTime(plan.range.first + (plan.range.count() - 1) * plan.range.step);
}

// The PNG folder's manifest: a whole render takes the folder over (what it held goes first), shards and --resume
// join the render there.
std::unique_ptr<FrameManifest> openFrameManifest(const RenderPlan& plan, const nlohmann::json& info, bool whole) {
  if (!whole) refuseJoiningAnotherRender(plan.folder, info);  // naming what differs, before anything is written
  std::unique_ptr<FrameManifest> manifest;
  try {
    manifest = std::make_unique<FrameManifest>(plan.folder, info, "manifest.json", FrameManifest::Existing::merge,
                                               whole ? FrameManifest::Claim::supersede : FrameManifest::Claim::join,
                                               interruptRequested, environment().lockWaitSeconds);
  } catch (const LockWaitCancelled&) {  // a signal while another render held the folder
    stopIfInterrupted("nothing was written yet");
    throw;
  }
  if (const auto earlier = manifest->supersededInfo(); earlier && !plan.quiet) {
    std::cerr << "replacing the earlier render in " << plan.folder << " ("
              << earlier->value("scene", std::string("unknown scene")) << ", " << manifest->supersededFrames()
              << " frames removed)\n";
  }
  return manifest;
}

// Every frame drawn in this process, by plan.renderers renderers on threads.
RenderCounts renderHere(const RenderPlan& plan, const nlohmann::json& info, bool whole, FrameBuilder& builder) {
  const Scene& scene = plan.scene;
  RendererPool renderers(scene.view, scene.output.size, environment().shaderFolder, plan.renderers);
  checkSpaceForFrames(plan, renderers, builder);

  ImageRecycler buffers;  // before the sinks: they give buffers back until they are finished or destroyed
  std::unique_ptr<FrameManifest> pngManifest;
  std::vector<std::unique_ptr<FrameManifest>> videoManifests;
  std::unique_ptr<PngSequenceSink> pngSink;
  std::vector<std::unique_ptr<VideoSink>> videoSinks;
  std::vector<FrameSink*> sinks;
  // The encoders start first: if one cannot, nothing of an earlier render has been replaced yet.
  for (const std::string& video : plan.videos) {
    videoManifests.push_back(std::make_unique<FrameManifest>(
        videoFolder(video), info, fs::path(video).filename().string() + ".manifest.json",
        FrameManifest::Existing::replace, FrameManifest::Claim::join, nullptr, environment().lockWaitSeconds));
    recordRenderer(*videoManifests.back(), renderers);
    VideoSettings settings{video,
                           *videoFormatOfPath(video),
                           scene.output.videoQuality,
                           scene.output.size.width,
                           scene.output.size.height,
                           scene.output.videoFps()};
    settings.cancelled = interruptRequested;
    settings.maxStallSeconds = environment().encoderWaitSeconds;
    settings.crf = scene.output.videoCrf;
    settings.holdStartFrames = int(std::lround(scene.output.holdStart * scene.output.videoFps()));
    settings.holdEndFrames = int(std::lround(scene.output.holdEnd * scene.output.videoFps()));
    videoSinks.push_back(std::make_unique<VideoSink>(settings, *videoManifests.back()));
  }
  if (plan.png) {
    pngManifest = openFrameManifest(plan, info, whole);
    recordRenderer(*pngManifest, renderers);
    pngSink = std::make_unique<PngSequenceSink>(plan.folder, *pngManifest, plan.encoders, scene.output.pngCompression);
    sinks.push_back(pngSink.get());
  }
  for (const auto& videoSink : videoSinks) sinks.push_back(videoSink.get());
  if (!sinks.empty()) sinks.back()->recycleInto(buffers);  // the last sink gets each frame's own buffer

  RenderCounts counts;
  Progress progress(plan.range.count(), plan.quiet, "render", "frame");
  bool finished = false;
  try {
    finished = renderFrames(plan, plan.range, pngManifest.get(), sinks, renderers, builder, buffers, [&](int, bool drawn) {
      ++(drawn ? counts.drawn : counts.skipped);
      progress.update(counts.drawn + counts.skipped);
    });
  } catch (const RunCancelled&) {  // a signal in the middle of a long frame: handled like one between frames
  } catch (const EncodingCancelled&) {  // a signal while the encoder was not reading
  }
  if (pngSink) pngSink->finish();  // every frame handed over is written whole, interrupted or not
  try {
    if (finished)
      for (const auto& videoSink : videoSinks) videoSink->finish();
  } catch (const EncodingCancelled&) {  // a signal while an encoder finished its video
    finished = false;
  }
  videoSinks.clear();  // unfinished: reaps ffmpeg and removes its temporary, so the video never gets its name
  reportStops(scene, builder.runs(), plan.quiet);
  if (!finished) {
    stopIfInterrupted(plan.videos.empty()
                          ? "frames written so far are complete; rerun the same command with --resume to finish"
                          : "the unfinished video was discarded (an earlier video of that name is untouched); rerun to "
                            "encode it");
  }
  counts.outcomes = runOutcomes(scene, builder.runs(), lastFrameTime(plan));
  counts.backend = glBackendWords();
  return counts;
}

// The messages of a process drawing frames to the render (ForkedWorkers): ready to write, a frame drawn or found
// complete, what it knows of the runs at its end, an error.
enum WorkerNews : char { kReady = 'r', kDrawn = 'd', kSkipped = 's', kRunsKnown = 'k', kFailed = 'e' };

// Worker `worker` of plan.renderers: every plan.renderers-th frame of the range from its own offset, with one
// renderer rasterising on its own thread and its share of the PNG encoders; worker 0 first checks that the whole
// range fits on the disk. Its exit status is what it returns; its errors go to the parent as messages (kFailed: "code message").
int drawFramesInWorker(const RenderPlan& plan, const nlohmann::json& info, FrameBuilder& builder, int worker,
                       const WorkerChannel& channel) {
  try {
    rasteriseOnTheDrawingThread();  // the other workers use the other cores
    const FrameRange& range = plan.range;
    const FrameRange mine{range.first + worker * range.step, range.end, range.step * plan.renderers};
    RendererPool renderers(plan.scene.view, plan.scene.output.size, environment().shaderFolder, 1);
    if (!sampleUpTo(builder, std::min(mine.first, range.end))) return kExitInterrupted;
    if (worker == 0) checkSpaceForFrames(plan, renderers, builder);
    channel.send(kReady);
    if (!channel.waitForGo(interruptRequested))  // the render was refused, or stopped: nothing to write
      return interruptRequested() ? kExitInterrupted : kExitOk;
    FrameManifest manifest(plan.folder, info, "manifest.json", FrameManifest::Existing::merge,
                           FrameManifest::Claim::join, interruptRequested, environment().lockWaitSeconds);
    recordRenderer(manifest, renderers);
    ImageRecycler buffers;
    PngSequenceSink sink(plan.folder, manifest, std::max(1, plan.encoders / plan.renderers),
                         plan.scene.output.pngCompression);
    sink.recycleInto(buffers);
    bool finished = false;
    int lastDrawn = worker == 0 ? range.first - 1 : -1;  // worker 0 sampled range.first (the space check) anyway
    try {
      finished = renderFrames(plan, mine, &manifest, {&sink}, renderers, builder, buffers, [&](int frame, bool drawn) {
        if (drawn) lastDrawn = frame;
        channel.send(drawn ? kDrawn : kSkipped);
      });
    } catch (const RunCancelled&) {
    }
    sink.finish();
    // What the runs are, as far as this worker's last frame drawn: "<last drawn> <outcomes' length>\n" + outcomes +
    // the stop reports (both may hold any character a run's name holds).
    const std::string outcomes = runOutcomes(plan.scene, builder.runs(), lastFrameTime(plan));
    channel.send(kRunsKnown, std::to_string(lastDrawn) + " " + std::to_string(outcomes.size()) + "\n" + outcomes +
                                 stopReports(plan.scene, builder.runs()));
    return finished ? kExitOk : kExitInterrupted;
  } catch (const RunCancelled&) {
    return kExitInterrupted;
  } catch (const LockWaitCancelled&) {
    return kExitInterrupted;
  } catch (const std::exception& error) {
    const ExitReport report = exitReportOf(error);
    channel.send(kFailed, std::to_string(report.code) + " " + report.message);
    return report.code;
  }
}

// "was killed by Segmentation fault", "ended with status 3": a worker's exit status (128 + the signal if killed).
std::string howWorkerEnded(int status) {
  return status > 128 ? std::string("was killed by ") + ::strsignal(status - 128)
                      : "ended with status " + std::to_string(status);
}

ExitReport failureOf(const std::string& text) {
  const std::size_t space = text.find(' ');
  return {std::atoi(text.substr(0, space).c_str()), space == std::string::npos ? "" : text.substr(space + 1)};
}

// Every frame drawn by plan.renderers worker processes forked from this one (each with the builder as it is now, so the
// runs are not started again), this one collecting their news. PNG frames only. Nothing if the processes cannot be
// started (a process limit): nothing is written then.
std::optional<RenderCounts> renderInProcesses(const RenderPlan& plan, const nlohmann::json& info, bool whole,
                                              FrameBuilder& builder) {
  std::optional<ForkedWorkers> started;
  try {
    started.emplace(plan.renderers, [&](int worker, const WorkerChannel& channel) {
      return drawFramesInWorker(plan, info, builder, worker, channel);
    });
  } catch (const std::system_error&) {
    return std::nullopt;
  }
  ForkedWorkers& workers = *started;
  std::optional<ExitReport> failure;
  int ready = 0;
  // Every worker ready, or the first that failed or ended without being ready, or a signal: then the others are
  // refused (by the destructor) and nothing is written.
  while (ready < workers.count() && !failure && !interruptRequested()) {
    const auto news = workers.next(interruptRequested);
    if (!news || news->kind == ForkedWorkers::kEnded) break;
    if (news->kind == kReady) ++ready;
    if (news->kind == kFailed) failure = failureOf(news->text);
  }
  if (failure) throw CommandExit(failure->code, failure->message);  // the others are stopped, nothing was written
  stopIfInterrupted("nothing was written yet");
  if (ready < workers.count()) {
    workers.refuse();
    std::string how = "ended";
    for (int status : workers.exitStatuses())
      if (status != kExitOk) how = howWorkerEnded(status);
    throw CommandExit(kExitFailure, "linkage: a process drawing frames " + how + " before it was ready; nothing was written");
  }

  const std::unique_ptr<FrameManifest> manifest = openFrameManifest(plan, info, whole);
  workers.go();
  RenderCounts counts;
  Progress progress(plan.range.count(), plan.quiet, "render", "frame");
  int furthest = -2;  // below any worker's "last drawn" (-1: none; worker 0: at least range.first - 1)
  std::string reports;
  while (const auto news = workers.next(interruptRequested)) {
    if (news->kind == kDrawn || news->kind == kSkipped) {
      ++(news->kind == kDrawn ? counts.drawn : counts.skipped);
      progress.update(counts.drawn + counts.skipped);
    } else if (news->kind == kRunsKnown) {
      // The worker that drew the last frame drawn knows the runs as one process drawing them all would.
      const std::size_t line = news->text.find('\n');
      std::istringstream head(news->text.substr(0, line));
      int drawnUpTo = -1;
      std::size_t length = 0;
      head >> drawnUpTo >> length;
      if (drawnUpTo > furthest) {
        furthest = drawnUpTo;
        counts.outcomes = news->text.substr(line + 1, length);
        reports = news->text.substr(line + 1 + length);
      }
    } else if (news->kind == kFailed && !failure) {
      failure = failureOf(news->text);
      workers.signalAll(SIGTERM);  // the others stop after their frames in flight: the render has failed
    }
  }
  const std::vector<int> statuses = workers.exitStatuses();
  if (!plan.quiet) std::cerr << reports;
  if (failure) throw CommandExit(failure->code, failure->message);
  const char* const toFinish = "frames written so far are complete; rerun the same command with --resume to finish";
  for (int status : statuses) {  // a signal after every frame was written ends the render as done, as in renderHere
    if (status == kExitInterrupted) {
      stopIfInterrupted(toFinish);
      throw CommandExit(kExitInterrupted, std::string("linkage: a process drawing frames was stopped; ") + toFinish);
    }
    if (status != kExitOk)  // a worker that sent no error: it crashed or was killed
      throw CommandExit(kExitFailure, "linkage: a process drawing frames " + howWorkerEnded(status) + "; " + toFinish);
  }
  for (const std::string& backend : readManifestFile(manifest->path()).backends)  // the workers drew
    counts.backend += (counts.backend.empty() ? "" : ", ") + backend;
  return counts;
}

void runRender(const RenderArguments& args) {
  installInterruptHandlers();  // first: a signal during planning still ends the render cleanly
  const CommandSummary summary("render", args.quiet);
  const RenderPlan plan = planRender(args);
  chooseGlBackend(args.gl);
  const Scene& scene = plan.scene;
  const nlohmann::json info = manifestInfo(plan);
  sweepOutputFolders(plan);  // first: a killed render's leftovers must not count against the free space
  std::vector<std::string> notes;
  const std::vector<InitialState> starts = runStarts(scene, &notes);
  if (!args.quiet)
    for (const std::string& note : notes) std::cerr << "linkage render: note: " << note << "\n";
  std::optional<FrameBuilder> built;
  try {
    built.emplace(scene, starts, startRuns(scene, starts), startFamilies(scene, starts), interruptRequested);
    if (!sampleUpTo(*built, plan.range.first)) stopIfInterrupted("nothing was written yet");
  } catch (const RunCancelled&) {
    stopIfInterrupted("nothing was written yet");
  }
  // A whole render replaces what the folder held (the edit-render loop); shards and --resume only join.
  const bool whole = (args.frames.empty() && !plan.resume) || args.replace;
  std::optional<RenderCounts> counts;
  if (plan.workerProcesses) counts = renderInProcesses(plan, info, whole, *built);
  if (!counts) counts = renderHere(plan, info, whole, *built);  // (or no worker could be started): on threads
  const double seconds = summary.seconds();
  char rate[48];
  std::snprintf(rate, sizeof rate, " (%.1f frames/s, ", seconds > 0 ? counts->drawn / seconds : 0.0);
  summary.print(renderSummary(plan, counts->drawn, counts->skipped), rate + counts->backend + "); " + counts->outcomes);
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  auto args = std::make_shared<RenderArguments>();
  CLI::App* command =
      app.add_subcommand("render", "Render a scene to PNG frames (with a checksum manifest) and/or a video");
  command->add_option("scene", args->scene, "scene file (JSON, see scenes/README.md; - reads standard input)")->required();
  addSceneOverrideOption(*command, args->overrides);
  command->add_option("--out", args->out, "frame folder (default: the scene's output.folder, renders/<name>)");
  command->add_option("--frames", args->frames,
                      "half-open range A:B of frames to render (A: or :B allowed; A:B:STEP every STEP-th; K one frame), or K/N: shard K of N equal "
                      "parts (K = 1..N, as a job array numbers its tasks); shards of one animation give "
                      "byte-identical files");
  command
      ->add_option("--time", args->time,
                   "the same in scene seconds: A:B renders the frames whose time t has A <= t < B (A: through the "
                   "last frame, :B from 0; A:B:STEP every STEP-th), e.g. --time 2.5:4")
      ->excludes("--frames");
  command
      ->add_option("--video", args->videos,
                   "also encode a video with ffmpeg, its format by the extension: .mp4 (H.264), .webm (VP9), "
                   ".gif (palette-optimised), e.g. renders/default.mp4; repeatable: every video from one drawing of "
                   "each frame, e.g. --video talk.mp4 --video blog.gif")
      ->allow_extra_args(false);
  command->add_option("--video-quality", args->videoQuality, "high, medium or small (default: output.video_quality, high)");
  command
      ->add_option("--crf", args->crf,
                   "N: the constant rate factor of mp4 and webm videos instead of --video-quality's (0 lossless "
                   "to 51; default: output.video_crf)")
      ->check(CLI::NonNegativeNumber);
  command
      ->add_option("--speed", args->speed,
                   "X: the video plays X times as fast as the scene's time, every frame shown (2: a 20 s scene in "
                   "10 s; 0.5: slow motion; " +
                       shortest(limits::kMinPlaybackSpeed) + " to " + shortest(limits::kMaxPlaybackSpeed) +
                       "; default: output.playback_speed, 1)")
      ->check(finiteRange(limits::kMinPlaybackSpeed, limits::kMaxPlaybackSpeed));
  command->add_flag("--png", args->png, "write PNG frames (the default unless the scene says output.png: false)");
  command->add_flag("--no-png", args->noPng, "no PNG frames (with --video: the video only)");
  command->add_option("-q,--quality", args->quality,
                      "a preset of frame size, frame rate and video quality, as manim's: " + qualityPresetWords() +
                          "; --size and --video-quality still override. Into output.folder-WxH-Nfps");
  command->add_option("--size", args->size,
                      "override the frame size, WIDTHxHEIGHT, e.g. 640x360 (without --out: into output.folder-WxH)");
  command->add_flag("--preview", args->preview,
                    "a quick look: a quarter of the size, every second frame (unless --frames gives a step), into "
                    "output.folder-preview");
  command->add_option("--threads", args->threads,
                      "how many frames are drawn side by side, at most " + std::to_string(limits::kMaxRenderers) +
                          ": PNG frames by that many worker processes (by renderers on threads for short ranges or "
                          "costly runs; one renderer with --video). Default: the cores this process may use. The "
                          "files do not depend on it")
      ->check(CLI::Range(1, 1024));
  addGlOption(*command, args->gl);
  command->add_flag("--quiet", args->quiet, "errors only: no progress, run reports or summary line");
  addNoClobberFlag(*command, args->noClobber);
  command->add_flag("--resume", args->resume, "skip frames whose file and manifest entry are complete (PNG only)");
  command->add_flag("--replace", args->replace,
                    "with --frames: remove the render the folder holds first, as a whole render does (for golden "
                    "frames, previews)");
  command->footer(
      "Frames go to DIR/frame_00000.png ... with DIR/manifest.json (SHA-256 of each file), and the lock files\n"
      "DIR/.manifest.json.lock and .manifest.json.active (kept: they serialise concurrent shards).\n"
      "DIR is --out, or the scene's output.folder (renders/<name>) for its own size and frame rate; another size,\n"
      "frame rate or a frame step goes to output.folder-640x360, -60fps, -every5; --preview to output.folder-preview.\n"
      "A video also gets VIDEO.manifest.json beside it (the checksum of every frame encoded).\n"
      "Examples:\n"
      "  linkage render scenes/default.json\n"
      "  linkage render scenes/comparison.json --size 640x360 --video renders/comparison.mp4 --no-png\n"
      "  linkage render scenes/default.json --size 480x270 --video renders/default.gif --no-png\n"
      "  parallel linkage render scenes/default.json --quiet --frames {} ::: 0:200 200:400 400:601\n"
      "  linkage render scenes/default.json --resume      # after an interruption\n"
      "SIGINT/SIGTERM stop after the frames in flight are written; exit status 130; --resume finishes.");
  command->callback([args] { runRender(*args); });
}

}  // namespace sl
