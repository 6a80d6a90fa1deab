// bench_render: renders synthetic frames (two runs, all four panels, anti-aliased) and reports frames
// per second of wall time and the split between render, readback, encode and write.
//
//   bench_render [--frames 600] [--size 1280x720] [--sink none|png|mp4|encode] [--out DIR]
//                [--encoders 2] [--repeat 3] [--no-aa] [--orbit] [--compression fast|small]
// --sink encode encodes and hashes each frame on the rendering thread, timing each step (CPU per frame, split).
// llvmpipe's thread count comes from the environment: LP_NUM_THREADS=2 bench_render ...
// Prints one line per repeat and the median; the machine may be shared, so compare medians and ratios.

#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fixtures/synthetic_frame.hpp"
#include "output/frame_manifest.hpp"
#include "output/png_encoder.hpp"
#include "output/png_sequence_sink.hpp"
#include "output/sha256.hpp"
#include "output/video_sink.hpp"
#include "render/renderer.hpp"

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// CPU seconds of the calling thread (encoding and hashing run on it: their CPU cost, whatever the load).
double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// CPU seconds used by this process (all threads, llvmpipe's and the encoders') and its children (ffmpeg).
double cpuSeconds() {
  double total = 0;
  for (int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
    rusage usage{};
    getrusage(who, &usage);
    total += usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  }
  return total;
}

// CPU seconds of each thread of this process, by thread id, with its name (/proc/self/task/*/stat): which core's
// time goes where. Threads that ended are not listed, so read it while the sink's workers still exist.
struct ThreadTimes {
  std::map<int, std::pair<std::string, double>> byThread;
};

ThreadTimes threadTimes() {
  ThreadTimes times;
  const double tick = 1.0 / double(sysconf(_SC_CLK_TCK));
  for (const auto& entry : std::filesystem::directory_iterator("/proc/self/task")) {
    std::ifstream in(entry.path() / "stat");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto open = text.find('('), close = text.rfind(')');
    if (open == std::string::npos || close == std::string::npos) continue;
    std::istringstream rest(text.substr(close + 2));
    std::string field;
    double utime = 0, stime = 0;
    for (int k = 3; k <= 15 && rest >> field; ++k) {  // fields 14 and 15: utime, stime
      if (k == 14) utime = std::stod(field);
      if (k == 15) stime = std::stod(field);
    }
    times.byThread[std::stoi(entry.path().filename().string())] = {text.substr(open + 1, close - open - 1),
                                                                   (utime + stime) * tick};
  }
  return times;
}

// "main 3.1, llvmpipe 1.2, encoders 2.4" (ms per frame) from two snapshots.
std::string threadSplit(const ThreadTimes& before, const ThreadTimes& after, int frames) {
  double main = 0, llvmpipe = 0, workers = 0;
  const int self = static_cast<int>(getpid());
  for (const auto& [tid, named] : after.byThread) {
    const auto earlier = before.byThread.find(tid);
    const double used = named.second - (earlier == before.byThread.end() ? 0.0 : earlier->second.second);
    (tid == self ? main : named.first.rfind("llvmpipe", 0) == 0 ? llvmpipe : workers) += used;
  }
  char text[160];
  std::snprintf(text, sizeof text, "CPU ms/frame by thread: main (build, render, readback) %.2f, llvmpipe %.2f, "
                "sink workers %.2f", 1e3 * main / frames, 1e3 * llvmpipe / frames, 1e3 * workers / frames);
  return text;
}

struct Options {
  int frames = 600, width = 1280, height = 720, encoders = 2, repeat = 3;
  std::string sink = "png", out = "/tmp/bench_render";
  bool antialias = true, orbit = false;
  sl::PngCompression compression = sl::PngCompression::Fast;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--frames")
      o.frames = std::stoi(next());
    else if (a == "--size")
      std::sscanf(next().c_str(), "%dx%d", &o.width, &o.height);
    else if (a == "--sink")
      o.sink = next();
    else if (a == "--out")
      o.out = next();
    else if (a == "--encoders")
      o.encoders = std::stoi(next());
    else if (a == "--repeat")
      o.repeat = std::stoi(next());
    else if (a == "--no-aa")
      o.antialias = false;
    else if (a == "--orbit")
      o.orbit = true;
    else if (a == "--compression")
      o.compression = next() == "small" ? sl::PngCompression::Small : sl::PngCompression::Fast;
    else {
      std::fprintf(stderr, "unknown option %s (see the comment at the top of bench_render.cpp)\n", a.c_str());
      std::exit(2);
    }
  }
  return o;
}

