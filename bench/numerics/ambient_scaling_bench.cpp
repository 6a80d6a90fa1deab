// Cost of the ambient method as the chain grows: one vector-field evaluation and one RK4 step (4
// evaluations plus vector updates) for n rods, unit hinge masses; and with rod masses (KKT via SparseLU).
// Must grow linearly: compare n = 10^4 with n = 10^3.
#include <benchmark/benchmark.h>

#include "contracts/registry.hpp"
#include "simulation/ambient_system.hpp"
#include "simulation/steppers.hpp"

namespace {

sl::AmbientSystem chainOf(int rods, bool rodMasses) {
  sl::Chain chain = sl::Chain::uniform(rods, rods - 1.0);
  if (rodMasses) chain.rodMasses.setConstant(0.5);
  Eigen::VectorXd x(rods - 1), xdot(rods - 1);
  for (int i = 0; i < rods - 1; ++i) x(i) = std::cos(0.7 * i + 0.3), xdot(i) = std::sin(1.3 * i);
  x.normalize();
  xdot -= x * x.dot(xdot);
  return sl::AmbientSystem(chain, {x, xdot}, 1e-14);
}

void evaluation(benchmark::State& state, bool rodMasses) {
  const sl::AmbientSystem system = chainOf(static_cast<int>(state.range(0)), rodMasses);
  const sl::State y = system.initialState();
  sl::State dydt(y.size());
  for (auto _ : state) {
    system.derivative(y, dydt);
    benchmark::DoNotOptimize(dydt.data());
  }
  state.SetComplexityN(state.range(0));
}
void BM_AmbientEvaluation(benchmark::State& state) { evaluation(state, false); }
void BM_AmbientEvaluationRodMasses(benchmark::State& state) { evaluation(state, true); }

void BM_AmbientRk4Step(benchmark::State& state) {
  const sl::AmbientSystem system = chainOf(static_cast<int>(state.range(0)), false);
  const std::unique_ptr<sl::Stepper> stepper = sl::makeStepper(sl::Integrator::Rk4, 0.0, 1e-4);
  stepper->initialize(system, system.initialState(), 0.0);
  for (auto _ : state) stepper->doStep(system);
  state.SetComplexityN(state.range(0));
}

}  // namespace

BENCHMARK(BM_AmbientEvaluation)
    ->Arg(4)
    ->Arg(16)
    ->Arg(64)
    ->Arg(256)
    ->Arg(1024)
    ->Arg(4096)
    ->Arg(10000)
    ->Complexity(benchmark::oN);
BENCHMARK(BM_AmbientRk4Step)
    ->Arg(4)
    ->Arg(10)
    ->Arg(16)
    ->Arg(64)
    ->Arg(100)
    ->Arg(256)
    ->Arg(1000)
    ->Arg(1024)
    ->Arg(4096)
    ->Arg(10000)
    ->Complexity(benchmark::oN);
BENCHMARK(BM_AmbientEvaluationRodMasses)->Arg(4)->Arg(64)->Arg(1000)->Arg(10000)->Complexity(benchmark::oN);
