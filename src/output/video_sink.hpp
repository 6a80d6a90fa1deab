#pragma once
// Frames piped as raw RGB into ffmpeg (mp4: H.264 yuv420p; webm: VP9 yuv420p; gif: one pass through a palette
// generated from the whole clip, with ordered dithering; all at the scene's frame rate), spawned with
// posix_spawnp (no shell, so no quoting issues with paths) in a process group of its own. A writer thread
// feeds the pipe so the caller can render the next frame meanwhile. ffmpeg writes a temporary next to the
// video (output/temporary_file.hpp); finish() renames it into place, and a sink destroyed unfinished
// removes it, so the video's name only ever holds a complete video. A video has no per-frame files, so its
// manifest (<video>.manifest.json next to it) records the pixel hashes only, after the rename.
// SIGPIPE is set to ignored while a VideoSink exists, so an ffmpeg that dies turns into an error
// message (write fails with EPIPE) instead of killing the process.
//
// ffmpeg is watched, never trusted: the pipe is written without blocking, so a stalled encoder is noticed
// (said after a second, given up after limits::kMaxEncoderStallSeconds or LINKAGE_ENCODER_WAIT) and a
// cancellation (a signal) is answered within 20 ms; an encoder that is not finished properly is killed with its
// process group. Its success is judged by what it wrote, not by its exit status alone: ffprobe (beside ffmpeg)
// must count one packet per frame in the temporary before it replaces anything.

#include <atomic>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "contracts/registry.hpp"
#include "output/frame_manifest.hpp"
#include "output/frame_sink.hpp"
#include "output/worker_pool.hpp"

namespace sl {

struct VideoSettings {
  std::string path;  // e.g. "out/animation.mp4"
  VideoFormat format = VideoFormat::Mp4;
  VideoQuality quality = VideoQuality::High;
  int width = 1280, height = 720;
  double fps = 60;
  std::string ffmpeg = "ffmpeg";  // program name or path
  std::string ffprobe = "";       // empty: "ffprobe" beside ffmpeg (the same folder, or the PATH)
  bool (*cancelled)() = nullptr;  // asked while waiting for ffmpeg; true ends the video (EncodingCancelled)
  double maxStallSeconds = limits::kMaxEncoderStallSeconds;  // ffmpeg reading nothing this long: given up
  // The first and the last frame held this many frames longer (ffmpeg's tpad, cloning them): output.hold_start and
  // output.hold_end times the frame rate.
  int holdStartFrames = 0, holdEndFrames = 0;
  int crf = -1;  // mp4 and webm: this constant rate factor instead of the quality's (output.video_crf); -1: none
};

// The video was abandoned because `cancelled` said so (a signal): nothing was replaced.
struct EncodingCancelled : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// ffmpeg's arguments for a video written to `output` (exposed for tests).
std::vector<std::string> ffmpegArguments(const VideoSettings& settings, const std::string& output);

class VideoSink : public FrameSink {
 public:
  // Throws if the size is odd (yuv420p) or ffmpeg cannot be started. `manifest` must outlive the sink.
  VideoSink(const VideoSettings& settings, FrameManifest& manifest);
  ~VideoSink() override;  // closes the pipe and reaps ffmpeg; call finish() to see errors

  void consume(int frameIndex, Image image) override;
  void finish() override;

 private:
  void writeFrame(const std::uint8_t* data, std::size_t size);
  void closeAndWait(bool kill);
  void verifyTemporary() const;
  VideoSettings settings_;
  FrameManifest& manifest_;
  int pipe_ = -1;
  int pid_ = -1;
  std::string temporary_;
  std::vector<FrameEntry> frames_;  // written by the one writer thread, read after it is drained
  bool finished_ = false;
  std::atomic<bool> abandoning_{false};  // the sink is being destroyed unfinished: the writer gives up at once
  std::unique_ptr<WorkerPool> writer_;
};

}  // namespace sl
