// Families and Jacobi fields: a fan of 64 geodesics to T = 20 at tolerance 1e-10, its members spread
// over the cores as the frames stage does it (contracts/parallel_for.hpp); a run with its Jacobi field against the
// same run alone (4 rods: one field; 6 rods: a matrix field of three).
#include <benchmark/benchmark.h>

#include "contracts/parallel_for.hpp"
#include "simulation/family.hpp"
#include "simulation/initial_state.hpp"
#include "simulation/trajectory.hpp"

namespace {

sl::RunConfig ambient(sl::Integrator integrator, double tolerance, bool jacobi = false) {
  sl::RunConfig config;
  config.method = sl::Method::Ambient, config.integrator = integrator, config.tolerance = tolerance;
  config.jacobi = jacobi;
  return config;
}

void fan(benchmark::State& state) {
  const sl::Chain chain = sl::Chain::uniform(4, 3.0);
  sl::InitialState start = sl::initialStateFromChart(chain, Eigen::Vector2d(0.3, 0.2), Eigen::Vector2d(0.5, 0.7));
  start.sphereVelocity /= std::sqrt(sl::speedSquared(chain, start));
  const sl::RunConfig config = ambient(sl::Integrator::Dopri5, 1e-10);
  const sl::FamilySpec family{sl::FamilyKind::Fan, static_cast<int>(state.range(0)), 0.9};
  for (auto _ : state) {
    const std::vector<sl::InitialState> starts = sl::familyStarts(chain, start, family, config);
    sl::parallelFor(starts.size(), [&](std::size_t m) {
      sl::Trajectory member(chain, starts[m], config);
      benchmark::DoNotOptimize(member.sampleAt(20.0));
    });
  }
}

void run(benchmark::State& state, int rods, bool jacobi) {
  const sl::Chain chain = sl::Chain::uniform(rods, rods - 1.0);
  const Eigen::VectorXd coords = Eigen::VectorXd::LinSpaced(rods - 2, 0.3, 0.2);
  const Eigen::VectorXd rates = Eigen::VectorXd::LinSpaced(rods - 2, 0.5, 0.7);
  const sl::InitialState start = sl::initialStateFromChart(chain, coords, rates);
  const sl::RunConfig config = ambient(sl::Integrator::Rkf78, 1e-12, jacobi);
  long steps = 0;
  for (auto _ : state) {
    sl::Trajectory trajectory(chain, start, config);
    benchmark::DoNotOptimize(trajectory.sampleAt(20.0));
    steps = trajectory.steps();
  }
  state.counters["steps"] = static_cast<double>(steps);
}

}  // namespace

BENCHMARK(fan)->Arg(64)->Arg(32)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(run, rods4_alone, 4, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, rods4_jacobi, 4, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, rods6_alone, 6, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, rods6_jacobi, 6, true)->Unit(benchmark::kMillisecond);
