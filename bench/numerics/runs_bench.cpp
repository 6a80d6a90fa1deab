// Whole runs: the reference start generic_L3 (L = 3, (0.3, 0.2), (0.5, 0.7)) to T = 20, sampled once at
// the end, for candidate defaults (method, integrator, tolerance). The accuracy of each candidate is
// checked in tests/simulation (reference_test.cpp); this measures wall time.
#include <benchmark/benchmark.h>

#include "contracts/registry.hpp"
#include "simulation/initial_state.hpp"
#include "simulation/trajectory.hpp"

namespace {

void run(benchmark::State& state, sl::Method method, sl::Integrator integrator, double tolerance) {
  const sl::Chain chain = sl::Chain::uniform(4, 3.0);
  const sl::InitialState start = sl::initialStateFromChart(chain, Eigen::Vector2d(0.3, 0.2), Eigen::Vector2d(0.5, 0.7));
  sl::RunConfig config;
  config.method = method, config.integrator = integrator, config.tolerance = tolerance;
  long evaluations = 0;
  for (auto _ : state) {
    sl::Trajectory trajectory(chain, start, config);
    benchmark::DoNotOptimize(trajectory.sampleAt(20.0));
    evaluations = trajectory.vectorFieldEvaluations();
  }
  state.counters["evaluations"] = static_cast<double>(evaluations);
}

}  // namespace

BENCHMARK_CAPTURE(run, default, sl::RunConfig().method, sl::RunConfig().integrator, sl::RunConfig().tolerance)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, ambient_dopri5_1e12, sl::Method::Ambient, sl::Integrator::Dopri5, 1e-12)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, ambient_bs_1e12, sl::Method::Ambient, sl::Integrator::BulirschStoer, 1e-12)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, ambient_bs_1e11, sl::Method::Ambient, sl::Integrator::BulirschStoer, 1e-11)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, ambient_rkf78_1e12, sl::Method::Ambient, sl::Integrator::Rkf78, 1e-12)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, ambient_rkf78_1e13, sl::Method::Ambient, sl::Integrator::Rkf78, 1e-13)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, christoffel_dopri5_1e12, sl::Method::Christoffel, sl::Integrator::Dopri5, 1e-12)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, embedded_dopri5_1e12, sl::Method::Embedded, sl::Integrator::Dopri5, 1e-12)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, christoffel_fd_dopri5_1e10, sl::Method::ChristoffelFd, sl::Integrator::Dopri5, 1e-10)
    ->Unit(benchmark::kMillisecond);
