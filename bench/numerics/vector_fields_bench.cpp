// ns per geodesic vector-field evaluation, 4 rods (L = 3), at the reference start (phi, t) = (0.3, 0.2).
#include <benchmark/benchmark.h>

#include "contracts/registry.hpp"
#include "fixtures/published_references.hpp"
#include "linkage/sphere_coordinates.hpp"
#include "simulation/ambient_system.hpp"
#include "simulation/chart_system.hpp"
#include "simulation/initial_state.hpp"
#include "simulation/published_fields.hpp"

namespace {

const sl::Chain chain = sl::Chain::uniform(4, 3.0);
const sl::ChainConstants bound(chain);
const sl::PublishedChain published(3.0);
const Eigen::Vector2d coords(0.3, 0.2), rates(0.5, 0.7);

void BM_ChristoffelFd(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(sl::christoffelFdAcceleration(published, coords, rates));
}
void BM_EmbeddedFd(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(sl::embeddedFdAcceleration(published, coords, rates));
}
// The same fields evaluated point by point, as the spec's code does (the speed before the stencil sharing).
void BM_ChristoffelFdStencilByStencil(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(sl::christoffelFdAccelerationStencilByStencil(3.0, coords, rates));
}
void BM_EmbeddedFdStencilByStencil(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(sl::embeddedFdAccelerationStencilByStencil(3.0, coords, rates));
}

// Through the ODE interface the integrators see (state vector in, derivative out).
void chartSystemField(benchmark::State& state, sl::Method method) {
  const sl::ChartSystem system(bound, sl::chartMethod(method, bound), sl::initialStateFromChart(chain, coords, rates));
  const sl::State y = system.initialState();
  sl::State dydt(y.size());
  for (auto _ : state) {
    system.derivative(y, dydt);
    benchmark::DoNotOptimize(dydt.data());
  }
}
void BM_ChristoffelFdSystem(benchmark::State& state) { chartSystemField(state, sl::Method::ChristoffelFd); }
void BM_EmbeddedFdSystem(benchmark::State& state) { chartSystemField(state, sl::Method::EmbeddedFd); }
void BM_Christoffel(benchmark::State& state) { chartSystemField(state, sl::Method::Christoffel); }
void BM_Embedded(benchmark::State& state) { chartSystemField(state, sl::Method::Embedded); }

void BM_Ambient(benchmark::State& state) {
  const sl::AmbientSystem system(chain, sl::initialStateFromChart(chain, coords, rates), 1e-14);
  const sl::State y = system.initialState();
  sl::State dydt(y.size());
  for (auto _ : state) {
    system.derivative(y, dydt);
    benchmark::DoNotOptimize(dydt.data());
  }
}

}  // namespace

BENCHMARK(BM_ChristoffelFd);
BENCHMARK(BM_EmbeddedFd);
BENCHMARK(BM_ChristoffelFdStencilByStencil);
BENCHMARK(BM_EmbeddedFdStencilByStencil);
BENCHMARK(BM_ChristoffelFdSystem);
BENCHMARK(BM_EmbeddedFdSystem);
BENCHMARK(BM_Christoffel);
BENCHMARK(BM_Embedded);
BENCHMARK(BM_Ambient);
