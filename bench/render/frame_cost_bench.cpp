// bench_frame_cost: the cost of one frame early and late in a long animation. A frame is the frame builder's
// step to it (sampling the runs up to its time and the FrameState) and the composer's DrawList for it, and in
// BM_WholeFrame also its rendering to pixels. Each benchmark run builds a fresh builder, walks it (untimed) to
// the first frame, then times consecutive frames from there: compare frame 100 with frame 10^5.
//
//   bench_frame_cost --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "frames/frame_builder.hpp"
#include "render/frame_composer.hpp"
#include "render/renderer.hpp"
#include "scene/scene_loader.hpp"
#include "simulation/family.hpp"
#include "simulation/initial_state.hpp"

namespace {

// Two runs over 102,000 frames at 30 fps, every panel, both plots; the sphere path fades after 3 s, so from frame 90
// on it holds as many points in every frame (without a fade the path grows to limits::kMaxPathPoints: what the
// picture shows, not overhead).
sl::Scene longScene(int width, int height) {
  return sl::parseScene(R"({"name": "long", "linkage": {"rods": 4, "L": 3},
    "initial": {"coords": [0.3, 0.2], "velocity": [0.5, 0.7]}, "duration": 3400,
    "runs": [{"name": "ambient", "method": "ambient"},
             {"name": "embedded", "method": "embedded", "integrator": "dopri5", "tolerance": 1e-12}],
    "output": {"fps": 30, "width": )" + std::to_string(width) + R"(, "height": )" + std::to_string(height) + R"(},
    "view": {"panels": ["text", "sphere", "linkage", {"panel": "plot", "plot": "divergence"},
                        {"panel": "plot", "plot": "energy"}], "trails": [1], "path_fade_seconds": 3}})",
                        "long.json");
}

struct Setup {
  sl::Scene scene;
  std::vector<sl::InitialState> starts;
};

Setup setupFor(int width, int height) {
  Setup s{longScene(width, height), {}};
  for (const sl::RunSpec& run : s.scene.runs) s.starts.push_back(sl::initialStateFromSpec(run.chain, run.initial));
  return s;
}

sl::FrameBuilder builderAt(const Setup& s, int first) {
  std::vector<sl::Trajectory> runs;
  for (std::size_t i = 0; i < s.scene.runs.size(); ++i)
    runs.emplace_back(s.scene.runs[i].chain, s.starts[i], s.scene.runs[i].config);
  sl::FrameBuilder builder(s.scene, s.starts, std::move(runs));
  builder.advanceTo(first - 1);
  return builder;
}

// Arguments: the first frame, the width and height.
void BM_BuilderAndComposer(benchmark::State& state) {
  const int first = int(state.range(0));
  const Setup s = setupFor(int(state.range(1)), int(state.range(2)));
  const sl::FrameComposer composer(s.scene.view, s.scene.output.size);
  sl::FrameBuilder builder = builderAt(s, first);
  int k = first;
  for (auto _ : state) {
    const sl::FrameState frame = builder.frame(k++);
    benchmark::DoNotOptimize(composer.compose(frame));
  }
}

void BM_Builder(benchmark::State& state) {
  const int first = int(state.range(0));
  const Setup s = setupFor(int(state.range(1)), int(state.range(2)));
  sl::FrameBuilder builder = builderAt(s, first);
  int k = first;
  for (auto _ : state) benchmark::DoNotOptimize(builder.frame(k++));
}

void BM_WholeFrame(benchmark::State& state) {
  const int first = int(state.range(0));
  const Setup s = setupFor(int(state.range(1)), int(state.range(2)));
  sl::Renderer renderer(s.scene.view, s.scene.output.size);
  sl::FrameBuilder builder = builderAt(s, first);
  int k = first;
  for (auto _ : state) benchmark::DoNotOptimize(renderer.render(builder.frame(k++)));
}

// 300 consecutive frames from each start, so every run times the same frames.
BENCHMARK(BM_BuilderAndComposer)->Args({100, 160, 90})->Args({100000, 160, 90})->Args({100, 1280, 720})
    ->Args({100000, 1280, 720})->Iterations(300)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Builder)->Args({100, 160, 90})->Args({100000, 160, 90})->Iterations(300)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_WholeFrame)->Args({100, 160, 90})->Args({100000, 160, 90})->Iterations(300)->Unit(benchmark::kMicrosecond);

}  // namespace
