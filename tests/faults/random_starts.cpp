// Random starts through the whole pipeline: random chains (3 to 6 rods, L anywhere in (n-2, n) and often
// within 1e-7..1e-1 of an end, random hinge and rod masses in 40% of cases), random starts (chart or drag, velocity
// components up to a size drawn log-uniformly from 1e-6 to 1e2, unit_speed or not), 1 to 3 runs each of a random
// method x integrator, a few frames each built and rendered at 160x90. Each case must be refused (a SceneError, or
// exit status 2 when the start is set up) or run to frames whose every number is finite; anything else (a crash,
// another exception or exit status, a NaN in a frame) is a failure printed with its scene. Deterministic for a seed.
//
//   random_starts --count 10000 --seed 1      (the campaign; CTest runs --count 60 --seed 7)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>

#include "cli/exit_codes.hpp"
#include "cli/scene_input.hpp"
#include "contracts/registry.hpp"
#include "frames/frame_builder.hpp"
#include "render/renderer.hpp"
#include "scene/scene_loader.hpp"

namespace {

using namespace sl;

bool finite(const Vec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }
bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The first non-finite number of a frame the renderer would draw, or "".
std::string nonFinite(const FrameState& frame) {
  for (const RunFrame& run : frame.runs) {
    for (const Vec2& h : run.hinges)
      if (!finite(h)) return run.name + ": hinge";
    for (const Vec3& p : run.path)
      if (!finite(p)) return run.name + ": path";
    if (!finite(run.current)) return run.name + ": current point";
    if (run.stopped && !std::isfinite(run.stopTime)) return run.name + ": stop time";
  }
  return "";
}

std::string numbers(std::mt19937_64& random, int count, double lo, double hi) {
  std::uniform_real_distribution<double> value(lo, hi);
  std::ostringstream out;
  out.precision(17);
  out << "[";
  for (int i = 0; i < count; ++i) out << (i ? ", " : "") << value(random);
  return out.str() + "]";
}

std::string randomScene(std::mt19937_64& random) {
  std::uniform_real_distribution<double> unit(0, 1);
  const int rods = std::vector<int>{3, 4, 4, 4, 5, 6}[random() % 6];
  // L anywhere in (n-2, n), often within 1e-6 of an end.
  const double u = unit(random);
  const double edge = std::pow(10.0, -1 - 6 * unit(random));
  const double L = u < 0.2 ? rods - 2 + edge : u < 0.4 ? rods - edge : rods - 2 + 2 * unit(random);
  std::ostringstream scene;
  scene.precision(17);
  scene << R"({"name": "random", "linkage": {"rods": )" << rods << ", \"L\": " << L;
  if (unit(random) < 0.4) {
    scene << ", \"hinge_masses\": " << numbers(random, rods - 1, 0.01, 3)
          << ", \"rod_masses\": " << numbers(random, rods, 0, 2);
  }
  scene << "}, \"initial\": {";
  // Speeds from 1e-6 to 1e2: faster ones wind round the sphere millions of times in the duration (valid, but
  // minutes of integration per case); unit_speed takes any size down to 1.
  const double speed = std::pow(10.0, -6 + 8 * unit(random));
  if (unit(random) < 0.5) {
    scene << "\"coords\": " << numbers(random, rods - 2, -1.6, 1.6) << ", \"velocity\": "
          << numbers(random, rods - 2, -speed, speed);
  } else {
    scene << "\"drag\": {\"point\": " << numbers(random, rods - 1, -1, 1)
          << ", \"direction\": " << numbers(random, rods - 1, -speed, speed) << "}";
  }
  scene << ", \"unit_speed\": " << (unit(random) < 0.6 ? "true" : "false") << "}";
  scene << ", \"duration\": " << 0.2 + 2 * unit(random) << ", \"runs\": [";
  const int runs = 1 + static_cast<int>(random() % 3);
  for (int r = 0; r < runs; ++r) {
    const auto& method = kMethods[random() % kMethods.size()];
    const auto& integrator = kIntegrators[random() % kIntegrators.size()];
    scene << (r ? ", " : "") << "{\"name\": \"run " << r << "\", \"method\": \"" << method.name
          << "\", \"integrator\": \"" << integrator.name << "\", ";
    if (integrator.adaptive)
      scene << "\"tolerance\": " << std::pow(10.0, -11 + 8 * unit(random));
    else
      scene << "\"step\": " << std::pow(10.0, -3 + 2 * unit(random));
    scene << "}";
  }
  scene << R"(], "output": {"fps": 4, "width": 160, "height": 90},)"
        << R"( "view": {"panels": ["sphere", "linkage", {"panel": "plot", "plot": "energy"}, "text"]}})";
  return scene.str();
}

}  // namespace

int main(int argc, char** argv) {
  long count = 1000, seed = 1;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string option = argv[i];
    if (option == "--count") count = std::atol(argv[i + 1]);
    else if (option == "--seed") seed = std::atol(argv[i + 1]);
    else {
      std::fprintf(stderr, "random_starts: unknown option %s (expected --count N, --seed S)\n", argv[i]);
      return 2;
    }
  }
  std::mt19937_64 random(static_cast<unsigned long long>(seed));
  const Scene layout = parseScene(
      R"({"name": "layout", "linkage": {"rods": 4, "L": 3}, "initial": {"coords": [0.3, 0.2], "velocity": [0.5, 0.7]},
          "duration": 1, "runs": [{"name": "a"}], "output": {"width": 160, "height": 90},
          "view": {"panels": ["sphere", "linkage", {"panel": "plot", "plot": "energy"}, "text"]}})",
      "layout.json");
  Renderer renderer(layout.view, {160, 90});
  long refused = 0, ran = 0, stopped = 0, failures = 0;
  for (long k = 0; k < count; ++k) {
    const std::string json = randomScene(random);
    const auto started = std::chrono::steady_clock::now();
    const auto fail = [&](const std::string& what) {
      ++failures;
      std::fprintf(stderr, "case %ld: %s\n  scene: %s\n", k, what.c_str(), json.c_str());
    };
    try {
      Scene scene;
      try {
        scene = parseScene(json, "case.json");
      } catch (const SceneError&) {
        ++refused;
        continue;
      }
      std::optional<FrameBuilder> builder;
      try {
        const std::vector<InitialState> starts = runStarts(scene);
        builder.emplace(scene, starts, startRuns(scene, starts), startFamilies(scene, starts));
      } catch (const CommandExit& exit) {
        if (exit.code() != kExitBadInput) fail(std::string("start refused with exit ") + std::to_string(exit.code()));
        ++refused;
        continue;
      }
      for (int frame : {0, builder->frameCount() / 2, builder->frameCount() - 1}) {
        if (frame <= builder->lastSampledFrame()) continue;
        const FrameState state = builder->frame(frame);
        if (const std::string what = nonFinite(state); !what.empty()) fail("frame " + std::to_string(frame) + ": " + what);
        const Image image = renderer.render(state);
        if (image.width != 160 || image.height != 90 || image.rgb.size() != 160u * 90u * 3u) fail("image size");
      }
      ++ran;
      for (const Trajectory& run : builder->runs()) stopped += run.stop().has_value();
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      if (seconds > 5) std::fprintf(stderr, "case %ld took %.1f s: %s\n", k, seconds, json.c_str());
    } catch (const std::exception& error) {
      fail(std::string("unexpected exception: ") + error.what());
    }
  }
  std::printf("random_starts: %ld cases (seed %ld): %ld ran (%ld runs stopped with a reason), %ld refused, %ld failures\n",
              count, seed, ran, stopped, refused, failures);
  return failures == 0 ? 0 : 1;
}
