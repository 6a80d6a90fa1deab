#include "output/video_sink.hpp"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "output/atomic_file.hpp"
#include "output/sha256.hpp"
#include "output/temporary_file.hpp"

extern char** environ;

namespace sl::output {
namespace {

void writeAll(int fd, const std::uint8_t* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error(std::string("ffmpeg stopped reading frames: ") + std::strerror(errno));
    data += n;
    size -= static_cast<std::size_t>(n);
  }
}

}  // namespace

// ffmpeg writes to `output`; "file:" keeps a name like "take:2.mp4" from being read as a protocol. Bit-exact
// flags keep the same frames giving the same bytes (no encoder version strings or timestamps).
std::vector<std::string> ffmpegArguments(const VideoSettings& s, const std::string& output) {
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.6g", s.fps);
  const int level = static_cast<int>(s.quality);  // 0 high, 1 medium, 2 small
  std::vector<std::string> args{s.ffmpeg,  "-hide_banner", "-loglevel", "error",    "-nostdin", "-y",
                                "-f",      "rawvideo",     "-pix_fmt",  "rgb24",    "-s",
                                std::to_string(s.width) + "x" + std::to_string(s.height),
                                "-framerate", rate,        "-i",        "pipe:0",   "-fflags", "+bitexact",
                                "-flags:v", "+bitexact"};
  const auto add = [&](std::initializer_list<std::string> more) { args.insert(args.end(), more); };
  switch (s.format) {
    case VideoFormat::Mp4:  // x264's constant quality: 18 is visually lossless for these flat-shaded frames
      add({"-c:v", "libx264", "-preset", "veryfast", "-crf", std::to_string(18 + 5 * level), "-pix_fmt", "yuv420p",
           "-movflags", "+faststart"});
      break;
    case VideoFormat::Webm:  // VP9 constant quality (-b:v 0), good deadline at a speed fit for long clips
      add({"-c:v", "libvpx-vp9", "-crf", std::to_string(30 + 6 * level), "-b:v", "0", "-deadline", "good",
           "-cpu-used", "4", "-row-mt", "1", "-pix_fmt", "yuv420p"});
      break;
    case VideoFormat::Gif: {  // one palette for the whole clip (stats of every frame), ordered dithering: no shimmer
      const int colours = 256 >> level;
      add({"-filter_complex",
           "[0:v]split[a][b];[a]palettegen=max_colors=" + std::to_string(colours) +
               ":stats_mode=full[p];[b][p]paletteuse=dither=bayer:bayer_scale=4",
           "-loop", "0"});
      break;
    }
  }
  args.push_back("file:" + output);
  return args;
}

VideoSink::VideoSink(const VideoSettings& settings, FrameManifest& manifest)
    : settings_(settings), manifest_(manifest) {
  if (traits(settings.format).needsEvenSize && (settings.width % 2 || settings.height % 2))
    throw std::invalid_argument("video size " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                                " must be even in both directions (" + std::string(traits(settings.format).name) +
                                ", yuv420p)");
  if (!(settings.fps > 0)) throw std::invalid_argument("video frame rate must be positive");
  ::signal(SIGPIPE, SIG_IGN);
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[0], 0);  // dup2 clears close-on-exec on stdin
  // A process group of its own: Ctrl-C in a terminal reaches linkage only, which then ends the video itself.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  // Beside the file the video will become: through a symbolic link that is its target's folder, so the final
  // rename never crosses file systems (the extension stays the requested one: ffmpeg reads the format off it).
  temporary_ = temporaryPathFor(outputTarget(settings.path)) + std::filesystem::path(settings.path).extension().string();
  std::vector<std::string> args = ffmpegArguments(settings, temporary_);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int status = posix_spawnp(&pid, settings.ffmpeg.c_str(), &actions, &attributes, argv.data(), environ);
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[0]);
  if (status != 0) {
    ::close(fds[1]);
    throw std::runtime_error("cannot start " + settings.ffmpeg + ": " + std::strerror(status));
  }
  pid_ = pid;
  pipe_ = fds[1];
  writer_ = std::make_unique<WorkerPool>(1, 2);
}

VideoSink::~VideoSink() {
  try {
    writer_.reset();
    closeAndWait();
  } catch (...) {
    // Reported by finish(); a destructor must not throw.
  }
  if (!finished_) ::unlink(temporary_.c_str());  // an unfinished video never reaches its final name
}

void VideoSink::consume(int frameIndex, Image image) {
  if (image.width != settings_.width || image.height != settings_.height)
    throw std::invalid_argument("frame " + std::to_string(frameIndex) + " is " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + ", the video " + std::to_string(settings_.width) + "x" +
                                std::to_string(settings_.height));
  auto shared = std::make_shared<Image>(std::move(image));
  writer_->submit([this, frameIndex, shared] {
    writeAll(pipe_, shared->rgb.data(), shared->rgb.size());
    frames_.push_back({frameIndex, "", sha256Hex(shared->rgb), ""});
  });
}

void VideoSink::closeAndWait() {
  if (pipe_ >= 0) ::close(pipe_);
  pipe_ = -1;
  if (pid_ < 0) return;
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("ffmpeg failed writing " + settings_.path + " (exit status " +
                             std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
}

void VideoSink::finish() {
  writer_->wait();
  closeAndWait();
  // The earlier video's manifest goes first: a kill between here and the flush leaves a video without a
  // manifest, never one that describes another video.
  ::unlink(manifest_.path().c_str());
  // Through a symbolic link to its target, never replacing the link (atomic_file.hpp).
  if (std::rename(temporary_.c_str(), outputTarget(settings_.path).c_str()) != 0)
    throw std::runtime_error("cannot rename the finished video into " + settings_.path + ": " + std::strerror(errno));
  finished_ = true;
  // Listed only now: a manifest never describes a video that is not in place.
  for (const FrameEntry& frame : frames_) manifest_.record(frame);
  manifest_.flush();
}

}  // namespace sl::output
