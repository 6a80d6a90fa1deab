#include "output/video_sink.hpp"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <poll.h>

#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "contracts/limits.hpp"
#include "output/atomic_file.hpp"
#include "output/sha256.hpp"
#include "output/temporary_file.hpp"

extern char** environ;

namespace sl {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Runs `args` (args[0] found on the PATH) with stdin from /dev/null and returns what it wrote to stdout and
// stderr, with its exit status.
std::pair<int, std::string> capture(const std::vector<std::string>& args) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 1);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 2);
  std::vector<std::string> copy = args;
  std::vector<char*> argv;
  for (auto& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int status = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  if (status != 0) {
    ::close(fds[0]);
    throw std::runtime_error("cannot start " + args[0] + ": " + std::strerror(status));
  }
  std::string text;
  char buffer[4096];
  for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    if (text.size() < 65536) text.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  int exit = 0;
  while (::waitpid(pid, &exit, 0) < 0 && errno == EINTR) {
  }
  return {WIFEXITED(exit) ? WEXITSTATUS(exit) : -1, text};
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
  const std::string hold = s.holdStartFrames > 0 || s.holdEndFrames > 0
                               ? "tpad=start=" + std::to_string(s.holdStartFrames) +
                                     ":stop=" + std::to_string(s.holdEndFrames) + ":start_mode=clone:stop_mode=clone"
                               : "";
  if (!hold.empty() && s.format != VideoFormat::Gif) add({"-vf", hold});
  switch (s.format) {
    case VideoFormat::Mp4:  // x264's constant quality: 18 is visually lossless for these flat-shaded frames
      add({"-c:v", "libx264", "-preset", "veryfast", "-crf", std::to_string(s.crf >= 0 ? s.crf : 18 + 5 * level),
           "-pix_fmt", "yuv420p", "-movflags", "+faststart"});
      break;
    case VideoFormat::Webm:  // VP9 constant quality (-b:v 0), good deadline at a speed fit for long clips
      add({"-c:v", "libvpx-vp9", "-crf", std::to_string(s.crf >= 0 ? s.crf : 30 + 6 * level), "-b:v", "0", "-deadline",
           "good", "-cpu-used", "4", "-row-mt", "1", "-pix_fmt", "yuv420p"});
      break;
    case VideoFormat::Gif: {  // one palette for the whole clip (stats of every frame), ordered dithering: no shimmer
      const int colours = 256 >> level;
      add({"-filter_complex",
           "[0:v]" + (hold.empty() ? "" : hold + ",") + "split[a][b];[a]palettegen=max_colors=" +
               std::to_string(colours) + ":stats_mode=full[p];[b][p]paletteuse=dither=bayer:bayer_scale=4",
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
  ::fcntl(pipe_, F_SETFL, ::fcntl(pipe_, F_GETFL) | O_NONBLOCK);  // ours only: ffmpeg's end blocks as usual
  writer_ = std::make_unique<WorkerPool>(1, 2);
}

VideoSink::~VideoSink() {
  abandoning_ = true;
  try {
    writer_.reset();
    closeAndWait(!finished_);
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
    writeFrame(shared->rgb.data(), shared->rgb.size());
    frames_.push_back({frameIndex, "", sha256Hex(shared->rgb), ""});
    giveBack(*shared);
  });
}

// Writes without blocking: while ffmpeg reads nothing, the wait asks for cancellation every 20 ms, says what it
// waits for after a second and gives up after the stall bound.
void VideoSink::writeFrame(const std::uint8_t* data, std::size_t size) {
  const double maxStall = settings_.maxStallSeconds;
  auto progress = Clock::now();
  bool announced = false;
  while (size > 0) {
    if (abandoning_) throw std::runtime_error("the video was abandoned");
    if (settings_.cancelled && settings_.cancelled()) throw EncodingCancelled("stopped writing " + settings_.path);
    const ssize_t n = ::write(pipe_, data, size);
    if (n > 0) {
      data += n;
      size -= static_cast<std::size_t>(n);
      progress = Clock::now();
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK)
      throw std::runtime_error(settings_.ffmpeg + " stopped reading frames for " + settings_.path + ": " +
                               std::strerror(errno));
    const double waited = secondsSince(progress);
    if (waited > maxStall)
      throw std::runtime_error("gave up after " + std::to_string(int(maxStall)) + " s: " + settings_.ffmpeg +
                               " read nothing of the frames for " + settings_.path +
                               " (stalled or hung? LINKAGE_ENCODER_WAIT sets the bound)");
    if (!announced && waited > 1.0) {
      std::cerr << "waiting for " << settings_.ffmpeg << " to read the frames for " << settings_.path << " (at most "
                << int(maxStall) << " s; LINKAGE_ENCODER_WAIT sets the bound)\n";
      announced = true;
    }
    pollfd ready{pipe_, POLLOUT, 0};
    ::poll(&ready, 1, 20);
  }
}

// Closes the pipe (end of input) and reaps ffmpeg, killing its process group first if `kill`, or once
// cancellation is asked for while it finishes.
void VideoSink::closeAndWait(bool kill) {
  if (pipe_ >= 0) ::close(pipe_);
  pipe_ = -1;
  if (pid_ < 0) return;
  bool killed = false;
  if (kill) {
    ::kill(-pid_, SIGKILL);
    killed = true;
  }
  int status = 0;
  while (true) {
    const pid_t done = ::waitpid(pid_, &status, WNOHANG);
    if (done == pid_ || (done < 0 && errno != EINTR)) break;
    if (!killed && settings_.cancelled && settings_.cancelled()) {
      ::kill(-pid_, SIGKILL);
      killed = true;
    }
    if (done == 0) ::poll(nullptr, 0, 20);
  }
  pid_ = -1;
  if (killed && !kill) throw EncodingCancelled("stopped " + settings_.ffmpeg + " writing " + settings_.path);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("ffmpeg failed writing " + settings_.path + " (exit status " +
                             std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
}

// What ffmpeg wrote must hold every frame: ffprobe counts the packets of the video stream in the temporary (a
// demux, no decoding), one per frame in each of our formats. An encoder that reports a write error but exits 0
// (a full disk) leaves fewer.
void VideoSink::verifyTemporary() const {
  std::string ffprobe = settings_.ffprobe;
  if (ffprobe.empty()) {
    const std::filesystem::path ffmpeg(settings_.ffmpeg);
    ffprobe = ffmpeg.has_parent_path() ? (ffmpeg.parent_path() / "ffprobe").string() : "ffprobe";
  }
  const std::string failure = "the video " + settings_.path + " was not replaced: ";
  std::error_code error;
  if (std::filesystem::file_size(temporary_, error) == 0 || error)
    throw std::runtime_error(failure + settings_.ffmpeg + " exited 0 but wrote nothing");
  std::pair<int, std::string> probe;
  try {
    probe = capture({ffprobe, "-v", "error", "-count_packets", "-select_streams", "v:0", "-show_entries",
                     "stream=nb_read_packets", "-of", "csv=p=0", "file:" + temporary_});
  } catch (const std::runtime_error& spawn) {
    throw std::runtime_error(failure + "cannot check what ffmpeg wrote (" + spawn.what() +
                             "; ffprobe comes with ffmpeg: apt-get install ffmpeg)");
  }
  std::string text = probe.second;
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  const std::string expected =
      std::to_string(frames_.size() + std::size_t(settings_.holdStartFrames) + std::size_t(settings_.holdEndFrames));
  if (probe.first != 0 || text != expected)
    throw std::runtime_error(failure + settings_.ffmpeg + " exited 0 but its output holds " +
                             (probe.first == 0 ? text : "no readable video") + " of " + expected +
                             " frames (a full disk?)" + (probe.first == 0 ? "" : ": " + text.substr(0, 300)));
}

void VideoSink::finish() {
  writer_->wait();
  closeAndWait(false);
  verifyTemporary();
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

}  // namespace sl