sl::ViewSettings settingsFor(const Options& o) {
  sl::ViewSettings s;
  s.antialias = o.antialias;
  s.pathFadeSeconds = 6;
  s.camera.orbitDegreesPerSecond = o.orbit ? 6 : 0;
  sl::PanelSpec text{sl::PanelKind::Text, std::array<double, 4>{0, 0, 1, 0.12}, 0};
  sl::PanelSpec sphere{sl::PanelKind::Sphere, std::array<double, 4>{0, 0.12, 0.5, 0.88}, 0};
  sl::PanelSpec linkage{sl::PanelKind::Linkage, std::array<double, 4>{0.5, 0.12, 0.5, 0.44}, 0};
  sl::PanelSpec plot{sl::PanelKind::Plot, std::array<double, 4>{0.5, 0.56, 0.5, 0.44}, 0};
  s.panels = {text, sphere, linkage, plot};
  s.linkageLayout = sl::LinkageLayout::SideBySide;
  return s;
}

struct Split {
  double wall = 0, render = 0, encode = 0, hash = 0, cpu = 0;
  std::string threads;
  std::size_t bytes = 0;
};

Split runOnce(const Options& o, sl::Renderer& renderer, const sl::SyntheticOptions& synthetic, double fps) {
  std::filesystem::remove_all(o.out);
  std::filesystem::create_directories(o.out);
  sl::FrameManifest manifest(o.out, {{"bench", "render"}});
  manifest.addRenderer(renderer.glRenderer(), renderer.glVersion());
  std::unique_ptr<sl::FrameSink> sink;
  if (o.sink == "png") sink = std::make_unique<sl::PngSequenceSink>(o.out, manifest, o.encoders, o.compression);
  if (o.sink == "mp4") {
    sl::VideoSettings video{o.out + "/bench.mp4", sl::VideoFormat::Mp4, sl::VideoQuality::High, o.width, o.height, fps};
    sink = std::make_unique<sl::VideoSink>(video, manifest);
  }
  sl::PngEncoder encoder(o.compression);
  Split split;
  const ThreadTimes threadsAtStart = threadTimes();
  const double cpuStart = cpuSeconds();
  const auto start = Clock::now();
  for (int k = 0; k < o.frames; ++k) {
    const sl::FrameState frame = sl::syntheticFrame(k / fps, k, synthetic);
    const auto t0 = Clock::now();
    sl::Image image = renderer.render(frame);
    split.render += seconds(Clock::now() - t0);
    if (o.sink == "encode") {  // encoding alone, on this thread: its cost per frame
      const double t1 = threadCpuSeconds();
      const std::vector<std::uint8_t> png = encoder.encode(image);
      const double t2 = threadCpuSeconds();
      split.encode += t2 - t1;
      split.bytes += png.size();
      sl::sha256Hex(png);
      split.hash += threadCpuSeconds() - t2;
    }
    if (sink) sink->consume(k, std::move(image));
  }
  if (sink) sink->finish();
  split.wall = seconds(Clock::now() - start);
  split.threads = threadSplit(threadsAtStart, threadTimes(), o.frames);
  split.cpu = cpuSeconds() - cpuStart;  // children's time counts once they are reaped (ffmpeg: at finish)
  return split;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  sl::Renderer renderer(settingsFor(o), {o.width, o.height});
  const double fps = 60;
  sl::SyntheticOptions synthetic;
  synthetic.duration = o.frames / fps;
  std::printf("renderer: %s | %s; LP_NUM_THREADS=%s\n", renderer.glRenderer().c_str(), renderer.glVersion().c_str(),
              std::getenv("LP_NUM_THREADS") ? std::getenv("LP_NUM_THREADS") : "(default)");
  std::printf("%d frames %dx%d, sink %s, %d encoder thread(s), anti-aliasing %s\n", o.frames, o.width, o.height,
              o.sink.c_str(), o.encoders, o.antialias ? "analytic" : "off");
  std::vector<double> rates;
  for (int r = 0; r < o.repeat; ++r) {
    const Split s = runOnce(o, renderer, synthetic, fps);
    rates.push_back(o.frames / s.wall);
    std::printf("  run %d: %.1f frames/s wall; render+readback %.2f ms/frame", r + 1, o.frames / s.wall,
                1e3 * s.render / o.frames);
    if (o.sink == "encode")
      std::printf(", PNG encode %.2f ms/frame (%.0f kB), file SHA-256 %.2f ms/frame", 1e3 * s.encode / o.frames,
                  1e-3 * double(s.bytes) / o.frames, 1e3 * s.hash / o.frames);
    // On a shared machine wall time varies with the load; CPU time per frame does much less, and two
    // idle cores can at best deliver 2 / (CPU seconds per frame) frames per second.
    std::printf("; CPU %.2f ms/frame (2-core bound %.0f frames/s)\n    %s\n", 1e3 * s.cpu / o.frames,
                2 * o.frames / s.cpu, s.threads.c_str());
  }
  std::sort(rates.begin(), rates.end());
  std::printf("median: %.1f frames/s\n", rates[rates.size() / 2]);
  return 0;
}
